import { useCallback, useEffect, useId, useMemo, useState, useSyncExternalStore } from 'react';
import { useTranslation } from 'react-i18next';
import type { ApiError } from '../api/client';
import type { ImportOut, Project } from '../api/types';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { CloseIcon, PlusIcon, RefreshIcon, WarningIcon } from '../ui/icons';
import { useActiveProject } from './ActiveProject';
import { folderKey, projectKey } from './blockFolders';
import { NewProjectDialog } from './NewProjectDialog';
import { projectContents } from './projectContents';
import { ProjectTreeBody, type TreeRowActions } from './ProjectTreeBody';
import { ImportDialog } from './TreeDialogs';
import { ImportIcon } from './treeIcons';
import { isExpanded, treeRows, type TreeRow } from './treeRows';
import { useProjects } from './useProjects';
import { useTreeActions } from './useTreeActions';
import './tree.css';

/**
 * The project navigator: the server's projects, each with its blocks by kind and its source
 * files. Double-click or Enter opens a block or file in the editor; the context menu (the row's
 * three-dot button, Shift+F10, the context-menu key) creates, renames, copies, deletes and
 * exports.
 */
export function ProjectTree() {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const headingId = useId();
  const { state, reload, add, remove } = useProjects();
  const [creating, setCreating] = useState(false);
  const [importing, setImporting] = useState(false);
  const [toggled, setToggled] = useState<ReadonlySet<string>>(() => new Set());
  const [selectedKey, setSelectedKey] = useState<string | null>(null);
  const [notice, setNotice] = useState<ApiError | null>(null);
  const { projectId, setProjectId } = useActiveProject();
  const contentsVersion = useSyncExternalStore(projectContents.subscribe, projectContents.version, projectContents.version);

  const setOpen = useCallback((key: string, open: boolean) => {
    setToggled((current) => {
      if (isExpanded(key, current) === open) return current;
      const next = new Set(current);
      if (next.has(key)) next.delete(key);
      else next.add(key);
      return next;
    });
  }, []);

  const selectKey = useCallback(
    (key: string, id: number) => {
      setSelectedKey(key);
      setProjectId(id);
      setOpen(projectKey(id), true);
      setOpen(folderKey(id, 'sources'), true);
    },
    [setOpen, setProjectId],
  );

  const projects = state.status === 'ready' ? state.projects : [];
  const rows = useMemo(
    () => treeRows(projects, toggled, (id) => projectContents.get(id)),
    // The store changes in place; its version says when.
    [projects, toggled, contentsVersion],
  );

  // The contents of every open project are loaded once; "Reload" loads them again.
  useEffect(() => {
    for (const project of projects) {
      if (isExpanded(projectKey(project.id), toggled)) projectContents.ensure(project.id);
    }
  }, [projects, toggled]);

  // A project made active elsewhere (the Start page's new source) is shown open at its sources;
  // one this list does not know yet (just created there) is read from the server once.
  const [sought, setSought] = useState<number | null>(null);
  useEffect(() => {
    if (projectId === null || state.status !== 'ready') return;
    const known = state.projects.some((project) => project.id === projectId);
    if (!known && sought !== projectId) {
      setSought(projectId);
      reload();
    } else if (known && sought === projectId) {
      setSought(null);
      setOpen(projectKey(projectId), true);
      setOpen(folderKey(projectId, 'sources'), true);
    }
  }, [projectId, state, sought, reload, setOpen]);

  const reloadAll = useCallback(() => {
    reload();
    for (const project of projects) {
      if (projectContents.get(project.id)) void projectContents.reload(project.id);
    }
  }, [reload, projects]);

  const onProjectDeleted = useCallback(
    (id: number) => {
      remove(id);
      if (projectId === id) setProjectId(null);
      setSelectedKey((key) => (key !== null && (key === projectKey(id) || key.startsWith(`${projectKey(id)}/`)) ? null : key));
    },
    [remove, projectId, setProjectId],
  );

  const treeActions = useTreeActions({ showError: setNotice, selectKey, onProjectDeleted, onProjectRenamed: add });

  const actions: TreeRowActions = useMemo(() => {
    const toggle = (row: TreeRow) => {
      if ((row.type === 'project' || row.type === 'folder') && row.expanded !== null) setOpen(row.key, !row.expanded);
    };
    const choose = (row: TreeRow) => {
      if (row.type === 'loading') return false;
      if (row.type === 'error') {
        void projectContents.reload(row.projectId);
        return false;
      }
      setSelectedKey(row.key);
      setProjectId(row.projectId);
      return true;
    };
    return {
      select: (row) => {
        if (choose(row)) toggle(row);
      },
      setOpen: (row, open) => setOpen(row.key, open),
      activate: (row) => {
        if (!choose(row)) return;
        if (row.type === 'block' || row.type === 'file') treeActions.activate(row);
        else toggle(row);
      },
      open: (row) => {
        if (row.type === 'block' || row.type === 'file') treeActions.activate(row);
      },
      rename: treeActions.rename,
      remove: treeActions.remove,
      menuFor: treeActions.actionsFor,
    };
  }, [setOpen, setProjectId, treeActions]);

  const onCreated = useCallback(
    (project: Project) => {
      add(project);
      selectKey(projectKey(project.id), project.id);
      setCreating(false);
    },
    [add, selectKey],
  );

  const onImported = useCallback(
    (result: ImportOut) => {
      add(result.project);
      selectKey(projectKey(result.project.id), result.project.id);
      setImporting(false);
    },
    [add, selectKey],
  );

  const selected = selectedKey ?? (projectId !== null ? projectKey(projectId) : null);

  return (
    <nav className="sidebar" aria-labelledby={headingId} data-testid="block-tree">
      <div className="pane-header">
        <h2 id={headingId} className="pane-header__title">
          {t('projects.title')}
        </h2>
        <div className="pane-header__actions">
          <button
            type="button"
            className="icon-button"
            aria-label={t('projects.refresh')}
            title={t('projects.refresh')}
            onClick={reloadAll}
          >
            <RefreshIcon />
          </button>
          <button
            type="button"
            className="icon-button"
            aria-label={t('projects.import.open')}
            title={t('projects.import.open')}
            data-testid="project-import"
            onClick={() => setImporting(true)}
          >
            <ImportIcon />
          </button>
          <button
            type="button"
            className="button button--small button--primary"
            data-testid="project-new"
            onClick={() => setCreating(true)}
          >
            <PlusIcon />
            <span>{t('projects.new')}</span>
          </button>
        </div>
      </div>
      <div className="pane-body">
        <ProjectTreeBody
          state={state}
          rows={rows}
          labelledBy={headingId}
          selected={selected}
          actions={actions}
          onRetry={reloadAll}
          onCreate={() => setCreating(true)}
        />
        {notice ? (
          <div className="tree-notice" role="alert" data-testid="project-tree-notice">
            <WarningIcon className="tree-notice__icon" />
            <p className="tree-notice__text">
              <code className="error-code">{notice.code}</code> {errorText(notice)}
            </p>
            <button
              type="button"
              className="icon-button"
              aria-label={t('common.close')}
              title={t('common.close')}
              onClick={() => setNotice(null)}
            >
              <CloseIcon size={12} />
            </button>
          </div>
        ) : null}
      </div>
      {creating ? <NewProjectDialog onClose={() => setCreating(false)} onCreated={onCreated} /> : null}
      {importing ? <ImportDialog onClose={() => setImporting(false)} onImported={onImported} /> : null}
      {treeActions.dialog}
    </nav>
  );
}
