import { useCallback, useEffect, useRef, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { discardFile, flushFile } from '../editor/autosave';
import { useEditorTabs, type EditorTab } from '../editor/EditorTabsContext';
import { hasPendingEdits, holdsUnsavedText } from '../editor/unsaved';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { useActiveProject } from '../projects/ActiveProject';
import { projectContents } from '../projects/projectContents';
import { readStored, writeStored } from '../ui/usePersistentState';
import {
  checkLesson,
  getLesson,
  getSolution,
  giveUp,
  openLesson,
  revealHint,
  type CheckResult,
  type Lesson,
  type LessonOpened,
  type Progress,
  type Solution,
  type Texts,
  type Where,
} from './api';
import { CheckResults } from './CheckResults';
import { OwnTitle, ProgressBadge } from './CourseOutline';
import { LessonPlant } from './LessonPlant';
import { LessonText } from './LessonText';
import { isRtl, textLanguage } from './markdown';
import { pick } from './progress';
import { answersToSend, EMPTY_QUIZ, Quiz, type QuizState } from './Quiz';

/** The hints a learner has revealed, kept in the browser so a reload shows them again. */
function hintsKey(projectId: number, lessonId: string): string {
  return `nasaq.lessonPane.hints.${projectId}.${lessonId}`;
}

function storedHints(projectId: number, lessonId: string): Texts[] {
  try {
    const value = JSON.parse(readStored(hintsKey(projectId, lessonId)) ?? '[]') as unknown;
    return Array.isArray(value) ? (value as Texts[]) : [];
  } catch {
    return [];
  }
}

type Notice = { kind: 'error'; error: ApiError } | { kind: 'text'; key: string };

/**
 * Whether every editor tab of the project has what it shows saved on the server, once the
 * saves just sent have been answered (the tabs learn it a moment later). False at once when a
 * save was refused or failed: the server does not have that text.
 */
async function savesSettled(tabs: () => readonly EditorTab[], projectId: number): Promise<boolean> {
  for (let k = 0; k < 40; k += 1) {
    const unsaved = tabs().filter((tab) => tab.kind === 'source' && tab.file?.projectId === projectId && holdsUnsavedText(tab));
    if (unsaved.length === 0) return true;
    if (unsaved.some((tab) => tab.kind === 'source' && (tab.save.status === 'conflict' || tab.save.status === 'failed'))) return false;
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
  return false;
}

/**
 * One lesson open: its text beside the editor (the learner's project of the lesson is made
 * from its start files and opened in the workbench, its first file in the editor), "Check"
 * against the learner's saved program, hints one at a time, the quiz, starting over, giving
 * up, and the reference solution once it is earned.
 */
export function LessonView({ lessonId, onBack }: { lessonId: string; onBack: () => void }) {
  const { t } = useTranslation();
  const { language: ui } = useUiLanguage();
  const errorText = useApiErrorText();
  const { setProjectId } = useActiveProject();
  const { tabs, closeFileTabs } = useEditorTabs();
  const openFile = useOpenProjectFile();
  const tabsRef = useRef(tabs);
  tabsRef.current = tabs;
  const openFileRef = useRef(openFile);
  openFileRef.current = openFile;

  const [lesson, setLesson] = useState<Lesson | null>(null);
  const [loadError, setLoadError] = useState<ApiError | null>(null);
  const [opened, setOpened] = useState<LessonOpened | null>(null);
  const [progress, setProgress] = useState<Progress | null>(null);
  const [textLang, setTextLang] = useState<string | null>(null);
  const [busy, setBusy] = useState<null | 'check' | 'reset' | 'hint' | 'giveUp' | 'solution'>(null);
  const [result, setResult] = useState<CheckResult | null>(null);
  const [notice, setNotice] = useState<Notice | null>(null);
  const [hints, setHints] = useState<Texts[]>([]);
  const [hintsTotal, setHintsTotal] = useState(0);
  const [quiz, setQuiz] = useState<QuizState>(EMPTY_QUIZ);
  const [confirming, setConfirming] = useState<null | 'reset' | 'giveUp'>(null);
  const [solution, setSolution] = useState<Solution | null>(null);
  const [attempt, setAttempt] = useState(0);

  const showFile = useCallback(async (projectId: number, name: string | null) => {
    if (!name) return;
    try {
      await openFileRef.current(projectId, name);
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    }
  }, []);

  // The lesson, and the learner's project of it opened in the workbench.
  useEffect(() => {
    let alive = true;
    setLesson(null);
    setLoadError(null);
    setOpened(null);
    setResult(null);
    setSolution(null);
    setQuiz(EMPTY_QUIZ);
    setNotice(null);
    (async () => {
      try {
        const loaded = await getLesson(lessonId);
        if (!alive) return;
        setLesson(loaded);
        setProgress(loaded.progress);
        setHintsTotal(loaded.hints_total);
        setTextLang(textLanguage(loaded.languages, loaded.text, ui));
        const made = await openLesson(lessonId, false);
        if (!alive) return;
        setOpened(made);
        if (made.progress) setProgress(made.progress);
        // The server keeps what was revealed (another browser sees it too); the copy in the
        // browser covers an answer that did not arrive.
        const kept = storedHints(made.project_id, lessonId);
        setHints(loaded.hints.length >= kept.length ? loaded.hints : kept);
        setProjectId(made.project_id);
        await showFile(made.project_id, made.open ?? loaded.open);
      } catch (caught) {
        if (alive) setLoadError(asApiError(caught));
      }
    })();
    return () => {
      alive = false;
    };
    // The interface language picks the first text shown; a language switch later keeps the learner's choice.
  }, [lessonId, attempt]);

  const projectId = opened?.project_id ?? null;

  // A new verdict comes into view (the pane may be scrolled to the text).
  const resultsRef = useRef<HTMLDivElement>(null);
  useEffect(() => {
    if (result) resultsRef.current?.scrollIntoView?.({ block: 'nearest' });
  }, [result]);

  const openWhere = useCallback(
    (where: Where) => {
      if (projectId === null) return;
      openFileRef
        .current(projectId, where.file, { line: where.line ?? 1, network: where.network, element: where.element })
        .catch((caught: unknown) => setNotice({ kind: 'error', error: asApiError(caught) }));
    },
    [projectId],
  );

  const check = useCallback(async () => {
    if (!lesson || projectId === null || busy) return;
    setBusy('check');
    setNotice(null);
    try {
      // The server checks the saved files: what the editors hold is saved first.
      await flushFile(projectId).catch(() => undefined);
      if (!(await savesSettled(() => tabsRef.current, projectId)) || hasPendingEdits()) {
        setNotice({ kind: 'text', key: 'lessonPane.check.unsaved' });
        return;
      }
      const answer = await checkLesson(lesson.id, projectId, answersToSend(lesson.quiz, quiz), ui);
      setResult(answer);
      if (answer.progress) setProgress(answer.progress);
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    } finally {
      setBusy(null);
    }
  }, [lesson, projectId, busy, quiz, ui]);

  const reset = useCallback(async () => {
    if (!lesson || projectId === null) return;
    setConfirming(null);
    setBusy('reset');
    setNotice(null);
    try {
      // The learner chose to start over: pending edits of the old files are dropped, not saved over the start.
      discardFile(projectId);
      closeFileTabs(projectId);
      const made = await openLesson(lesson.id, true);
      setOpened(made);
      if (made.progress) setProgress(made.progress);
      setResult(null);
      setQuiz(EMPTY_QUIZ);
      setProjectId(made.project_id);
      await projectContents.reload(made.project_id);
      await showFile(made.project_id, made.open ?? lesson.open);
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    } finally {
      setBusy(null);
    }
  }, [lesson, projectId, closeFileTabs, setProjectId, showFile]);

  const hint = useCallback(async () => {
    if (!lesson || projectId === null) return;
    setBusy('hint');
    setNotice(null);
    try {
      const revealed = await revealHint(lesson.id, projectId);
      setHints(revealed.hints);
      setHintsTotal(revealed.total);
      writeStored(hintsKey(projectId, lesson.id), JSON.stringify(revealed.hints));
      setProgress((current) => (current ? { ...current, hints_revealed: revealed.hints.length } : current));
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    } finally {
      setBusy(null);
    }
  }, [lesson, projectId]);

  const surrender = useCallback(async () => {
    if (!lesson || projectId === null) return;
    setConfirming(null);
    setBusy('giveUp');
    setNotice(null);
    try {
      setProgress(await giveUp(lesson.id, projectId));
      setSolution(await getSolution(lesson.id, projectId));
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    } finally {
      setBusy(null);
    }
  }, [lesson, projectId]);

  const showSolution = useCallback(async () => {
    if (!lesson || projectId === null) return;
    setBusy('solution');
    setNotice(null);
    try {
      setSolution(await getSolution(lesson.id, projectId));
    } catch (caught) {
      setNotice({ kind: 'error', error: asApiError(caught) });
    } finally {
      setBusy(null);
    }
  }, [lesson, projectId]);

  if (loadError) {
    return (
      <div className="lesson-view" data-testid="lesson-view">
        <BackButton onBack={onBack} />
        <div className="lesson-pane__error" role="alert" data-testid="lesson-error">
          <p>
            <code className="error-code">{loadError.code}</code> {errorText(loadError)}
          </p>
          <button type="button" className="button button--small" onClick={() => setAttempt((n) => n + 1)}>
            {t('lessonPane.retry')}
          </button>
        </div>
      </div>
    );
  }
  if (!lesson) {
    return (
      <div className="lesson-view" data-testid="lesson-view">
        <BackButton onBack={onBack} />
        <p className="lesson-pane__loading">{t('lessonPane.loading')}</p>
      </div>
    );
  }

  const own = lesson.languages[0] ?? 'en';
  const shown = textLang && lesson.text[textLang] !== undefined ? textLang : textLanguage(lesson.languages, lesson.text, ui);
  const earned = progress?.status === 'passed' || !!progress?.gave_up;
  const ready = projectId !== null && busy === null;

  return (
    <article className="lesson-view" data-testid="lesson-view" data-lesson={lesson.id}>
      <BackButton onBack={onBack} />
      <header className="lesson-view__header">
        <h3 className="lesson-view__title" data-testid="lesson-title">
          <OwnTitle texts={lesson.title} language={own} />
        </h3>
        <div className="lesson-view__meta">
          <span className="course-lesson__number" dir="ltr">
            {lesson.id}
          </span>
          <ProgressBadge lesson={{ progress }} />
          {lesson.works_in !== 'none' ? (
            <span className="lesson-chip" dir="ltr">
              {lesson.works_in}
            </span>
          ) : null}
          <span className="lesson-chip">{t(`lessonPane.form.${lesson.form}`)}</span>
          {lesson.time_limit_min ? <span className="lesson-chip">{t('lessonPane.timeLimit', { count: lesson.time_limit_min })}</span> : null}
        </div>
        {lesson.prerequisites.length > 0 ? (
          <p className="course-lesson__before">
            {t('lessonPane.outline.prerequisites')} <span dir="ltr">{lesson.prerequisites.join(', ')}</span>
          </p>
        ) : null}
        {opened ? (
          <p className="lesson-view__project">
            {t('lessonPane.project')} <strong dir="auto">{opened.project_name}</strong>
            {opened.open ? (
              <>
                {' '}
                <button type="button" className="link-button" dir="ltr" data-testid="lesson-open-file" onClick={() => void showFile(opened.project_id, opened.open)}>
                  {opened.open}
                </button>
              </>
            ) : null}
          </p>
        ) : (
          <p className="lesson-pane__loading">{t('lessonPane.opening')}</p>
        )}
      </header>

      {lesson.languages.length > 1 ? (
        <div className="lesson-view__languages" role="group" aria-label={t('lessonPane.textLanguage')}>
          {lesson.languages
            .filter((language) => lesson.text[language] !== undefined)
            .map((language) => (
              <button key={language} type="button" className="view-bar__choice" aria-pressed={language === shown} lang={language} data-testid={`lesson-lang-${language}`} onClick={() => setTextLang(language)}>
                {t(`lessonPane.languages.${language}`, { defaultValue: language })}
              </button>
            ))}
        </div>
      ) : null}

      <LessonText lessonId={lesson.id} language={shown} text={lesson.text[shown] ?? ''} />

      {lesson.plant && projectId !== null ? <LessonPlant config={lesson.plant} projectId={projectId} /> : null}

      <Quiz questions={lesson.quiz} language={shown} state={quiz} onChange={setQuiz} verdicts={result?.quiz ?? null} />

      {hintsTotal > 0 ? (
        <section className="lesson-hints" aria-label={t('lessonPane.hints.title')} data-testid="lesson-hints">
          <h4 className="lesson-section-title">{t('lessonPane.hints.title')}</h4>
          {hints.length > 0 ? (
            <ol className="lesson-hints__list">
              {hints.map((text, k) => (
                <li key={k} data-testid="lesson-hint" dir={isRtl(shown) ? 'rtl' : 'ltr'} lang={shown}>
                  {pick(text, shown)}
                </li>
              ))}
            </ol>
          ) : null}
          {hints.length < hintsTotal ? (
            <button type="button" className="button button--small" disabled={!ready} data-testid="lesson-hint-next" onClick={() => void hint()}>
              {t('lessonPane.hints.next', { shown: hints.length + 1, total: hintsTotal })}
            </button>
          ) : (
            <p className="lesson-pane__note">{t('lessonPane.hints.all')}</p>
          )}
        </section>
      ) : null}

      <div className="lesson-actions">
        <button type="button" className="button button--primary" disabled={!ready} data-testid="lesson-check" onClick={() => void check()}>
          {busy === 'check' ? t('lessonPane.check.running') : t('lessonPane.check.button')}
        </button>
        {confirming === 'reset' ? (
          <ConfirmRow question={t('lessonPane.reset.confirm')} yes={t('lessonPane.reset.yes')} testId="lesson-reset-yes" onYes={() => void reset()} onCancel={() => setConfirming(null)} />
        ) : (
          <button type="button" className="button" disabled={!ready} data-testid="lesson-reset" onClick={() => setConfirming('reset')}>
            {t('lessonPane.reset.button')}
          </button>
        )}
        {earned ? null : confirming === 'giveUp' ? (
          <ConfirmRow question={t('lessonPane.giveUp.confirm')} yes={t('lessonPane.giveUp.yes')} testId="lesson-give-up-yes" onYes={() => void surrender()} onCancel={() => setConfirming(null)} />
        ) : (
          <button type="button" className="button" disabled={!ready} data-testid="lesson-give-up" onClick={() => setConfirming('giveUp')}>
            {t('lessonPane.giveUp.button')}
          </button>
        )}
      </div>

      {notice ? (
        <p className="lesson-notice" role="alert" data-testid="lesson-notice">
          {notice.kind === 'error' ? (
            <>
              <code className="error-code">{notice.error.code}</code> {errorText(notice.error)}
            </>
          ) : (
            t(notice.key)
          )}
        </p>
      ) : null}

      <div ref={resultsRef}>{result ? <CheckResults result={result} onOpen={openWhere} /> : null}</div>

      {earned ? (
        <section className="lesson-solution" aria-label={t('lessonPane.solution.title')} data-testid="lesson-solution">
          <h4 className="lesson-section-title">{t('lessonPane.solution.title')}</h4>
          {solution ? (
            solution.files.map((file) => (
              <figure key={file.name} className="lesson-solution__file">
                <figcaption dir="ltr">
                  <code>{file.name}</code>
                </figcaption>
                <pre dir="ltr">{file.text}</pre>
              </figure>
            ))
          ) : (
            <button type="button" className="button button--small" disabled={!ready} data-testid="lesson-solution-show" onClick={() => void showSolution()}>
              {t('lessonPane.solution.show')}
            </button>
          )}
        </section>
      ) : null}
    </article>
  );
}

function BackButton({ onBack }: { onBack: () => void }) {
  const { t } = useTranslation();
  return (
    <button type="button" className="link-button lesson-view__back" data-testid="lesson-back" onClick={onBack}>
      {t('lessonPane.back')}
    </button>
  );
}

/** "Are you sure?" in place of a button that throws work away (start over, give up). */
function ConfirmRow({ question, yes, testId, onYes, onCancel }: { question: string; yes: string; testId: string; onYes: () => void; onCancel: () => void }) {
  const { t } = useTranslation();
  return (
    <span className="lesson-confirm" role="group" aria-label={question}>
      <span>{question}</span>
      <button type="button" className="button button--small button--danger" data-testid={testId} onClick={onYes}>
        {yes}
      </button>
      <button type="button" className="button button--small" onClick={onCancel}>
        {t('lessonPane.cancel')}
      </button>
    </span>
  );
}
