import { useTranslation } from 'react-i18next';
import { CpuDetails } from './CpuStateIndicator';
import { cpuModeOf } from './cpuState';
import { useMonitor, useSession } from './SessionContext';

/**
 * The status bar's CPU item: the simulated CPU's mode (or that nothing is downloaded yet), the
 * scans, the simulated time and the scan time.
 */
export function CpuStatus() {
  const { t } = useTranslation();
  const { session } = useSession();
  const connection = useMonitor((state) => state.connection);
  const cpu = useMonitor((state) => state.cpu);
  const mode = cpuModeOf(session !== null, { connection, cpu });
  return (
    <span className={`status-item status-item--cpu cpu-state--${mode}`} data-testid="cpu-status" data-mode={mode}>
      {mode !== 'none' ? <span className="led" aria-hidden="true" /> : null}
      {t('status.cpu')} {t(`cpu.mode.${mode}`)}
      {cpu && connection === 'open' ? <CpuDetails cpu={cpu} testIds /> : null}
    </span>
  );
}
