import { useId } from 'react';
import { useTranslation } from 'react-i18next';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { ComingBadge } from '../ui/ComingBadge';
import { CheckIcon, DocumentIcon, NasaqMark } from '../ui/icons';
import type { SourceLanguage } from './CodeEditor';
import { useEditorTabs, type EditorTab } from './EditorTabsContext';
import { SCL_EXAMPLE, STL_EXAMPLE } from './examples';

const WORKS_NOW = ['projects', 'stlScl', 'ladFbd', 'simulator', 'monitoring', 'languages', 'rtl', 'offline'] as const;
const COMING = ['graph', 'lessons'] as const;
const STEPS = ['create', 'code', 'download', 'language', 'lessons'] as const;

/** A self-holding motor circuit in STL, as the STL editor shows it. Code stays LTR. */
const STL_SAMPLE = `      A(
      O     "Start"        // I 0.0
      O     "Motor"        // Q 4.0
      )
      AN    "Stop"         // I 0.1
      =     "Motor"`;

const NEW_SOURCES: ReadonlyArray<{ language: SourceLanguage; extension: string; example: string }> = [
  { language: 'stl', extension: 'awl', example: STL_EXAMPLE },
  { language: 'scl', extension: 'scl', example: SCL_EXAMPLE },
];

/** `source1.awl`, or the first number no open tab uses yet. */
function freeName(tabs: readonly EditorTab[], extension: string): string {
  const taken = new Set(tabs.map((tab) => (tab.kind === 'source' ? tab.name.toLowerCase() : '')));
  let number = 1;
  while (taken.has(`source${number}.${extension}`)) number += 1;
  return `source${number}.${extension}`;
}

/** The welcome page: what Nasaq is, what works today and what comes next. */
export function StartPage() {
  const { t } = useTranslation();
  const { language, dir } = useUiLanguage();
  const { tabs, openSource } = useEditorTabs();
  const titleId = useId();

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
                key={source.language}
                type="button"
                className="button button--primary"
                data-testid={`new-source-${source.language}`}
                onClick={() =>
                  openSource({
                    name: freeName(tabs, source.extension),
                    language: source.language,
                    text: source.example,
                  })
                }
              >
                <DocumentIcon />
                {t(`start.newSource.${source.language}`)}
              </button>
            ))}
          </div>
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
