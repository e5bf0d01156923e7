import { useMemo } from 'react';
import { useTranslation } from 'react-i18next';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { PlusIcon, RefreshIcon, WarningIcon } from '../ui/icons';
import { BLOCK_FOLDERS, folderKey, projectKey } from './blockFolders';
import { ProjectNode } from './ProjectNode';
import type { ProjectsState } from './useProjects';
import { useTreeKeyboard } from './useTreeKeyboard';

interface ProjectTreeBodyProps {
  state: ProjectsState;
  labelledBy: string;
  expanded: ReadonlySet<number>;
  selected: number | null;
  onOpenChange: (id: number, open: boolean) => void;
  onSelect: (id: number) => void;
  onRetry: () => void;
  onCreate: () => void;
}

function projectIdOf(key: string): number | null {
  const match = /^project:(\d+)$/.exec(key);
  return match ? Number(match[1]) : null;
}

/** What the tree pane shows: loading, the server error, the empty state or the tree itself. */
export function ProjectTreeBody({
  state,
  labelledBy,
  expanded,
  selected,
  onOpenChange,
  onSelect,
  onRetry,
  onCreate,
}: ProjectTreeBodyProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const projects = state.status === 'ready' ? state.projects : [];

  const visibleKeys = useMemo(
    () =>
      projects.flatMap((project) => [
        projectKey(project.id),
        ...(expanded.has(project.id) ? BLOCK_FOLDERS.map((folder) => folderKey(project.id, folder.id)) : []),
      ]),
    [projects, expanded],
  );

  const actions = useMemo(
    () => ({
      expand: (key: string) => {
        const id = projectIdOf(key);
        if (id === null || expanded.has(id)) return false;
        onOpenChange(id, true);
        return true;
      },
      collapse: (key: string) => {
        const id = projectIdOf(key);
        if (id === null || !expanded.has(id)) return false;
        onOpenChange(id, false);
        return true;
      },
      activate: (key: string) => {
        const id = projectIdOf(key);
        if (id === null) return;
        onSelect(id);
        onOpenChange(id, !expanded.has(id));
      },
    }),
    [expanded, onOpenChange, onSelect],
  );

  const keyboard = useTreeKeyboard(visibleKeys, actions);

  if (state.status === 'loading') {
    return (
      <p className="pane-message" role="status" data-testid="project-tree-loading">
        <span className="spinner" aria-hidden="true" />
        {t('projects.loading')}
      </p>
    );
  }

  if (state.status === 'error') {
    const unreachable = state.error.unreachable;
    return (
      <div className="pane-message pane-message--error" role="alert" data-testid="project-tree-error">
        <WarningIcon className="pane-message__icon" />
        <strong>{unreachable ? t('projects.unreachableTitle') : t('projects.loadFailedTitle')}</strong>
        <p>{unreachable ? t('projects.unreachableText') : errorText(state.error)}</p>
        <p className="pane-message__code">
          <code className="error-code">{state.error.code}</code>
        </p>
        <button type="button" className="button button--small" onClick={onRetry}>
          <RefreshIcon />
          <span>{t('common.retry')}</span>
        </button>
      </div>
    );
  }

  if (projects.length === 0) {
    return (
      <div className="pane-message" data-testid="project-tree-empty">
        <strong>{t('projects.emptyTitle')}</strong>
        <p>{t('projects.emptyText')}</p>
        <button type="button" className="button button--small" onClick={onCreate}>
          <PlusIcon />
          <span>{t('projects.createFirst')}</span>
        </button>
      </div>
    );
  }

  return (
    <ul
      role="tree"
      aria-labelledby={labelledBy}
      className="tree"
      onKeyDown={keyboard.onKeyDown}
      onFocus={keyboard.onFocus}
    >
      {projects.map((project, index) => (
        <ProjectNode
          key={project.id}
          project={project}
          position={index + 1}
          count={projects.length}
          expanded={expanded.has(project.id)}
          selected={selected === project.id}
          tabStop={keyboard.tabStop}
          onToggle={() => onOpenChange(project.id, !expanded.has(project.id))}
          onSelect={() => onSelect(project.id)}
        />
      ))}
    </ul>
  );
}
