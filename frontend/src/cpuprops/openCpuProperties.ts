import { useCallback } from 'react';
import { listFiles, saveFile } from '../api/client';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { projectContents } from '../projects/projectContents';
import { CPU_PROPERTIES_FILE, DEFAULT_TEXT } from './format';

/**
 * Opens a project's CPU properties page. A project without `cpu.properties` runs with the
 * defaults; the page first writes them into a new file (the tree shows it), so what the page
 * shows is always a file's text. Rejects with the ApiError when that cannot be done.
 */
export function useOpenCpuProperties(): (projectId: number) => Promise<void> {
  const openProjectFile = useOpenProjectFile();
  return useCallback(
    async (projectId: number) => {
      const files = await listFiles(projectId);
      if (!files.some((file) => file.name.toLowerCase() === CPU_PROPERTIES_FILE)) {
        const info = await saveFile(projectId, CPU_PROPERTIES_FILE, { text: DEFAULT_TEXT });
        projectContents.putFile(projectId, info);
        projectContents.reloadSoon(projectId);
      }
      const name = files.find((file) => file.name.toLowerCase() === CPU_PROPERTIES_FILE)?.name ?? CPU_PROPERTIES_FILE;
      await openProjectFile(projectId, name);
    },
    [openProjectFile],
  );
}
