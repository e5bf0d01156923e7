import { useTranslation } from 'react-i18next';
import type { DiagnosticEntry } from '../api/monitor';
import { formatSimTime } from '../cpu/cpuState';
import { useMonitor, useSession } from '../cpu/SessionContext';
import { useProblemText } from '../cpu/useProblemText';
import { ErrorIcon } from '../ui/icons';

/** `OB1 NW 2 line 7`: where in the program the CPU made the entry. */
export function cpuEntryPlace(entry: Pick<DiagnosticEntry, 'block' | 'network' | 'line'>): string {
  const parts: string[] = [];
  if (entry.block) parts.push(entry.block);
  if (entry.network != null) parts.push(`NW ${entry.network}`);
  if (entry.line != null) parts.push(`L ${entry.line}`);
  return parts.join(' ');
}

/**
 * The CPU's diagnostic buffer, newest first as on a CPU's module information: its history comes
 * from GET .../diagnostics when the socket connects, new entries from the frames. Each entry is
 * said in the interface language from its catalogue key and params.
 */
export function CpuDiagnostics() {
  const { t } = useTranslation();
  const { session } = useSession();
  const entries = useMonitor((state) => state.diagnostics);
  const problemText = useProblemText();
  if (!session) return null;
  return (
    <section className="cpu-diagnostics" aria-label={t('diagnostics.cpuBuffer')} data-testid="cpu-diagnostics">
      <h3 className="cpu-diagnostics__title">
        {t('diagnostics.cpuBuffer')}
        <span className="count-badge">{entries.length}</span>
      </h3>
      {entries.length === 0 ? (
        <p className="panel-empty">{t('diagnostics.cpuBufferEmpty')}</p>
      ) : (
        <ol className="diagnostics__list" reversed>
          {[...entries].reverse().map((entry, index) => {
            const place = cpuEntryPlace(entry);
            return (
              <li key={`${entries.length - index}`} className="diagnostic diagnostic--error" data-testid="cpu-diagnostic">
                <ErrorIcon className="diagnostic__icon" />
                <code className="diagnostic__code">{entry.code}</code>
                <span className="diagnostic__message">{problemText(entry)}</span>
                <code className="diagnostic__location" dir="ltr">
                  {place ? `${place} · ` : ''}
                  {formatSimTime(entry.time_ms)}
                </code>
              </li>
            );
          })}
        </ol>
      )}
    </section>
  );
}
