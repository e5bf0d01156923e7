import { Fragment } from 'react';
import { useTranslation } from 'react-i18next';
import { Dialog } from '../ui/Dialog';
import { SCOPES, SHORTCUTS, currentPlatform, keysOf, type Platform } from './shortcuts';
import './shortcuts.css';

interface ShortcutsDialogProps {
  onClose: () => void;
  /** Which keys to print (tests choose; the app asks the browser). */
  platform?: Platform;
}

/** Help → Keyboard shortcuts: every shortcut of the registry, grouped by where it works. */
export function ShortcutsDialog({ onClose, platform = currentPlatform() }: ShortcutsDialogProps) {
  const { t } = useTranslation();
  return (
    <Dialog
      title={t('shortcuts.title')}
      onClose={onClose}
      testId="shortcuts-dialog"
      size="medium"
      footer={
        <button type="button" className="button button--primary" onClick={onClose}>
          {t('common.close')}
        </button>
      }
    >
      <p className="dialog__text">{t('shortcuts.intro')}</p>
      {SCOPES.map((scope) => (
        <section key={scope} className="shortcuts__group" aria-labelledby={`shortcuts-${scope}`}>
          <h3 id={`shortcuts-${scope}`} className="shortcuts__heading">
            {t(`shortcuts.scope.${scope}`)}
          </h3>
          <table className="shortcuts__table" data-testid={`shortcuts-${scope}`}>
            <thead className="visually-hidden">
              <tr>
                <th scope="col">{t('shortcuts.keysColumn')}</th>
                <th scope="col">{t('shortcuts.actionColumn')}</th>
              </tr>
            </thead>
            <tbody>
              {SHORTCUTS.filter((shortcut) => shortcut.scope === scope).map((shortcut) => (
                <tr key={shortcut.id} data-testid={`shortcut-${shortcut.id}`}>
                  <td className="shortcuts__keys" dir="ltr">
                    {keysOf(shortcut, platform).map((combo, index) => (
                      <Fragment key={combo.join('+')}>
                        {index > 0 ? <span className="shortcuts__or"> / </span> : null}
                        {combo.map((key, at) => (
                          <Fragment key={key}>
                            {at > 0 ? '+' : null}
                            <kbd>{key === 'click' ? t('shortcuts.click') : key}</kbd>
                          </Fragment>
                        ))}
                      </Fragment>
                    ))}
                  </td>
                  <td>{t(shortcut.labelKey)}</td>
                </tr>
              ))}
            </tbody>
          </table>
        </section>
      ))}
    </Dialog>
  );
}
