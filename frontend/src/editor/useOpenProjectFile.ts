import { useCallback } from 'react';
import { getFile } from '../api/client';
import { useEditorTabs, type RevealAt } from './EditorTabsContext';
import { isWatchTableName } from '../watchtables/format';
import { openWatchTable } from '../watchtables/selection';
import { languageOfFile } from './fileLanguage';

export type OpenProjectFile = (
  projectId: number,
  name: string,
  at?: RevealAt | null,
) => Promise<void>;

/**
 * Opens a project file in a source tab, or brings its tab to the front; with `at`, the editor
 * shows that line. A file not yet open is read from the server (the promise rejects with the
 * ApiError when it cannot be).
 */
export function useOpenProjectFile(): OpenProjectFile {
  const { tabs, openSource, reveal, activate } = useEditorTabs();
  return useCallback(
    async (projectId, name, at = null) => {
      const open = tabs.find(
        (tab) => tab.kind === 'source' && tab.file?.projectId === projectId && tab.file.path === name,
      );
      if (open) {
        if (at) reveal(open.id, at);
        else activate(open.id);
        return;
      }
      if (isWatchTableName(name)) {
        openWatchTable(projectId, name); // a table opens in the Watch panel, as a VAT in its window
        return;
      }
      const file = await getFile(projectId, name);
      openSource({
        name: file.name,
        language: languageOfFile(file.name) ?? (file.language as Exclude<typeof file.language, 'watch'>),
        text: file.text,
        file: { projectId, path: file.name },
        version: file.version,
        dirty: false,
        at,
      });
    },
    [tabs, openSource, reveal, activate],
  );
}
