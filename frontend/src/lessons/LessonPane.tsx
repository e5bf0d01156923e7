import { useId } from 'react';
import { useTranslation } from 'react-i18next';
import { nativeNameOf } from '../i18n/languages';
import { ComingBadge } from '../ui/ComingBadge';
import { BookIcon, CloseIcon } from '../ui/icons';
import { COURSE_OUTLINE } from './courseOutline';

/** The lesson pane beside the editor: today the course plan, later the lessons themselves. */
export function LessonPane({ onClose }: { onClose: () => void }) {
  const { t } = useTranslation();
  const headingId = useId();

  return (
    <aside id="lesson-pane" className="lesson-pane" aria-labelledby={headingId} data-testid="lesson-pane">
      <div className="pane-header">
        <h2 id={headingId} className="pane-header__title">
          <BookIcon />
          <span>{t('lessons.title')}</span>
        </h2>
        <div className="pane-header__actions">
          <button
            type="button"
            className="icon-button"
            aria-label={t('lessons.close')}
            title={t('lessons.close')}
            data-testid="lesson-close"
            onClick={onClose}
          >
            <CloseIcon />
          </button>
        </div>
      </div>
      {/* Focusable so keyboard users can scroll the course plan. */}
      <div className="pane-body lesson-pane__body" role="region" aria-labelledby={headingId} tabIndex={0}>
        <p className="lesson-pane__intro">
          {t('lessons.intro')} <ComingBadge />
        </p>
        <h3 className="lesson-pane__subtitle">{t('lessons.overview')}</h3>
        <ol className="course-outline">
          {COURSE_OUTLINE.map((unit, index) => (
            <li key={unit.id} className="course-outline__unit">
              <span className="course-outline__number" aria-hidden="true">
                {index + 1}
              </span>
              <div className="course-outline__body">
                <strong>{t(`lessons.units.${unit.id}.title`)}</strong>
                <p>{t(`lessons.units.${unit.id}.text`)}</p>
                <p className="course-outline__sources">
                  {t('lessons.sourceLanguages')}{' '}
                  {unit.sources.map((language) => (
                    <span key={language} className="language-chip" lang={language}>
                      {nativeNameOf(language)}
                    </span>
                  ))}
                </p>
              </div>
            </li>
          ))}
        </ol>
        <p className="lesson-pane__note">{t('lessons.note')}</p>
      </div>
    </aside>
  );
}
