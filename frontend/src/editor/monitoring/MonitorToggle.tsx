import { useTranslation } from 'react-i18next';
import type { Problem } from '../../api/monitorClient';
import { useSession } from '../../cpu/SessionContext';
import { useProblemText } from '../../cpu/useProblemText';
import { Icon, type IconProps } from '../../ui/icons';

/** Glasses: STEP 7's "Monitor" button. */
export function GlassesIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <circle cx="4.5" cy="9.5" r="2.75" />
      <circle cx="11.5" cy="9.5" r="2.75" />
      <path d="M7.25 9.25c.5-.4 1-.4 1.5 0M1.75 9 3 4.5M14.25 9 13 4.5" />
    </Icon>
  );
}

/** Remembers each tab's monitoring toggle while the page lives (a tab's view may remount). */
const toggles = new Map<string, boolean>();
export const monitorToggleOf = (tabId: string) => toggles.get(tabId) ?? false;
export const rememberMonitorToggle = (tabId: string, on: boolean) => void toggles.set(tabId, on);

interface MonitorToggleProps {
  on: boolean;
  onChange: (on: boolean) => void;
  projectId: number;
  problem: Problem | null;
}

/** The status line's monitoring switch, with what stands in its way (no session, a problem). */
export function MonitorToggle({ on, onChange, projectId, problem }: MonitorToggleProps) {
  const { t } = useTranslation();
  const problemText = useProblemText();
  const { session } = useSession();
  const waiting = on && session?.projectId !== projectId;
  return (
    <span className="monitor-toggle">
      <button
        type="button"
        className={`monitor-toggle__button${on ? ' monitor-toggle__button--on' : ''}`}
        aria-pressed={on}
        data-testid="monitor-toggle"
        title={t('debug.monitor.title')}
        onClick={() => onChange(!on)}
      >
        <GlassesIcon />
        <span>{t('debug.monitor.label')}</span>
      </button>
      {waiting ? <span className="monitor-toggle__note">{t('debug.monitor.noSession')}</span> : null}
      {on && problem ? (
        <span className="monitor-toggle__note monitor-toggle__note--problem" data-testid="monitor-problem">
          <code className="error-code">{problem.code}</code> {problemText(problem)}
        </span>
      ) : null}
    </span>
  );
}
