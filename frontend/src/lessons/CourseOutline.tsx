import { useEffect, useRef, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { WarningIcon } from '../ui/icons';
import { getCourse, type Course, type CourseProblem, type LessonSummary } from './api';
import { isRtl } from './markdown';
import { clock, pick, statusOf } from './progress';

/** A title in the unit's or lesson's own language, with the English one beside it when they differ. */
export function OwnTitle({ texts, language, className }: { texts: Partial<Record<string, string>>; language: string; className?: string }) {
  const own = texts[language] ?? texts.en ?? '';
  const english = language !== 'en' ? texts.en : undefined;
  return (
    <span className={className ?? 'own-title'}>
      <span className="own-title__own" lang={language} dir={isRtl(language) ? 'rtl' : 'ltr'}>
        {own}
      </span>
      {english && english !== own ? (
        <span className="own-title__en" lang="en" dir="ltr">
          {english}
        </span>
      ) : null}
    </span>
  );
}

/** Not started / tried / passed, attempts and time: the learner's progress in one lesson. */
export function ProgressBadge({ lesson }: { lesson: Pick<LessonSummary, 'progress'> }) {
  const { t } = useTranslation();
  const status = statusOf(lesson.progress);
  const progress = lesson.progress;
  return (
    <span className={`lesson-progress lesson-progress--${status}`} data-testid="lesson-progress" data-status={status} data-attempts={progress?.attempts ?? 0}>
      <span className="lesson-progress__status">{t(`lessonPane.progress.${status}`)}</span>
      {progress && progress.attempts > 0 ? <span className="lesson-progress__detail">{t('lessonPane.progress.attempts', { count: progress.attempts })}</span> : null}
      {progress && progress.time_s > 0 ? (
        <span className="lesson-progress__detail">
          {t('lessonPane.progress.time')} <span dir="ltr">{clock(progress.time_s)}</span>
        </span>
      ) : null}
    </span>
  );
}

function Problems({ problems }: { problems: readonly CourseProblem[] }) {
  const { t, i18n } = useTranslation();
  if (problems.length === 0) return null;
  return (
    <details className="course-problems" data-testid="course-problems">
      <summary>
        <WarningIcon className="course-problems__icon" /> {t('lessonPane.outline.problems', { count: problems.length })}
      </summary>
      <ul>
        {problems.map((problem, k) => {
          const key = problem.key ? `problems.${problem.key}` : null;
          return (
            <li key={k}>
              <code className="error-code">{problem.code}</code>{' '}
              <code dir="ltr">
                {problem.file}
                {problem.line != null ? `:${problem.line}` : ''}
              </code>{' '}
              {key && i18n.exists(key) ? t(key, { ...problem.params }) : problem.message}
            </li>
          );
        })}
      </ul>
    </details>
  );
}

/**
 * The course by unit: each unit and lesson titled in its own language with English beside it,
 * the learner's progress, the lesson's editor language and plant, and the lessons to do first.
 * The unit in the interface language is open; the others open with a click.
 */
export function CourseOutline({ onOpen }: { onOpen: (id: string) => void }) {
  const { t } = useTranslation();
  const { language } = useUiLanguage();
  const errorText = useApiErrorText();
  const [course, setCourse] = useState<Course | null>(null);
  const [error, setError] = useState<ApiError | null>(null);
  const [attempt, setAttempt] = useState(0);

  // Asked once (and on "try again"): the answer holds every title in all its languages, so a
  // language switch needs no new request; a late answer for a pane already closed is dropped.
  const asked = useRef(language);
  useEffect(() => {
    let alive = true;
    setError(null);
    getCourse(asked.current).then(
      (loaded) => alive && setCourse(loaded),
      (caught: unknown) => alive && setError(asApiError(caught)),
    );
    return () => {
      alive = false;
    };
  }, [attempt]);

  if (error) {
    return (
      <div className="lesson-pane__error" role="alert" data-testid="course-error">
        <p>
          <code className="error-code">{error.code}</code> {errorText(error)}
        </p>
        <button type="button" className="button button--small" onClick={() => setAttempt((n) => n + 1)}>
          {t('lessonPane.retry')}
        </button>
      </div>
    );
  }
  if (!course) return <p className="lesson-pane__loading">{t('lessonPane.loading')}</p>;

  const titles = new Map<string, LessonSummary>();
  for (const unit of course.units) for (const lesson of unit.lessons) titles.set(lesson.id, lesson);
  const units = [...course.units].sort((a, b) => a.order - b.order);
  const ownUnit = units.some((unit) => unit.language === language);

  return (
    <div className="course" data-testid="course-outline">
      <p className="lesson-pane__intro">{t('lessonPane.outline.intro')}</p>
      {units.length === 0 ? <p className="lesson-pane__note">{t('lessonPane.outline.empty')}</p> : null}
      {units.map((unit) => (
        <details key={unit.id} className="course-unit" open={!ownUnit || unit.language === language} data-testid={`course-unit-${unit.id}`}>
          <summary className="course-unit__summary">
            <OwnTitle texts={unit.title} language={unit.language} className="own-title course-unit__title" />
            <span className="course-unit__count">{t('lessonPane.outline.lessons', { count: unit.lessons.length })}</span>
          </summary>
          {pick(unit.summary, language) ? <p className="course-unit__text">{pick(unit.summary, language)}</p> : null}
          <ol className="course-lessons">
            {[...unit.lessons]
              .sort((a, b) => a.order - b.order)
              .map((lesson) => {
                const own = lesson.languages[0] ?? unit.language;
                const before = lesson.prerequisites.filter((id) => statusOf(titles.get(id)?.progress) !== 'passed');
                return (
                  <li key={lesson.id} className="course-lesson">
                    <button type="button" className="course-lesson__open" data-testid={`lesson-open-${lesson.id}`} onClick={() => onOpen(lesson.id)}>
                      <span className="course-lesson__number" dir="ltr">
                        {lesson.id}
                      </span>
                      <OwnTitle texts={lesson.title} language={own} className="own-title course-lesson__title" />
                    </button>
                    <div className="course-lesson__meta">
                      <ProgressBadge lesson={lesson} />
                      {lesson.works_in !== 'none' ? <span className="lesson-chip" dir="ltr">{lesson.works_in}</span> : null}
                      <span className="lesson-chip">{t(`lessonPane.form.${lesson.form}`)}</span>
                      {lesson.plant ? <span className="lesson-chip lesson-chip--plant">{t('lessonPane.outline.plant')}</span> : null}
                    </div>
                    {lesson.prerequisites.length > 0 ? (
                      <p className={before.length > 0 ? 'course-lesson__before course-lesson__before--open' : 'course-lesson__before'} data-testid={`lesson-prerequisites-${lesson.id}`}>
                        {t('lessonPane.outline.prerequisites')}{' '}
                        {lesson.prerequisites.map((id) => (
                          <span key={id}>
                            <button type="button" className="link-button" dir="ltr" onClick={() => onOpen(id)} title={titles.get(id) ? pick(titles.get(id)!.title, language) : id}>
                              {id}
                            </button>
                            {statusOf(titles.get(id)?.progress) === 'passed' ? <span className="visually-hidden"> ({t('lessonPane.progress.passed')})</span> : null}
                          </span>
                        ))}
                      </p>
                    ) : null}
                  </li>
                );
              })}
          </ol>
        </details>
      ))}
      <Problems problems={course.problems} />
    </div>
  );
}
