import { useTranslation } from 'react-i18next';
import { CpuStatus } from '../cpu/CpuStatus';
import { useServerHealth } from '../health/ServerHealth';
import { nativeNameOf } from '../i18n/languages';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { CompileStatus } from './CompileButton';

function ServerStatus() {
  const { t } = useTranslation();
  const { health } = useServerHealth();
  const state = health.state;
  const text =
    state === 'online'
      ? t('status.serverOnline', { version: health.health.version })
      : state === 'checking'
        ? t('status.serverChecking')
        : t('status.serverOffline');
  const title = state === 'offline' ? `${health.error.code}: ${health.error.message}` : undefined;
  return (
    <span className={`status-item status-item--${state}`} data-testid="server-status" data-state={state} title={title}>
      <span className="led" aria-hidden="true" />
      <span role="status">{text}</span>
    </span>
  );
}

/** The bottom line: server connection, interface language, the last compile and CPU state. */
export function StatusBar() {
  const { t } = useTranslation();
  const { language } = useUiLanguage();
  return (
    <footer className="statusbar">
      <ServerStatus />
      <span className="status-item" data-testid="ui-language-status">
        {t('status.language')} <span lang={language}>{nativeNameOf(language)}</span>
      </span>
      <CompileStatus />
      <CpuStatus />
    </footer>
  );
}
