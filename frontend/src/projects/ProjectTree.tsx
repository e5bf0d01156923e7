import { useCallback, useId, useState } from 'react';
import { useTranslation } from 'react-i18next';
import type { Project } from '../api/types';
import { PlusIcon, RefreshIcon } from '../ui/icons';
import { useActiveProject } from './ActiveProject';
import { NewProjectDialog } from './NewProjectDialog';
import { ProjectTreeBody } from './ProjectTreeBody';
import { useProjects } from './useProjects';

/** The project navigator: the server's projects, each with its (coming) block folders. */
export function ProjectTree() {
  const { t } = useTranslation();
  const headingId = useId();
  const { state, reload, add } = useProjects();
  const [creating, setCreating] = useState(false);
  const [expanded, setExpanded] = useState<ReadonlySet<number>>(() => new Set());
  const { projectId: selected, setProjectId: setSelected } = useActiveProject();

  const setOpen = useCallback((id: number, open: boolean) => {
    setExpanded((current) => {
      if (current.has(id) === open) return current;
      const next = new Set(current);
      if (open) next.add(id);
      else next.delete(id);
      return next;
    });
  }, []);

  const onCreated = useCallback(
    (project: Project) => {
      add(project);
      setOpen(project.id, true);
      setSelected(project.id);
      setCreating(false);
    },
    [add, setOpen, setSelected],
  );

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
            onClick={reload}
          >
            <RefreshIcon />
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
          labelledBy={headingId}
          expanded={expanded}
          selected={selected}
          onOpenChange={setOpen}
          onSelect={setSelected}
          onRetry={reload}
          onCreate={() => setCreating(true)}
        />
      </div>
      {creating ? <NewProjectDialog onClose={() => setCreating(false)} onCreated={onCreated} /> : null}
    </nav>
  );
}
