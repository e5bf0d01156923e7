import { useEffect, useId, useState, type ComponentType, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { SetTime, Step } from '../api/monitor';
import { CompileButton } from '../app/CompileButton';
import { useActiveProject } from '../projects/ActiveProject';
import { CloseIcon, PlayIcon, StepIcon, StopIcon } from '../ui/icons';
import { ContinueIcon, DownloadIcon, RestartIcon } from './cpuIcons';
import { CpuStateIndicator } from './CpuStateIndicator';
import { cpuModeOf } from './cpuState';
import { useMonitor, useSession } from './SessionContext';
import '../styles/monitor.css';
import { SessionLimit } from './SessionLimit';
import { useProblemText } from './useProblemText';

type TimeMode = SetTime['mode'];
type StepBy = Step['by'];

const TIME_MODES: readonly TimeMode[] = ['virtual', 'real', 'fast', 'pause'];
const STEPS: readonly StepBy[] = ['scan', 'instruction', 'statement', 'network'];

interface ButtonProps {
  id: string;
  label: string;
  /** Mnemonic shown on the button; stays Latin in every language, as on the CPU's mode selector. */
  text?: string;
  Icon: ComponentType<{ className?: string }>;
  enabled: boolean;
  reason?: string;
  onClick: () => void;
  describedBy?: string;
  shortcut?: string;
}

function CpuButton({ id, label, text, Icon, enabled, reason, onClick, describedBy, shortcut }: ButtonProps) {
  return (
    <button
      type="button"
      className={`cpu-button cpu-button--${id}`}
      data-testid={`cpu-${id}`}
      disabled={!enabled}
      aria-label={label}
      aria-describedby={!enabled && reason ? describedBy : undefined}
      aria-keyshortcuts={shortcut}
      title={!enabled && reason ? `${label} — ${reason}` : label}
      onClick={onClick}
    >
      <Icon className="cpu-button__icon" />
      {text ? <span className="cpu-button__text">{text}</span> : null}
    </button>
  );
}

/** The cycle time field: edited freely, sent on Enter or when it loses focus. */
function CycleTimeField({ value, disabled, onApply }: { value: number; disabled: boolean; onApply: (ms: number) => void }) {
  const { t } = useTranslation();
  const id = useId();
  const [draft, setDraft] = useState<string | null>(null);
  const apply = () => {
    if (draft === null) return;
    const ms = Number(draft);
    setDraft(null);
    if (Number.isFinite(ms) && ms >= 1 && ms <= 60_000 && ms !== value) onApply(ms);
  };
  const onKeyDown = (event: KeyboardEvent<HTMLInputElement>) => {
    if (event.key === 'Enter') apply();
    if (event.key === 'Escape') setDraft(null);
  };
  return (
    <span className="cpu-cycle">
      <label htmlFor={id} className="visually-hidden">
        {t('cpu.cycleTime')}
      </label>
      <input
        id={id}
        className="cpu-cycle__input"
        data-testid="cpu-cycle-ms"
        type="number"
        inputMode="numeric"
        min={1}
        max={60000}
        step={1}
        dir="ltr"
        disabled={disabled}
        title={t('cpu.cycleTime')}
        value={draft ?? String(value)}
        onChange={(event) => setDraft(event.target.value)}
        onBlur={apply}
        onKeyDown={onKeyDown}
      />
      <span className="cpu-cycle__unit" aria-hidden="true">
        ms
      </span>
    </span>
  );
}

/**
 * The CPU panel in the top bar: download the active project (Ctrl+B), RUN, STOP, warm restart,
 * single steps, continue, the time mode and cycle time, and the CPU's state.
 */
export function CpuToolbar() {
  const { t } = useTranslation();
  const problemText = useProblemText();
  const reasonId = useId();
  const { projectId } = useActiveProject();
  const { session, download, downloading, command, problem, report } = useSession();
  const connection = useMonitor((state) => state.connection);
  const cpu = useMonitor((state) => state.cpu);
  const closedBy = useMonitor((state) => state.closedBy);
  const [stepBy, setStepBy] = useState<StepBy>('scan');
  const [closedDismissed, setClosedDismissed] = useState(false);
  useEffect(() => setClosedDismissed(false), [closedBy]);

  const mode = cpuModeOf(session !== null, { connection, cpu });
  const online = connection === 'open' && cpu !== null;
  const holding = cpu?.mode === 'HOLD';
  const paused = cpu?.mode === 'RUN' && cpu.time_mode === 'pause';
  const chosenStep: StepBy = holding ? stepBy : 'scan';

  const noProject = t('cpu.reason.noProject');
  const noSession = t('cpu.reason.noSession');
  const reason = projectId === null ? noProject : noSession;

  const shown = problem ?? (closedBy && !closedDismissed ? closedBy : null);
  const dismiss = () => (problem ? report(null) : setClosedDismissed(true));

  const setTime = (change: { mode?: TimeMode; cycle_ms?: number }) =>
    void command({ type: 'set_time', mode: change.mode ?? cpu?.time_mode ?? 'virtual', cycle_ms: change.cycle_ms ?? null });

  return (
    <div className="cpu-toolbar-wrap">
      <div className="cpu-toolbar" role="group" aria-label={t('cpu.toolbarLabel')} data-testid="cpu-toolbar">
        <span className="cpu-toolbar__label" aria-hidden="true">
          CPU
        </span>
        <button
          type="button"
          className="cpu-button cpu-button--download"
          data-testid="cpu-download"
          disabled={projectId === null || downloading}
          aria-keyshortcuts="Control+B"
          aria-describedby={projectId === null ? reasonId : undefined}
          aria-busy={downloading}
          title={`${t('cpu.download.label')} (Ctrl+B)${projectId === null ? ` — ${noProject}` : ''}`}
          onClick={() => void download()}
        >
          <DownloadIcon className="cpu-button__icon" />
          <span className="cpu-button__text cpu-button__text--word">
            {downloading ? t('cpu.download.busy') : t('cpu.download.text')}
          </span>
        </button>
        <CompileButton />
        <CpuButton
          id="run"
          label={t('cpu.run.label')}
          text="RUN"
          Icon={PlayIcon}
          enabled={online && (cpu.mode !== 'RUN' || paused)}
          reason={reason}
          describedBy={reasonId}
          onClick={() => void command({ type: 'run' })}
        />
        <CpuButton
          id="stop"
          label={t('cpu.stop.label')}
          text="STOP"
          Icon={StopIcon}
          enabled={online && cpu.mode !== 'STOP'}
          reason={reason}
          describedBy={reasonId}
          onClick={() => void command({ type: 'stop' })}
        />
        <CpuButton
          id="restart"
          label={t('cpu.restart.label')}
          Icon={RestartIcon}
          enabled={online}
          reason={reason}
          describedBy={reasonId}
          onClick={() => void command({ type: 'restart', cold: false })}
        />
        <span className="cpu-toolbar__sep" aria-hidden="true" />
        <CpuButton
          id="step"
          label={t('cpu.step.label')}
          text="STEP"
          Icon={StepIcon}
          enabled={online && cpu.mode !== 'STOP'}
          reason={online ? t('cpu.reason.stopped') : reason}
          describedBy={reasonId}
          onClick={() => void command({ type: 'step', by: chosenStep })}
        />
        <label className="visually-hidden" htmlFor={`${reasonId}-step`}>
          {t('cpu.stepBy.label')}
        </label>
        <select
          id={`${reasonId}-step`}
          className="select select--dark select--compact"
          data-testid="cpu-step-by"
          disabled={!online}
          value={chosenStep}
          title={t('cpu.stepBy.label')}
          onChange={(event) => setStepBy(event.target.value as StepBy)}
        >
          {STEPS.map((by) => (
            <option key={by} value={by} disabled={by !== 'scan' && !holding}>
              {t(`cpu.stepBy.${by}`)}
            </option>
          ))}
        </select>
        <CpuButton
          id="continue"
          label={t('cpu.continue.label')}
          Icon={ContinueIcon}
          enabled={online && (holding || paused)}
          reason={online ? t('cpu.reason.notHolding') : reason}
          describedBy={reasonId}
          onClick={() => void command({ type: 'continue' })}
        />
        <span className="cpu-toolbar__sep" aria-hidden="true" />
        <label className="visually-hidden" htmlFor={`${reasonId}-time`}>
          {t('cpu.timeMode.label')}
        </label>
        <select
          id={`${reasonId}-time`}
          className="select select--dark select--compact"
          data-testid="cpu-time-mode"
          disabled={!online}
          value={cpu?.time_mode ?? 'virtual'}
          title={t('cpu.timeMode.label')}
          onChange={(event) => setTime({ mode: event.target.value as TimeMode })}
        >
          {TIME_MODES.map((timeMode) => (
            <option key={timeMode} value={timeMode}>
              {t(`cpu.timeMode.${timeMode}`)}
            </option>
          ))}
        </select>
        <CycleTimeField value={cpu?.cycle_ms ?? 10} disabled={!online} onApply={(ms) => setTime({ cycle_ms: ms })} />
        <CpuStateIndicator mode={mode} cpu={online ? cpu : null} />
        <span id={reasonId} className="visually-hidden">
          {reason}
        </span>
      </div>
      {shown ? (
        <div className="cpu-problem" role="alert" data-testid="cpu-problem">
          <code className="error-code">{shown.code}</code>
          <div className="cpu-problem__body">
            <span className="cpu-problem__text">{problemText(shown)}</span>
            {shown.code === 'MON610' ? (
              <SessionLimit
                onRetry={() => {
                  report(null);
                  void download();
                }}
              />
            ) : null}
          </div>
          <button type="button" className="icon-button cpu-problem__close" aria-label={t('common.close')} onClick={dismiss}>
            <CloseIcon />
          </button>
        </div>
      ) : null}
    </div>
  );
}
