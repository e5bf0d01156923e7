import { useCallback, useId, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { BookIcon, CloseIcon } from '../ui/icons';
import { readStored, writeStored } from '../ui/usePersistentState';
import { CourseOutline } from './CourseOutline';
import { LessonView } from './LessonView';
import './lessons.css';

/** Where the open lesson is remembered, so a reload comes back to it. */
export const OPEN_LESSON_STORAGE_KEY = 'nasaq.lessonPane.lesson';

/**
 * The lesson pane beside the editor: the course outline by unit, or one lesson open with its
 * text, its checks, hints and quiz (the lesson's project is open in the workbench).
 *
 * Decisions where the issue is silent:
 * - Prerequisites are shown (marked while not passed) but do not lock a lesson: as in a course
 *   book, a learner may read ahead; the outline says what to do first.
 * - A lesson's text is shown in the interface language when the lesson has it, else in English,
 *   else in its own language; one click switches between the lesson's languages.
 * - The pane grows with the window while a lesson is open (text and diagrams need room); the
 *   outline keeps the narrow width.
 * - Revealed hints are kept in the browser as well, so a reload shows them again; the server
 *   counts them in the progress.
 * - "Check" saves the open editors first and refuses (with a note) while a save is refused or
 *   failed, so a check never runs against text the learner does not see.
 */
export function LessonPane({ onClose }: { onClose: () => void }) {
  const { t } = useTranslation();
  const headingId = useId();
  const [lessonId, setLessonIdState] = useState<string | null>(() => readStored(OPEN_LESSON_STORAGE_KEY) || null);

  const setLessonId = useCallback((id: string | null) => {
    setLessonIdState(id);
    writeStored(OPEN_LESSON_STORAGE_KEY, id ?? '');
  }, []);

  return (
    <aside
      id="lesson-pane"
      className={lessonId ? 'lesson-pane lesson-pane--lesson' : 'lesson-pane'}
      aria-labelledby={headingId}
      data-testid="lesson-pane"
    >
      <div className="pane-header">
        <h2 id={headingId} className="pane-header__title">
          <BookIcon />
          <span>{t('lessonPane.title')}</span>
        </h2>
        <div className="pane-header__actions">
          <button
            type="button"
            className="icon-button"
            aria-label={t('lessonPane.close')}
            title={t('lessonPane.close')}
            data-testid="lesson-close"
            onClick={onClose}
          >
            <CloseIcon />
          </button>
        </div>
      </div>
      {/* Focusable so keyboard users can scroll the lesson. */}
      <div className="pane-body lesson-pane__body" role="region" aria-labelledby={headingId} tabIndex={0}>
        {lessonId ? (
          <LessonView key={lessonId} lessonId={lessonId} onBack={() => setLessonId(null)} />
        ) : (
          <CourseOutline onOpen={setLessonId} />
        )}
      </div>
    </aside>
  );
}
