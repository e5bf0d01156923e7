import { useState, type RefObject } from 'react';
import { useTranslation } from 'react-i18next';
import { CpuToolbar } from '../cpu/CpuToolbar';
import { LanguageSwitch } from '../i18n/LanguageSwitch';
import { BookIcon, HelpIcon, NasaqMark } from '../ui/icons';
import { AboutDialog } from './AboutDialog';

interface TopBarProps {
  lessonPaneOpen: boolean;
  onToggleLessonPane: () => void;
  lessonToggleRef?: RefObject<HTMLButtonElement | null>;
}

/** The application bar: product mark, CPU toolbar, language, lesson pane and help. */
export function TopBar({ lessonPaneOpen, onToggleLessonPane, lessonToggleRef }: TopBarProps) {
  const { t } = useTranslation();
  const [aboutOpen, setAboutOpen] = useState(false);

  return (
    <header className="topbar">
      <div className="topbar__brand">
        <NasaqMark size={22} className="topbar__mark" />
        <span className="topbar__name">Nasaq</span>
        <span className="topbar__tagline">{t('app.tagline')}</span>
      </div>
      <CpuToolbar />
      <div className="topbar__end">
        <LanguageSwitch />
        <button
          ref={lessonToggleRef}
          type="button"
          className={lessonPaneOpen ? 'topbar-button topbar-button--on' : 'topbar-button'}
          aria-pressed={lessonPaneOpen}
          aria-controls={lessonPaneOpen ? 'lesson-pane' : undefined}
          data-testid="lesson-toggle"
          onClick={onToggleLessonPane}
        >
          <BookIcon />
          <span>{t('topbar.lessons')}</span>
        </button>
        <button
          type="button"
          className="topbar-button"
          aria-haspopup="dialog"
          data-testid="help-button"
          onClick={() => setAboutOpen(true)}
        >
          <HelpIcon />
          <span>{t('topbar.help')}</span>
        </button>
      </div>
      {aboutOpen ? <AboutDialog onClose={() => setAboutOpen(false)} /> : null}
    </header>
  );
}
