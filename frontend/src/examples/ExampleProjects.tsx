import { useEffect, useId, useState } from 'react';
import './examples.css';
import { useTranslation } from 'react-i18next';
import { ApiError, asApiError } from '../api/client';
import type { Project } from '../api/types';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { useActiveProject } from '../projects/ActiveProject';
import { announceProject } from '../projects/useProjects';
import { listExamples, openExample, type ExampleProject } from './api';

/**
 * The Start page's example projects, titled and described in the interface language. "Open"
 * makes the example a project in that language (its comments translated, its code the same,
 * see backend `nasaq.workbench.example_variants`) and opens its main source.
 */
export function ExampleProjects() {
  const { t } = useTranslation();
  const { language } = useUiLanguage();
  const titleId = useId();
  const errorText = useApiErrorText();
  const openFile = useOpenProjectFile();
  const { setProjectId } = useActiveProject();
  const [examples, setExamples] = useState<readonly ExampleProject[] | null>(null);
  const [error, setError] = useState<ApiError | null>(null);
  const [busy, setBusy] = useState<string | null>(null);

  useEffect(() => {
    const controller = new AbortController();
    // Without the list (server down, an older server) the Start page simply shows no examples:
    // the status bar already says when the server cannot be reached.
    listExamples(language, controller.signal).then(
      (found) => setExamples(found),
      () => {
        if (!controller.signal.aborted) setExamples([]);
      },
    );
    return () => controller.abort();
  }, [language]);

  const open = async (example: ExampleProject) => {
    setBusy(example.name);
    setError(null);
    try {
      const project: Project = await openExample(example.name, language);
      announceProject(project);
      setProjectId(project.id);
      if (example.main) await openFile(project.id, example.main);
    } catch (caught) {
      setError(asApiError(caught));
    } finally {
      setBusy(null);
    }
  };

  if (examples === null || examples.length === 0) return null;
  return (
    <section className="card" aria-labelledby={titleId} data-testid="example-projects">
      <h2 id={titleId} className="card__title">
        {t('examples.title')}
      </h2>
      <p className="card__text">{t('examples.lead')}</p>
      {error ? (
        <p className="field__error" role="alert">
          {errorText(error)}
        </p>
      ) : null}
      <ul className="example-list">
        {examples.map((example) => (
          <li key={example.name} className="example-list__item" data-testid={`example-${example.name}`}>
            <div>
              <strong>{example.title}</strong>
              <p>{example.description}</p>
            </div>
            <button
              type="button"
              className="button"
              disabled={busy !== null}
              aria-label={t('examples.openNamed', { title: example.title })}
              onClick={() => void open(example)}
            >
              {t('examples.open')}
            </button>
          </li>
        ))}
      </ul>
    </section>
  );
}
