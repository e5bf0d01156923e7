/**
 * S7-Graph's Debug > Control Sequencer for the FB on screen: a non-modal dialog that stays open
 * while the chart is monitored. It acts on the instance DB the FB's last call used (the block
 * status says which) through `graph_control` messages, which the FB carries out at its next call:
 * the mode (AUTO/MAN/TAP/TOP, the current one pressed), acknowledge, a step on or off by number
 * (MAN only; the number defaults to the selected step), T_PUSH, INIT_SQ/OFF_SQ and the interlock
 * and supervision checks. For testing it also sets a breakpoint on the selected step's activation
 * (kept in `stepBreakpoints`, set on the server with the editor's breakpoints), steps one
 * transition at a time and continues; the hold says which step is about to become active.
 *
 * Without a running session (or with monitoring off, or before the FB's first call tells its
 * instance DB) everything is disabled with the reason; a command the server refuses (MON6xx) is
 * shown in the interface language.
 *
 * Decisions: Step on/off stay enabled outside MAN (with a hint), because "MAN, then step on" sent
 * at once is legal: the server checks the mode the DB will be in once its queued commands are
 * carried out (MON621 otherwise). The interlock/supervision check boxes show the DB's own flags
 * (`G7_IL_OFF`/`G7_SV_OFF`, watched), not a guess. A hold at a step of another Graph FB is shown
 * with that FB's name; continue and single step act on the whole CPU, as in S7-Graph/PLCSIM.
 */
import { useEffect, useId, useMemo, useRef, useState, useSyncExternalStore, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { GraphControl, GraphStatus } from '../api/monitor';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import { useProblemText } from '../cpu/useProblemText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { sessionBlockName } from '../lad/useLadMonitoring';
import { CloseIcon } from '../ui/icons';
import type { GraphBlock, Step } from './model';
import type { GraphSelection } from './selection';
import { stepBreakpointKey, stepBreakpoints as defaultBreakpoints, type StepBreakpointStore } from './stepBreakpoints';
import type { GraphMonitor } from './useGraphMonitoring';
import './control.css';

export interface ControlSequencerProps {
  open: boolean;
  onClose: () => void;
  monitor: GraphMonitor;
  selection: GraphSelection;
  block: GraphBlock;
  /** The step breakpoints (tests pass their own). */
  breakpointStore?: StepBreakpointStore;
}

const MODES = ['auto', 'man', 'tap', 'top'] as const;
type Op = GraphControl['op'];

/** The step the selection points at: a step, or the first source step of a transition. */
function selectedStep(block: GraphBlock, selection: GraphSelection): Step | null {
  const sequencer = block.sequencers[selection.sequencer];
  const item = selection.item;
  if (!sequencer || !item) return null;
  const name = item.kind === 'step' ? item.name : sequencer.transitions.find((t) => t.name === item.name)?.source[0];
  return sequencer.steps.find((step) => step.name === name) ?? null;
}

function stepName(block: GraphBlock, status: GraphStatus | null, number: number): string {
  for (const sequencer of block.sequencers) {
    const found = sequencer.steps.find((step) => step.number === number);
    if (found) return found.name;
  }
  return status?.steps.find((step) => step.number === number)?.name ?? `S${number}`;
}

const MAX_LISTED = 6;
const listed = (names: readonly string[]) => (names.length > MAX_LISTED ? `${names.slice(0, MAX_LISTED).join(', ')} …` : names.join(', '));

export function ControlSequencer({ open, ...props }: ControlSequencerProps) {
  if (!open) return null;
  return <ControlPanel {...props} />;
}

function ControlPanel({ onClose, monitor, selection, block, breakpointStore = defaultBreakpoints }: Omit<ControlSequencerProps, 'open'>) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const problemText = useProblemText();
  const { session: active } = useSession();
  const titleId = useId();
  const panel = useRef<HTMLElement>(null);
  const { status, db, hold, session, problem } = monitor;
  const fb = sessionBlockName(block.name);
  const ready = session !== null && db !== null;

  useEffect(() => panel.current?.focus(), []);

  // The step number: the selected step's, until the user types another.
  const selected = selectedStep(block, selection);
  const [number, setNumber] = useState(selected ? String(selected.number) : '');
  useEffect(() => {
    if (selected) setNumber(String(selected.number));
  }, [selected?.number]);
  const stepNumber = /^\s*\d+\s*$/.test(number) ? Number(number) : null;
  const known = stepNumber !== null && block.sequencers.some((sequencer) => sequencer.steps.some((step) => step.number === stepNumber));

  // The interlock and supervision check boxes: the DB's own flags, watched.
  const checkEntries = useMemo(() => (ready ? [`${db}.G7_IL_OFF`, `${db}.G7_SV_OFF`] : []), [ready, db]);
  useWatchEntries('graph-control', checkEntries);
  const interlockOff = useMonitor((state) => (checkEntries[0] ? state.watch[checkEntries[0]]?.value : undefined));
  const supervisionOff = useMonitor((state) => (checkEntries[1] ? state.watch[checkEntries[1]]?.value : undefined));

  // The breakpoint on the selected step's activation.
  const projectId = active?.projectId ?? null;
  const breakpoint = selected && projectId !== null ? { projectId, block: fb, step: selected.number } : null;
  const breakpointList = useSyncExternalStore(breakpointStore.subscribe, breakpointStore.list, breakpointStore.list);
  const breakpointOn = breakpoint !== null && breakpointList.some((bp) => stepBreakpointKey(bp) === stepBreakpointKey(breakpoint));
  const report = useMonitor((state) => (breakpoint ? state.breakpoints[stepBreakpointKey(breakpoint)] : undefined));
  const refused = breakpointOn && report?.state === 'refused' ? report.problem : null;

  const errors = useMemo(() => {
    const steps = status?.steps ?? [];
    return {
      interlock: steps.filter((step) => step.interlock_error).map((step) => step.name),
      supervision: steps.filter((step) => step.supervision_error).map((step) => step.name),
      active: steps.filter((step) => step.state !== 'inactive').map((step) => step.name),
    };
  }, [status]);

  const command = (op: Op, step?: number) => {
    if (!session || !db) return;
    session.send(step === undefined ? { type: 'graph_control', db, op } : { type: 'graph_control', db, op, step });
  };

  const mode = status?.mode ?? null;
  const graphHold = hold && hold.graph_step != null ? hold : null;
  // A symbolic FB name cannot be told from the session's 'FB<n>': its hold counts as this FB's.
  const here = graphHold !== null && (!graphHold.graph_block || graphHold.graph_block === fb || fb.startsWith('"'));
  const heldText = graphHold
    ? here
      ? t('graphControl.control.held', { step: stepName(block, status, graphHold.graph_step ?? 0) })
      : t('graphControl.control.heldOther', { step: graphHold.graph_step, block: graphHold.graph_block })
    : hold
      ? t('graphControl.control.heldElsewhere', { block: hold.location.block })
      : null;

  function onKeyDown(event: KeyboardEvent<HTMLElement>) {
    if (event.key === 'Escape') {
      event.stopPropagation();
      onClose();
    }
  }

  const why = !session
    ? t(active ? 'graphControl.control.monitoringOff' : 'graphControl.control.noSession')
    : !db
      ? t('graphControl.control.notCalled', { block: block.name })
      : null;

  return (
    <section
      ref={panel}
      role="dialog"
      aria-modal="false"
      aria-labelledby={titleId}
      className="graph-control"
      data-testid="graph-control-dialog"
      dir={dir}
      lang={language}
      tabIndex={-1}
      onKeyDown={onKeyDown}
    >
      <header className="graph-control__header">
        <h2 id={titleId} className="graph-control__title">
          {t('graphControl.control.title')} <code dir="ltr">{block.name}</code>
          {db ? (
            <span className="graph-control__db">
              {' '}
              {t('graphControl.control.db')} <code dir="ltr">{db}</code>
            </span>
          ) : null}
        </h2>
        <button type="button" className="icon-button" aria-label={t('graphControl.control.close')} onClick={onClose}>
          <CloseIcon />
        </button>
      </header>

      <div className="graph-control__status" role="status" aria-live="polite" data-testid="graph-control-status" data-mode={mode ?? ''} data-held={graphHold?.graph_step ?? ''}>
        <p>{mode ? t('graphControl.control.statusMode', { mode }) : t('graphControl.control.statusNoMode')}</p>
        <p>{errors.active.length ? t('graphControl.control.active', { steps: listed(errors.active) }) : t('graphControl.control.noneActive')}</p>
        {errors.interlock.length === 0 && errors.supervision.length === 0 ? (
          <p>{t('graphControl.control.noErrors')}</p>
        ) : (
          <>
            {errors.interlock.length ? (
              <p className="graph-control__error-flag">{t('graphControl.control.interlockError', { steps: listed(errors.interlock) })}</p>
            ) : null}
            {errors.supervision.length ? (
              <p className="graph-control__error-flag">{t('graphControl.control.supervisionError', { steps: listed(errors.supervision) })}</p>
            ) : null}
          </>
        )}
        {heldText ? (
          <p className="graph-control__held" data-testid="graph-control-held">
            {heldText}
          </p>
        ) : null}
      </div>

      {why ? (
        <p className="graph-control__why" data-testid="graph-control-why">
          {why}
        </p>
      ) : null}
      {problem ? (
        <p className="graph-control__problem" role="alert" data-testid="graph-control-error">
          <code className="error-code">{problem.code}</code> {problemText(problem)}
        </p>
      ) : null}

      <fieldset className="graph-control__group" disabled={!ready}>
        <legend>{t('graphControl.control.mode')}</legend>
        <div className="graph-control__modes" dir="ltr">
          {MODES.map((choice) => (
            <button
              key={choice}
              type="button"
              className="graph-control__mode"
              aria-pressed={mode === choice.toUpperCase()}
              title={t(`graphControl.control.modeHelp.${choice}`)}
              data-testid={`graph-mode-${choice}`}
              onClick={() => command(choice)}
            >
              {/* S7-Graph's mode names, the same in every language */}
              {choice.toUpperCase()}
            </button>
          ))}
        </div>
        <div className="graph-control__row">
          <button type="button" className="button" data-testid="graph-ack" title={t('graphControl.control.ackHelp')} onClick={() => command('ack')}>
            {t('graphControl.control.ack')}
          </button>
          <button type="button" className="button" data-testid="graph-push" title={t('graphControl.control.pushHelp')} onClick={() => command('push')}>
            T_PUSH
          </button>
          <button type="button" className="button" data-testid="graph-init" title={t('graphControl.control.initHelp')} onClick={() => command('init')}>
            INIT_SQ
          </button>
          <button type="button" className="button" data-testid="graph-off" title={t('graphControl.control.offHelp')} onClick={() => command('off')}>
            OFF_SQ
          </button>
        </div>
      </fieldset>

      <fieldset className="graph-control__group" disabled={!ready}>
        <legend>{t('graphControl.control.stepNumber')}</legend>
        <div className="graph-control__row">
          <input
            type="number"
            min={1}
            max={65535}
            className="input graph-control__number"
            dir="ltr"
            aria-label={t('graphControl.control.stepNumber')}
            aria-invalid={number !== '' && !known}
            data-testid="graph-step-number"
            value={number}
            onChange={(event) => setNumber(event.target.value)}
          />
          <button type="button" className="button" data-testid="graph-step-on" disabled={stepNumber === null} onClick={() => stepNumber !== null && command('step_on', stepNumber)}>
            {t('graphControl.control.stepOn')}
          </button>
          <button type="button" className="button" data-testid="graph-step-off" disabled={stepNumber === null} onClick={() => stepNumber !== null && command('step_off', stepNumber)}>
            {t('graphControl.control.stepOff')}
          </button>
        </div>
        {mode !== 'MAN' ? <p className="graph-control__hint">{t('graphControl.control.manOnly')}</p> : null}
      </fieldset>

      <fieldset className="graph-control__group" disabled={!ready}>
        <legend>{t('graphControl.control.checks')}</legend>
        <label className="graph-control__check">
          <input
            type="checkbox"
            checked={interlockOff === undefined ? true : !interlockOff}
            data-testid="graph-check-interlock"
            onChange={(event) => command(event.target.checked ? 'interlock_on' : 'interlock_off')}
          />{' '}
          {t('graphControl.control.interlock')}
        </label>
        <label className="graph-control__check">
          <input
            type="checkbox"
            checked={supervisionOff === undefined ? true : !supervisionOff}
            data-testid="graph-check-supervision"
            onChange={(event) => command(event.target.checked ? 'supervision_on' : 'supervision_off')}
          />{' '}
          {t('graphControl.control.supervision')}
        </label>
      </fieldset>

      <fieldset className="graph-control__group" disabled={session === null}>
        <legend>{t('graphControl.control.debug')}</legend>
        <div className="graph-control__row">
          <button
            type="button"
            className="button"
            aria-pressed={breakpointOn}
            disabled={breakpoint === null}
            data-testid="graph-break-step"
            onClick={() => breakpoint && breakpointStore.toggle(breakpoint)}
          >
            {selected ? t('graphControl.control.breakStep', { step: selected.name }) : t('graphControl.control.breakNoStep')}
          </button>
          <button type="button" className="button" data-testid="graph-single-step" onClick={() => session?.send({ type: 'step', by: 'transition' })}>
            {t('graphControl.control.singleStep')}
          </button>
          <button type="button" className="button" data-testid="graph-continue" disabled={!hold} onClick={() => session?.send({ type: 'continue' })}>
            {t('graphControl.control.continue')}
          </button>
        </div>
        {refused ? (
          <p className="graph-control__problem" role="alert" data-testid="graph-break-error">
            <code className="error-code">{refused.code}</code> {problemText(refused)}
          </p>
        ) : null}
      </fieldset>
    </section>
  );
}
