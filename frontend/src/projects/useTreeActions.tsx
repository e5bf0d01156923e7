import { useCallback, useState, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import {
  ApiError,
  asApiError,
  deleteFile,
  deleteProject,
  duplicateFile,
  exportUrl,
  renameFile,
  renameProject,
  saveFile,
} from '../api/client';
import type { Project } from '../api/types';
import { discardFile, flushFile, rebaseFile } from '../editor/autosave';
import { useEditorTabs } from '../editor/EditorTabsContext';
import { SOURCE_SUFFIX, languageOfFile } from '../editor/fileLanguage';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useOpenCpuProperties } from '../cpuprops/openCpuProperties';
import { fileKey } from './blockFolders';
import { freeCopyName, freeSourceName, freeSymbolTableName, nameTaken, newSourceText } from './fileNames';
import { projectContents } from './projectContents';
import type { MenuAction } from './RowMenu';
import { ConfirmDialog, FileNameDialog, ProjectNameDialog } from './TreeDialogs';
import type { TreeRow } from './treeRows';

type TreeDialog =
  | { kind: 'new'; projectId: number; language: 'stl' | 'scl' | 'lad' | 'graph' | 'symbols' }
  | { kind: 'rename'; projectId: number; name: string }
  | { kind: 'duplicate'; projectId: number; name: string }
  | { kind: 'deleteFile'; projectId: number; name: string }
  | { kind: 'deleteProject'; project: Project }
  | { kind: 'renameProject'; project: Project };

interface TreeActionsOptions {
  /** A problem to show in the tree pane (a file that cannot be opened). */
  showError: (error: ApiError) => void;
  /** Select (and show) this row: a file just created, renamed or copied. */
  selectKey: (key: string, projectId: number) => void;
  onProjectDeleted: (projectId: number) => void;
  /** The server renamed the project: its row shows the new name. */
  onProjectRenamed: (project: Project) => void;
}

/** The name the server would refuse as taken (API108), said before asking it. */
function takenError(name: string): ApiError {
  return new ApiError(
    {
      code: 'API108',
      key: 'file_name_taken',
      message: `The project already has a file named '${name}' (letter case does not count).`,
      params: { name },
    },
    409,
  );
}

/**
 * What can be done to the rows of the project tree (the context menu, Enter, F2, Delete) and the
 * dialogs that ask for names and confirmations.
 */
export function useTreeActions({ showError, selectKey, onProjectDeleted, onProjectRenamed }: TreeActionsOptions) {
  const { t } = useTranslation();
  const { openSource, openDb, renameFileTabs, closeFileTabs } = useEditorTabs();
  const openProjectFile = useOpenProjectFile();
  const openCpuProperties = useOpenCpuProperties();
  const [dialog, setDialog] = useState<TreeDialog | null>(null);
  const close = useCallback(() => setDialog(null), []);

  const open = useCallback(
    (projectId: number, name: string, line?: number | null) => {
      openProjectFile(projectId, name, line ? { line } : null).catch((error: unknown) => showError(asApiError(error)));
    },
    [openProjectFile, showError],
  );

  const exportProject = useCallback(async (projectId: number) => {
    await flushFile(projectId);
    const link = document.createElement('a');
    link.href = exportUrl(projectId);
    link.download = '';
    link.hidden = true;
    document.body.append(link);
    link.click();
    link.remove();
  }, []);

  /** Opens the row (Enter, double-click): a block at its header line, a file at its start. */
  const activate = useCallback(
    (row: TreeRow) => {
      if (row.type === 'block') open(row.projectId, row.block.file, row.block.line);
      else if (row.type === 'file') open(row.projectId, row.file.name);
    },
    [open],
  );

  const rename = useCallback((row: TreeRow) => {
    if (row.type === 'file') setDialog({ kind: 'rename', projectId: row.projectId, name: row.file.name });
    else if (row.type === 'project') setDialog({ kind: 'renameProject', project: row.project });
  }, []);

  const remove = useCallback((row: TreeRow) => {
    if (row.type === 'file') setDialog({ kind: 'deleteFile', projectId: row.projectId, name: row.file.name });
    else if (row.type === 'project') setDialog({ kind: 'deleteProject', project: row.project });
  }, []);

  function actionsFor(row: TreeRow): MenuAction[] {
    const { projectId } = row;
    const creating: MenuAction[] = [
      { id: 'new-stl', label: t('projects.actions.newStl'), onSelect: () => setDialog({ kind: 'new', projectId, language: 'stl' }) },
      { id: 'new-scl', label: t('projects.actions.newScl'), onSelect: () => setDialog({ kind: 'new', projectId, language: 'scl' }) },
      { id: 'new-lad', label: t('projects.actions.newLad'), onSelect: () => setDialog({ kind: 'new', projectId, language: 'lad' }) },
      { id: 'new-graph', label: t('projects.actions.newGraph'), onSelect: () => setDialog({ kind: 'new', projectId, language: 'graph' }) },
      {
        id: 'new-symbols',
        label: t('projects.actions.newSymbols'),
        onSelect: () => setDialog({ kind: 'new', projectId, language: 'symbols' }),
      },
    ];
    switch (row.type) {
      case 'project':
        return [
          ...creating,
          { id: 'rename', label: t('shortcuts.renameProject.action'), onSelect: () => rename(row) },
          {
            id: 'cpu-properties',
            label: t('cpuProps.menu'),
            onSelect: () => void openCpuProperties(projectId).catch((error: unknown) => showError(asApiError(error))),
          },
          { id: 'export', label: t('projects.actions.export'), onSelect: () => void exportProject(projectId) },
          { id: 'delete', label: t('projects.actions.deleteProject'), onSelect: () => remove(row), danger: true },
        ];
      case 'file':
        return [
          { id: 'open', label: t('projects.actions.open'), onSelect: () => activate(row) },
          ...creating,
          { id: 'rename', label: t('projects.actions.rename'), onSelect: () => rename(row) },
          {
            id: 'duplicate',
            label: t('projects.actions.duplicate'),
            onSelect: () => setDialog({ kind: 'duplicate', projectId, name: row.file.name }),
          },
          { id: 'delete', label: t('projects.actions.delete'), onSelect: () => remove(row), danger: true },
        ];
      case 'block':
        return [
          { id: 'open', label: t('projects.actions.open'), onSelect: () => activate(row) },
          ...(row.block.kind === 'DB'
            ? [
                {
                  id: 'data-view',
                  label: t('dbEditor.openDataView'),
                  onSelect: () =>
                    openDb({
                      projectId,
                      block: `DB${row.block.number}`,
                      name: `DB${row.block.number}${row.block.name ? ` ${row.block.name}` : ''}`,
                    }),
                },
              ]
            : []),
          ...creating,
        ];
      case 'folder':
        return creating;
      default:
        return [];
    }
  }

  const filesOf = (projectId: number) => projectContents.get(projectId)?.files ?? [];
  let element: ReactNode = null;
  if (dialog?.kind === 'new') {
    const { projectId, language } = dialog;
    element = (
      <FileNameDialog
        title={t(`projects.files.newTitle.${language}`)}
        submitLabel={t('projects.files.create')}
        initialName={
          language === 'symbols'
            ? freeSymbolTableName(filesOf(projectId))
            : freeSourceName(filesOf(projectId), SOURCE_SUFFIX[language])
        }
        testId="file-new-dialog"
        onClose={close}
        onSubmit={async (name) => {
          if (nameTaken(filesOf(projectId), name)) throw takenError(name);
          // A symbol table starts empty (no example rows to delete); a source as an empty FC.
          const typed = languageOfFile(name) ?? language;
          const text =
            typed === 'symbols' ? '' : newSourceText(typed === 'scl' || typed === 'fbd' || typed === 'lad' || typed === 'graph' ? typed : 'stl', projectContents.get(projectId)?.blocks ?? []);
          const info = await saveFile(projectId, name, { text });
          projectContents.putFile(projectId, info);
          projectContents.reloadSoon(projectId);
          close();
          selectKey(fileKey(projectId, info.name), projectId);
          openSource({
            name: info.name,
            language: languageOfFile(info.name) ?? language,
            text,
            file: { projectId, path: info.name },
            version: info.version,
            dirty: false,
          });
        }}
      />
    );
  } else if (dialog?.kind === 'rename') {
    const { projectId, name: from } = dialog;
    element = (
      <FileNameDialog
        title={t('projects.files.renameTitle', { name: from })}
        submitLabel={t('projects.files.renameSubmit')}
        initialName={from}
        testId="file-rename-dialog"
        onClose={close}
        onSubmit={async (to) => {
          if (to !== from) {
            if (nameTaken(filesOf(projectId), to, from)) throw takenError(to);
            await flushFile(projectId, from);
            const info = await renameFile(projectId, from, to);
            rebaseFile(projectId, from, info.version);
            renameFileTabs(projectId, from, info.name);
            projectContents.putFile(projectId, info, from);
            projectContents.reloadSoon(projectId);
            selectKey(fileKey(projectId, info.name), projectId);
          }
          close();
        }}
      />
    );
  } else if (dialog?.kind === 'duplicate') {
    const { projectId, name: from } = dialog;
    element = (
      <FileNameDialog
        title={t('projects.files.duplicateTitle', { name: from })}
        submitLabel={t('projects.files.duplicateSubmit')}
        initialName={freeCopyName(filesOf(projectId), from)}
        testId="file-duplicate-dialog"
        onClose={close}
        onSubmit={async (to) => {
          if (nameTaken(filesOf(projectId), to)) throw takenError(to);
          await flushFile(projectId, from);
          const info = await duplicateFile(projectId, from, to);
          projectContents.putFile(projectId, info);
          projectContents.reloadSoon(projectId);
          close();
          selectKey(fileKey(projectId, info.name), projectId);
        }}
      />
    );
  } else if (dialog?.kind === 'deleteFile') {
    const { projectId, name } = dialog;
    element = (
      <ConfirmDialog
        title={t('projects.files.deleteTitle', { name })}
        confirmLabel={t('projects.files.deleteSubmit')}
        testId="file-delete-dialog"
        onClose={close}
        onConfirm={async () => {
          await deleteFile(projectId, name);
          discardFile(projectId, name);
          closeFileTabs(projectId, name);
          projectContents.removeFile(projectId, name);
          projectContents.reloadSoon(projectId);
          close();
        }}
      >
        <p className="dialog__text">{t('projects.files.deleteText', { name })}</p>
      </ConfirmDialog>
    );
  } else if (dialog?.kind === 'renameProject') {
    const { project } = dialog;
    element = (
      <ProjectNameDialog
        title={t('shortcuts.renameProject.title', { name: project.name })}
        submitLabel={t('shortcuts.renameProject.submit')}
        initialName={project.name}
        testId="project-rename-dialog"
        onClose={close}
        onSubmit={async (name) => {
          // Files, tabs and a running session refer to the project by its id: they carry on.
          const renamed = name === project.name ? project : await renameProject(project.id, name);
          close();
          onProjectRenamed(renamed);
        }}
      />
    );
  } else if (dialog?.kind === 'deleteProject') {
    const { project } = dialog;
    element = (
      <ConfirmDialog
        title={t('projects.deleteTitle', { name: project.name })}
        confirmLabel={t('projects.deleteSubmit')}
        testId="project-delete-dialog"
        onClose={close}
        onConfirm={async () => {
          await deleteProject(project.id);
          discardFile(project.id);
          closeFileTabs(project.id);
          projectContents.forget(project.id);
          close();
          onProjectDeleted(project.id);
        }}
      >
        <p className="dialog__text">{t('projects.deleteText', { name: project.name })}</p>
      </ConfirmDialog>
    );
  }

  return { actionsFor, activate, rename, remove, dialog: element };
}
