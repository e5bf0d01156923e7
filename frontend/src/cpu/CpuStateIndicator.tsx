import { useTranslation } from 'react-i18next';
import type { CpuState } from '../api/monitor';
import { formatMs, formatSimTime, type CpuMode } from './cpuState';
import { useMonitor } from './SessionContext';
import { useProblemText } from './useProblemText';

/** The scan counter, the simulated clock and the scan-time statistic of a running session. */
export function CpuDetails({ cpu, testIds = false }: { cpu: CpuState; testIds?: boolean }) {
  const { t } = useTranslation();
  const cycle = cpu.cycle;
  const cycleTitle = cycle
    ? t('cpu.cycleStats', {
        last: formatMs(cycle.last_ms),
        min: formatMs(cycle.min_ms),
        max: formatMs(cycle.max_ms),
        avg: formatMs(cycle.avg_ms),
      })
    : undefined;
  return (
    <span className="cpu-state__details">
      <span className="cpu-state__detail" data-testid={testIds ? 'cpu-scans' : undefined}>
        {t('cpu.scans')} <bdi dir="ltr">{cpu.scans}</bdi>
      </span>
      <span className="cpu-state__detail" data-testid={testIds ? 'cpu-time' : undefined}>
        {t('cpu.simTime')} <bdi dir="ltr">{formatSimTime(cpu.time_ms)}</bdi>
      </span>
      {cycle ? (
        <span className="cpu-state__detail" data-testid={testIds ? 'cpu-cycle' : undefined} title={cycleTitle}>
          {t('cpu.cycle')} <bdi dir="ltr">{formatMs(cycle.avg_ms)}</bdi>
        </span>
      ) : null}
    </span>
  );
}

/**
 * The CPU's operating mode as a status LED and text, like the LEDs on an S7 CPU front; on a wide
 * screen also the scan counter, the simulated clock and the scan time (the status bar always
 * shows them).
 */
export function CpuStateIndicator({ mode, cpu }: { mode: CpuMode; cpu?: CpuState | null }) {
  const { t } = useTranslation();
  const problemText = useProblemText();
  // The stop's diagnostic entry says it in the interface language; the English reason otherwise.
  const stopCode = mode === 'stop' ? (cpu?.stop_code ?? null) : null;
  const stopEntry = useMonitor((state) =>
    stopCode === null ? undefined : state.diagnostics.findLast((entry) => entry.code === stopCode),
  );
  const reason = stopEntry ? problemText(stopEntry) : cpu?.stop_reason;
  const stopped = mode === 'stop' && reason ? `${cpu?.stop_code ?? ''} ${reason}`.trim() : undefined;
  return (
    <span className={`cpu-state cpu-state--${mode}`} data-testid="cpu-state" data-mode={mode} title={stopped}>
      <span className="led" aria-hidden="true" />
      <span className="cpu-state__text" role="status">
        {t(`cpu.mode.${mode}`)}
      </span>
      {cpu && mode !== 'closed' ? <CpuDetails cpu={cpu} /> : null}
    </span>
  );
}
