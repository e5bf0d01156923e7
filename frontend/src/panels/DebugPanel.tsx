import { useEffect, useRef } from 'react';
import { useTranslation } from 'react-i18next';
import type { HoldState, StackFrame } from '../api/monitor';
import { useMonitor, useSession } from '../cpu/SessionContext';
import { formatAccu, formatStatusWord } from '../editor/monitoring/statusColumns';
import { formatValue } from '../editor/monitoring/inlineValues';
import { useBreakpointSync } from '../editor/monitoring/useBreakpointSync';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import '../editor/monitoring/monitoring.css';

/** An address register as the pointer it holds: `P#12.3` (byte and bit of an area pointer). */
export function formatPointer(value: number): string {
  return `P#${(value >>> 3) & 0xffff}.${value & 7}`;
}

/** The registers of a hold, in STEP 7's order, as text. */
export function registerRows(registers: HoldState['registers']): Array<[string, string]> {
  const read = (name: string) => registers[name] ?? 0;
  const accu = (name: string) => `${formatAccu(read(name), 'hex')}  (${formatAccu(read(name), 'dec')})`;
  return [
    ['ACCU1', accu('accu1')],
    ['ACCU2', accu('accu2')],
    ['AR1', formatPointer(read('ar1'))],
    ['AR2', formatPointer(read('ar2'))],
    ['STW', formatStatusWord(read('stw'))],
    ['RLO', String(read('rlo') ? 1 : 0)],
    ['STA', String(read('sta') ? 1 : 0)],
  ];
}

function framePlace(frame: StackFrame): string {
  const parts = [frame.block];
  if (frame.network != null) parts.push(`NW ${frame.network}`);
  if (frame.line != null) parts.push(`L ${frame.line}`);
  return parts.join(' · ');
}

/**
 * Opens the file the CPU holds in at the held line whenever a hold starts or a step moves it,
 * so the editor can highlight the line.
 */
function useFollowHold(hold: HoldState | null): void {
  const { session } = useSession();
  const openFile = useOpenProjectFile();
  const openRef = useRef(openFile);
  openRef.current = openFile;
  const projectId = session?.projectId ?? null;
  useEffect(() => {
    const location = hold?.location;
    if (!location?.file || location.line == null || projectId === null) return;
    openRef.current(projectId, location.file, { line: location.line }).catch(() => undefined);
  }, [hold, projectId]);
}

/**
 * The debugger's panel: while the CPU holds, the call stack (innermost first; a click shows the
 * place), the held block's locals and the registers. It also keeps the breakpoints set on the
 * session and follows the holds in the editor.
 */
export function DebugPanel() {
  const { t } = useTranslation();
  const { session } = useSession();
  const hold = useMonitor((state) => state.hold);
  const openFile = useOpenProjectFile();
  useBreakpointSync();
  useFollowHold(hold);

  if (!hold) {
    return (
      <div className="debug-panel" data-testid="debug-panel" data-holding="false">
        <p className="panel-empty">{t('debug.panel.notHolding')}</p>
      </div>
    );
  }
  const show = (frame: StackFrame) => {
    if (!session || !frame.file) return;
    openFile(session.projectId, frame.file, frame.line != null ? { line: frame.line } : null).catch(() => undefined);
  };
  return (
    <div className="debug-panel" data-testid="debug-panel" data-holding="true" data-reason={hold.reason}>
      <p className="debug-panel__where" role="status">
        {t(hold.reason === 'breakpoint' ? 'debug.panel.heldAtBreakpoint' : 'debug.panel.heldAfterStep', {
          place: framePlace(hold.location),
        })}
      </p>
      <div className="debug-panel__columns">
        <section className="debug-panel__section" aria-labelledby="debug-stack-title">
          <h3 id="debug-stack-title" className="debug-panel__title">
            {t('debug.panel.callStack')}
          </h3>
          <ol className="debug-stack" data-testid="debug-call-stack">
            {hold.call_stack.map((frame, index) => (
              <li key={`${index}-${frame.block}`}>
                <button
                  type="button"
                  className={`debug-stack__frame${index === 0 ? ' debug-stack__frame--current' : ''}`}
                  disabled={!frame.file}
                  onClick={() => show(frame)}
                  data-testid={`debug-frame-${index}`}
                >
                  <code dir="ltr">{framePlace(frame)}</code>
                  {frame.file ? (
                    <span className="debug-stack__file" dir="ltr">
                      {frame.file}
                      {frame.line != null ? `:${frame.line}` : ''}
                    </span>
                  ) : null}
                </button>
              </li>
            ))}
          </ol>
        </section>
        <section className="debug-panel__section" aria-labelledby="debug-locals-title">
          <h3 id="debug-locals-title" className="debug-panel__title">
            {t('debug.panel.locals')}
          </h3>
          {hold.locals.length === 0 ? (
            <p className="panel-empty">{t('debug.panel.noLocals')}</p>
          ) : (
            <table className="debug-table">
              <thead>
                <tr>
                  <th scope="col">{t('debug.panel.name')}</th>
                  <th scope="col">{t('debug.panel.type')}</th>
                  <th scope="col">{t('debug.panel.value')}</th>
                </tr>
              </thead>
              <tbody>
                {hold.locals.map((local) => (
                  <tr key={local.name} data-testid={`debug-local-${local.name}`}>
                    <th scope="row" dir="ltr">
                      <code>{local.name}</code>
                    </th>
                    <td dir="ltr">
                      <code>{local.type}</code>
                    </td>
                    <td dir="ltr" data-testid="debug-local-value">
                      <code>{formatValue(local.value)}</code>
                    </td>
                  </tr>
                ))}
              </tbody>
            </table>
          )}
        </section>
        <section className="debug-panel__section" aria-labelledby="debug-registers-title">
          <h3 id="debug-registers-title" className="debug-panel__title">
            {t('debug.panel.registers')}
          </h3>
          <dl className="debug-registers" data-testid="debug-registers">
            {registerRows(hold.registers).map(([name, value]) => (
              <div key={name} className="debug-registers__row" data-testid={`debug-register-${name}`}>
                <dt>{name}</dt>
                <dd dir="ltr">
                  <code>{value}</code>
                </dd>
              </div>
            ))}
          </dl>
        </section>
      </div>
    </div>
  );
}
