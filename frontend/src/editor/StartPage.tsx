import { useId, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { ExampleProjects } from '../examples/ExampleProjects';
import { useActiveProject } from '../projects/ActiveProject';
import { NewProjectDialog } from '../projects/NewProjectDialog';
import { projectContents } from '../projects/projectContents';
import { ComingBadge } from '../ui/ComingBadge';
import { CheckIcon, DocumentIcon, NasaqMark } from '../ui/icons';
import { useEditorTabs } from './EditorTabsContext';
import { createStartSource, type StartLanguage } from './newSource';
import { ProjectPickDialog } from './ProjectPickDialog';

const WORKS_NOW = ['projects', 'stlScl', 'ladFbd', 'graph', 'simulator', 'monitoring', 'lessons', 'languages', 'rtl', 'offline'] as const;
const COMING = ['classroom'] as const;
const STEPS = ['create', 'code', 'download', 'language', 'lessons'] as const;

/** A self-holding motor circuit in STL, as the STL editor shows it. Code stays LTR. */
const STL_SAMPLE = `      A(
      O     "Start"        // I 0.0
      O     "Motor"        // Q 4.0
      )
      AN    "Stop"         // I 0.1
      =     "Motor"`;

const NEW_SOURCES: readonly StartLanguage[] = ['stl', 'scl'];

/**
 * "New STL/SCL source": a file of the selected project (or of the one the user picks or creates),
 * never a text that exists only in the browser and could not be saved.
 */
function useNewSource() {
  const { openSource } = useEditorTabs();
  const { projectId, setProjectId } = useActiveProject();
  const [asking, setAsking] = useState<{ language: StartLanguage; stage: 'pick' | 'create' } | null>(null);
  const [error, setError] = useState<ApiError | null>(null);

  const createIn = async (target: number, language: StartLanguage) => {
    const { info, text } = await createStartSource(target, language);
    projectContents.ensure(target);
    projectContents.putFile(target, info);
    projectContents.reloadSoon(target);
    setProjectId(target);
    setAsking(null);
    openSource({
      name: info.name,
      language,
      text,
      file: { projectId: target, path: info.name },
      version: info.version,
      dirty: false,
    });
  };

  const start = (language: StartLanguage) => {
    setError(null);
    if (projectId === null) setAsking({ language, stage: 'pick' });
    else createIn(projectId, language).catch((caught: unknown) => setError(asApiError(caught)));
  };

  return { start, asking, setAsking, createIn, error, setError };
}

/** The welcome page: what Nasaq is, what works today and what comes next. */
export function StartPage() {
  const { t } = useTranslation();
  const { language, dir } = useUiLanguage();
  const errorText = useApiErrorText();
  const titleId = useId();
  const { start, asking, setAsking, createIn, error, setError } = useNewSource();

  return (
    <article className="start-page" dir={dir} lang={language} aria-labelledby={titleId} data-testid="start-page">
      <div className="start-page__hero">
        <NasaqMark size={44} className="start-page__mark" />
        <div>
          <h1 id={titleId} className="start-page__title">
            {t('start.title')}
          </h1>
          <p className="start-page__lead">{t('start.lead')}</p>
          <div className="start-page__actions" role="group" aria-label={t('start.newSource.label')}>
            {NEW_SOURCES.map((source) => (
              <button
                key={source}
                type="button"
                className="button button--primary"
                data-testid={`new-source-${source}`}
                onClick={() => start(source)}
              >
                <DocumentIcon />
                {t(`start.newSource.${source}`)}
              </button>
            ))}
          </div>
          {error ? (
            <p className="field__error" role="alert" data-testid="new-source-error">
              <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
            </p>
          ) : null}
          {asking?.stage === 'pick' ? (
            <ProjectPickDialog
              title={t(`start.newSource.${asking.language}`)}
              onClose={() => setAsking(null)}
              onChosen={(target) => createIn(target, asking.language)}
              onCreateProject={() => setAsking({ ...asking, stage: 'create' })}
            />
          ) : null}
          {asking?.stage === 'create' ? (
            <NewProjectDialog
              onClose={() => setAsking(null)}
              onCreated={(project) => {
                createIn(project.id, asking.language).catch((caught: unknown) => {
                  setAsking(null);
                  setError(asApiError(caught));
                });
              }}
            />
          ) : null}
        </div>
      </div>

      <div className="start-page__columns">
        <section className="card" aria-labelledby={`${titleId}-now`}>
          <h2 id={`${titleId}-now`} className="card__title">
            {t('start.now.title')}
          </h2>
          <ul className="feature-list">
            {WORKS_NOW.map((item) => (
              <li key={item} className="feature-list__item">
                <CheckIcon className="feature-list__icon feature-list__icon--ok" />
                <div>
                  <strong>{t(`start.now.${item}.title`)}</strong>
                  <p>{t(`start.now.${item}.text`)}</p>
                </div>
              </li>
            ))}
          </ul>
        </section>

        <section className="card" aria-labelledby={`${titleId}-next`}>
          <h2 id={`${titleId}-next`} className="card__title">
            {t('start.next.title')}
          </h2>
          <ul className="feature-list">
            {COMING.map((item) => (
              <li key={item} className="feature-list__item">
                <ComingBadge />
                <div>
                  <strong>{t(`start.next.${item}.title`)}</strong>
                  <p>{t(`start.next.${item}.text`)}</p>
                </div>
              </li>
            ))}
          </ul>
        </section>
      </div>

      <ExampleProjects />

      <div className="start-page__columns">
        <section className="card" aria-labelledby={`${titleId}-steps`}>
          <h2 id={`${titleId}-steps`} className="card__title">
            {t('start.steps.title')}
          </h2>
          <ol className="steps">
            {STEPS.map((step) => (
              <li key={step}>{t(`start.steps.${step}`)}</li>
            ))}
          </ol>
        </section>

        <section className="card" aria-labelledby={`${titleId}-sample`}>
          <h2 id={`${titleId}-sample`} className="card__title">
            {t('start.sample.title')}
          </h2>
          <p className="card__text">{t('start.sample.text')}</p>
          <figure className="code-figure" aria-labelledby={`${titleId}-code`}>
            <figcaption id={`${titleId}-code`} className="visually-hidden">
              {t('start.sample.codeLabel')}
            </figcaption>
            <pre className="code-block" dir="ltr" lang="en" tabIndex={0}>
              <code>{STL_SAMPLE}</code>
            </pre>
          </figure>
        </section>
      </div>
    </article>
  );
}
