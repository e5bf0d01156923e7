import { useEffect, useId, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, listProjects, type ApiError } from '../api/client';
import type { Project } from '../api/types';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { Dialog } from '../ui/Dialog';

interface ProjectPickDialogProps {
  /** The dialog's title: what is about to be created. */
  title: string;
  onClose: () => void;
  onChosen: (projectId: number) => Promise<void>;
  /** The user wants a new project for it (shown when there is none, and always as a choice). */
  onCreateProject: () => void;
}

/**
 * Asks which project a new source goes into, when no project is selected: every source is a
 * project file, so its text is saved from the start. Without any project it offers to create one.
 */
export function ProjectPickDialog({ title, onClose, onChosen, onCreateProject }: ProjectPickDialogProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const ids = useId();
  const [projects, setProjects] = useState<Project[] | null>(null);
  const [chosen, setChosen] = useState<number | null>(null);
  const [error, setError] = useState<ApiError | null>(null);
  const [busy, setBusy] = useState(false);

  useEffect(() => {
    const request = new AbortController();
    listProjects(request.signal).then(
      (list) => {
        const sorted = [...list].sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
        setProjects(sorted);
        setChosen(sorted[0]?.id ?? null);
      },
      (caught: unknown) => {
        if (!request.signal.aborted) setError(asApiError(caught));
      },
    );
    return () => request.abort();
  }, []);

  async function submit(event: FormEvent<HTMLFormElement>) {
    event.preventDefault();
    if (chosen === null || busy) return;
    setBusy(true);
    setError(null);
    try {
      await onChosen(chosen);
    } catch (caught) {
      setError(asApiError(caught));
      setBusy(false);
    }
  }

  const empty = projects !== null && projects.length === 0;
  return (
    <Dialog
      title={title}
      onClose={onClose}
      testId="project-pick-dialog"
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button type="button" className="button" data-testid="project-pick-new" onClick={onCreateProject}>
            {t('start.pickProject.newProject')}
          </button>
          {empty ? null : (
            <button
              type="submit"
              form={`${ids}-form`}
              className="button button--primary"
              data-testid="project-pick-submit"
              disabled={chosen === null || busy}
            >
              {t('projects.files.create')}
            </button>
          )}
        </>
      }
    >
      <form id={`${ids}-form`} className="form" onSubmit={(event) => void submit(event)}>
        {projects === null && !error ? <p role="status">{t('start.pickProject.loading')}</p> : null}
        {empty ? <p className="dialog__text">{t('start.pickProject.none')}</p> : null}
        {projects && projects.length > 0 ? (
          <div className="field">
            <p className="dialog__text">{t('start.pickProject.question')}</p>
            <label className="field__label" htmlFor={`${ids}-project`}>
              {t('start.pickProject.label')}
            </label>
            <select
              id={`${ids}-project`}
              className="input"
              data-testid="project-pick-select"
              value={chosen ?? ''}
              onChange={(event) => setChosen(Number(event.target.value))}
            >
              {projects.map((project) => (
                <option key={project.id} value={project.id}>
                  {project.name}
                </option>
              ))}
            </select>
          </div>
        ) : null}
        {error ? (
          <p className="field__error" role="alert">
            <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
          </p>
        ) : null}
      </form>
    </Dialog>
  );
}
