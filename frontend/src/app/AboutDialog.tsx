import { useTranslation } from 'react-i18next';
import { useEditorTabs } from '../editor/EditorTabsContext';
import { useServerHealth } from '../health/ServerHealth';
import { Dialog } from '../ui/Dialog';
import { NasaqMark } from '../ui/icons';

const HERE = ['projects', 'editors', 'diagrams', 'graph', 'simulator', 'monitoring', 'lessons', 'panels', 'languages'] as const;
const COMING = ['classroom'] as const;

interface AboutDialogProps {
  onClose: () => void;
  /** Opens the keyboard shortcuts dialog (in place of this one). */
  onShowShortcuts: () => void;
}

/** Help → About: the server's version, a short "what's here / what's coming", the shortcuts. */
export function AboutDialog({ onClose, onShowShortcuts }: AboutDialogProps) {
  const { t } = useTranslation();
  const { health } = useServerHealth();
  const { openStart } = useEditorTabs();

  const version =
    health.state === 'online'
      ? health.health.version
      : health.state === 'checking'
        ? t('about.versionChecking')
        : t('about.versionUnknown');

  return (
    <Dialog
      title={t('about.title')}
      onClose={onClose}
      testId="about-dialog"
      size="medium"
      footer={
        <>
          <button
            type="button"
            className="button"
            data-testid="about-open-start"
            onClick={() => {
              openStart();
              onClose();
            }}
          >
            {t('editor.openStart')}
          </button>
          <button type="button" className="button button--primary" onClick={onClose}>
            {t('common.close')}
          </button>
        </>
      }
    >
      <div className="about">
        <div className="about__brand">
          <NasaqMark size={36} className="about__mark" />
          <div>
            <p className="about__name">Nasaq</p>
            <p className="about__tagline">{t('about.tagline')}</p>
          </div>
        </div>
        <dl className="about__facts">
          <dt>{t('about.serverVersion')}</dt>
          <dd data-testid="about-version">
            <bdi>{version}</bdi>
          </dd>
        </dl>
        <div className="about__columns">
          <section>
            <h3 className="about__heading">{t('about.hereTitle')}</h3>
            <ul className="about__list">
              {HERE.map((item) => (
                <li key={item}>{t(`about.here.${item}`)}</li>
              ))}
            </ul>
          </section>
          <section>
            <h3 className="about__heading">{t('about.comingTitle')}</h3>
            <ul className="about__list">
              {COMING.map((item) => (
                <li key={item}>{t(`about.coming.${item}`)}</li>
              ))}
            </ul>
          </section>
        </div>
        <section>
          <h3 className="about__heading">{t('about.shortcutsTitle')}</h3>
          <p className="dialog__text">
            {t('shortcuts.aboutText')}{' '}
            <button type="button" className="button button--small" data-testid="about-shortcuts" onClick={onShowShortcuts}>
              {t('shortcuts.open')}
            </button>
          </p>
        </section>
      </div>
    </Dialog>
  );
}
