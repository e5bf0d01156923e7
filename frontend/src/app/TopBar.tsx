import { useEffect, useState, type RefObject } from 'react';
import { useTranslation } from 'react-i18next';
import { CpuToolbar } from '../cpu/CpuToolbar';
import { LanguageSwitch } from '../i18n/LanguageSwitch';
import { BookIcon, HelpIcon, NasaqMark } from '../ui/icons';
import { AboutDialog } from './AboutDialog';
import { ShortcutsDialog } from './ShortcutsDialog';
import { ariaKeys, opensShortcutHelp } from './shortcuts';

interface TopBarProps {
  lessonPaneOpen: boolean;
  onToggleLessonPane: () => void;
  lessonToggleRef?: RefObject<HTMLButtonElement | null>;
}

/** The application bar: product mark, CPU toolbar, language, lesson pane, shortcuts and help. */
export function TopBar({ lessonPaneOpen, onToggleLessonPane, lessonToggleRef }: TopBarProps) {
  const { t } = useTranslation();
  const [aboutOpen, setAboutOpen] = useState(false);
  const [shortcutsOpen, setShortcutsOpen] = useState(false);

  // F1 (outside the code editor) or `?` lists the keyboard shortcuts.
  useEffect(() => {
    const onKey = (event: KeyboardEvent) => {
      if (event.defaultPrevented || !opensShortcutHelp(event)) return;
      event.preventDefault();
      setAboutOpen(false);
      setShortcutsOpen(true);
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, []);

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
          title={t('topbar.lessons')}
          onClick={onToggleLessonPane}
        >
          <BookIcon />
          <span>{t('topbar.lessons')}</span>
        </button>
        <button
          type="button"
          className="topbar-button topbar-button--key"
          aria-haspopup="dialog"
          aria-label={t('shortcuts.open')}
          aria-keyshortcuts={ariaKeys('help')}
          title={`${t('shortcuts.open')} (F1)`}
          data-testid="shortcuts-button"
          onClick={() => setShortcutsOpen(true)}
        >
          <span aria-hidden="true">?</span>
        </button>
        <button
          type="button"
          className="topbar-button"
          aria-haspopup="dialog"
          data-testid="help-button"
          title={t('topbar.help')}
          onClick={() => setAboutOpen(true)}
        >
          <HelpIcon />
          <span>{t('topbar.help')}</span>
        </button>
      </div>
      {aboutOpen ? (
        <AboutDialog
          onClose={() => setAboutOpen(false)}
          onShowShortcuts={() => {
            setAboutOpen(false);
            setShortcutsOpen(true);
          }}
        />
      ) : null}
      {shortcutsOpen ? <ShortcutsDialog onClose={() => setShortcutsOpen(false)} /> : null}
    </header>
  );
}
