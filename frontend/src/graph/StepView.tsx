/**
 * S7-Graph's single-step view of the selected step: its name, number, initial flag and comment;
 * its action table; its interlock (C), supervision (V) and the conditions of the transitions
 * leaving it, each drawn and edited in the LAD/FBD editor (through {@link useConditionDoc}).
 * Every change is one edit of the Graph document, so undo is shared with the chart.
 *
 * Online: the step's state and times, the operands' values of its actions and the power flow
 * of its conditions, from the Graph monitoring the shell runs.
 *
 * Decisions where S7-Graph is not followed to the letter: a step without an interlock or
 * supervision shows a button that adds one (S7-Graph shows an empty network, which is the same
 * as none); a transition's condition left empty passes at once, as in S7-Graph.
 */
import { useCallback, useId, useMemo, useState, useSyncExternalStore, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { outlines } from '../editor/intellisense/outlineStore';
import { LadEditor } from '../lad/LadEditor';
import { fbdBodyHeight, fbdLayoutVersion, subscribeFbdLayouts } from '../lad/fbdGeometry';
import { rungSize } from '../lad/geometry';
import { layoutOf } from '../lad/layoutCache';
import type { Network, Series } from '../lad/model';
import { HEADER_H, NETWORK_PAD } from '../lad/NetworkView';
import { operandCompleter, outlineBlock } from '../lad/operands';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { readStored, writeStored } from '../ui/usePersistentState';
import { ActionsTable } from './ActionsTable';
import { blockSteps } from './actionRules';
import { conditionProblems, conditionStates, externalStatus, useConditionDoc, type ConditionSlot, type Refusal } from './conditionDoc';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useProjectContents } from '../projects/projectContents';
import { renameStep, setStepNumber, updateStep, updateTransition } from './edits';
import type { Action, GraphBlock, Step } from './model';
import type { GraphSelection } from './selection';
import type { GraphMonitor } from './useGraphMonitoring';
import type { GraphDocument } from './useGraphDocument';
import './step.css';

export interface StepViewProps {
  doc: GraphDocument;
  selection: GraphSelection;
  onSelect: (selection: GraphSelection) => void;
  monitor: GraphMonitor | null;
  projectId: number | null;
  file: string | null;
  active: boolean;
}

const MODE_KEY = 'nasaq.graph.conditionMode';

/** The step the view shows: the selected step, a selected transition's source, else the sequencer's first. */
export function shownStep(block: GraphBlock | null, selection: GraphSelection): Step | null {
  if (!block) return null;
  const steps = blockSteps(block);
  const item = selection.item;
  if (item?.kind === 'step') return steps.find((step) => step.name === item.name) ?? null;
  if (item?.kind === 'transition') {
    const transition = block.sequencers.flatMap((sequencer) => sequencer.transitions).find((t) => t.name === item.name);
    const source = transition?.source[0];
    const found = source ? steps.find((step) => step.name === source) : undefined;
    if (found) return found;
  }
  return block.sequencers[selection.sequencer]?.steps[0] ?? steps[0] ?? null;
}

/** `ms` as the step view shows a step's time: `12.3 s`, `2 min 5.0 s`. */
export function formatTime(ms: number): string {
  const seconds = ms / 1000;
  if (seconds < 60) return `${seconds.toFixed(1)} s`;
  const minutes = Math.floor(seconds / 60);
  return `${minutes} min ${(seconds - minutes * 60).toFixed(1)} s`;
}

export function formatValue(value: unknown): string {
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (typeof value === 'number') return Number.isInteger(value) ? String(value) : value.toPrecision(6);
  if (value === null || value === undefined) return '—';
  return String(value);
}

/** The interlock, supervision and outgoing transitions of `step` as condition slots. */
export function stepSlots(block: GraphBlock, stepName: string, status: GraphMonitor['status'] | null, titles: { interlock: string; supervision: string } = { interlock: '', supervision: '' }): { interlock: ConditionSlot[]; supervision: ConditionSlot[]; transitions: ConditionSlot[] } {
  const step = blockSteps(block).find((s) => s.name === stepName);
  if (!step) return { interlock: [], supervision: [], transitions: [] };
  const stepStatus = status?.steps.find((s) => s.number === step.number);
  const active = stepStatus ? stepStatus.state !== 'inactive' : false;
  const slot = (which: 'interlock' | 'supervision'): ConditionSlot[] => {
    const series = step[which];
    if (series === null) return [];
    const coil = which === 'interlock' ? 'C' : 'V';
    return [
      {
        coil,
        title: titles[which],
        series,
        origin: `S${step.number}/${coil}/`,
        write: (b: GraphBlock, next: Series) => updateStep(b, step.name, (s) => ({ ...s, [which]: next })),
        coilState: stepStatus && active ? (which === 'interlock' ? !stepStatus.interlock_error : stepStatus.supervision_error) : null,
      },
    ];
  };
  const transitions = block.sequencers
    .flatMap((sequencer) => sequencer.transitions)
    .filter((transition) => transition.source.includes(step.name))
    .map((transition): ConditionSlot => {
      const to = transition.target.length === 0 ? '⊥' : transition.jump ? `↷ ${transition.target[0] ?? ''}` : `→ ${transition.target.join(', ')}`;
      const tt = status?.transitions.find((t) => t.number === transition.number)?.tt;
      return {
        coil: transition.name,
        title: `T${transition.number} ${transition.name} ${to}`,
        series: transition.condition,
        origin: `T${transition.number}/`,
        write: (b: GraphBlock, next: Series) => updateTransition(b, transition.name, (t) => ({ ...t, condition: next })),
        coilState: tt ?? null,
      };
    });
  return { interlock: slot('interlock'), supervision: slot('supervision'), transitions };
}

/** The toolbar's height and the frame around the list (the toolbar may wrap to two rows). */
const EDITOR_CHROME = 96;
const MAX_EDITOR_H = 720;

/** A condition editor's height: all its networks drawn without scrolling (up to a limit). */
export function editorHeight(networks: readonly Network[], mode: 'LAD' | 'FBD', count: number): number {
  let height = EDITOR_CHROME;
  for (const network of networks.slice(0, count)) {
    height += HEADER_H + NETWORK_PAD + (mode === 'FBD' ? fbdBodyHeight(network) : rungSize(layoutOf(network)).height + 16);
  }
  return Math.min(MAX_EDITOR_H, Math.max(160, height));
}

function replaceBlock(blocks: readonly GraphBlock[], index: number, next: GraphBlock | null): readonly GraphBlock[] {
  if (!next || next === blocks[index]) return blocks;
  return blocks.map((block, k) => (k === index ? next : block));
}

export function StepView({ doc, selection, onSelect, monitor, projectId, file, active }: StepViewProps) {
  const { t, i18n } = useTranslation();
  const { dir, language } = useUiLanguage();
  const block = doc.blocks?.[selection.block] ?? null;
  const step = shownStep(block, selection);
  const steps = useMemo(() => (block ? blockSteps(block) : []), [block]);
  const editable = doc.state.status === 'ready' && !doc.pending;
  const [notice, setNotice] = useState<string | null>(null);
  // FBD heights are known once elkjs has laid a network out: the editors' heights follow.
  useSyncExternalStore(subscribeFbdLayouts, fbdLayoutVersion, fbdLayoutVersion);
  const titleId = useId();
  const [mode, setModeState] = useState<'LAD' | 'FBD'>(() => (readStored(MODE_KEY) === 'FBD' ? 'FBD' : 'LAD'));
  const setMode = (next: 'LAD' | 'FBD') => {
    setModeState(next);
    writeStored(MODE_KEY, next);
  };

  const outline = useSyncExternalStore(
    outlines.subscribe,
    () => (projectId === null ? null : outlines.get(projectId)),
    () => null,
  );
  const complete = useMemo(() => operandCompleter(outline, block ? outlineBlock(outline, block.name) : null, i18n.language), [outline, block, i18n.language]);

  const index = selection.block;
  const edit = useCallback((change: (block: GraphBlock) => GraphBlock | null, label: string) => doc.edit((blocks) => replaceBlock(blocks, index, blocks[index] ? change(blocks[index]) : null), label), [doc, index]);

  const stepName = step?.name ?? '';
  const status = monitor?.status ?? null;
  const onRefused = useCallback((why: Refusal) => setNotice(t(`graphStep.refused.${why}`)), [t]);
  const titles = useMemo(() => ({ interlock: t('graphStep.interlock.title'), supervision: t('graphStep.supervision.title') }), [t]);
  const interlockSlots = useCallback((b: GraphBlock) => stepSlots(b, stepName, null, titles).interlock, [stepName, titles]);
  const supervisionSlots = useCallback((b: GraphBlock) => stepSlots(b, stepName, null, titles).supervision, [stepName, titles]);
  const transitionSlots = useCallback((b: GraphBlock) => stepSlots(b, stepName, null, titles).transitions, [stepName, titles]);
  const interlockDoc = useConditionDoc(doc, index, interlockSlots, onRefused);
  const supervisionDoc = useConditionDoc(doc, index, supervisionSlots, onRefused);
  const transitionsDoc = useConditionDoc(doc, index, transitionSlots, onRefused);
  const online = useMemo(() => (block && monitor?.status ? stepSlots(block, stepName, monitor.status, titles) : null), [block, stepName, monitor?.status, titles]);
  const elements = monitor?.elements ?? null;
  const contents = useProjectContents(projectId);
  const diagnosticMessage = useDiagnosticMessage();
  const offline = useMemo(() => (block ? stepSlots(block, stepName, null, titles) : null), [block, stepName, titles]);
  const problemsOf = useCallback(
    (slots: readonly ConditionSlot[] | undefined) => conditionProblems(contents?.diagnostics ?? [], file, slots ?? [], diagnosticMessage),
    [contents?.diagnostics, file, diagnosticMessage],
  );
  const statusOf = useCallback((slots: readonly ConditionSlot[] | undefined) => (online && elements && slots ? externalStatus(conditionStates(elements, slots)) : null), [online, elements]);

  // Ctrl+Z / Ctrl+Y outside a text field undo and redo the Graph document (a field keeps its own).
  const onKeyDown = (event: KeyboardEvent<HTMLDivElement>) => {
    if (event.defaultPrevented || !(event.ctrlKey || event.metaKey) || (event.target as HTMLElement).closest('input, textarea, select')) return;
    const key = event.key.toLowerCase();
    if (key === 'z' && !event.shiftKey) doc.undo();
    else if (key === 'y' || (key === 'z' && event.shiftKey)) doc.redo();
    else return;
    event.preventDefault();
  };

  if (!block || !step) {
    return (
      <div className="graph-step" data-testid="graph-step-view" hidden={!active} dir={dir} lang={language}>
        <p className="graph-step__empty">{t('graphStep.noStep')}</p>
      </div>
    );
  }

  const stepStatus = status?.steps.find((s) => s.number === step.number) ?? null;
  const setActions = (actions: Action[], label: string) => edit((b) => updateStep(b, step.name, (s) => ({ ...s, actions })), label);
  const sequencerOf = (name: string) => Math.max(0, block.sequencers.findIndex((sequencer) => sequencer.steps.some((s) => s.name === name)));

  const rename = (text: string) => {
    const name = text.trim();
    if (name === step.name) return;
    const next = renameStep(block, step.name, name);
    if (!next) {
      setNotice(t('graphStep.refused.name', { name }));
      return;
    }
    edit(() => next, t('graphStep.undo.rename'));
    onSelect({ ...selection, item: { kind: 'step', name } });
  };
  const renumber = (text: string) => {
    const number = Number(text);
    if (number === step.number) return;
    const next = Number.isInteger(number) && number >= 1 ? setStepNumber(block, step.name, number) : null;
    if (!next) {
      setNotice(t('graphStep.refused.number', { number: text }));
      return;
    }
    edit(() => next, t('graphStep.undo.number'));
  };

  const conditionEditor = (which: 'interlock' | 'supervision' | 'transitions', count: number) => {
    // A hidden view draws no diagrams (the chart stays quick on a large sequencer).
    if (!active) return null;
    const ladDoc = which === 'interlock' ? interlockDoc : which === 'supervision' ? supervisionDoc : transitionsDoc;
    return (
      <div className="graph-step__condition" style={{ height: `${editorHeight(ladDoc.blocks?.[0]?.networks ?? [], mode, count)}px` }}>
        <LadEditor
          key={`${which}-${step.name}`}
          doc={ladDoc}
          text=""
          projectId={projectId}
          file={null}
          mode={mode}
          active={active}
          readOnly={!editable}
          monitoring={false}
          onMonitorProblem={() => undefined}
          embedded={{ fixedNetworks: true, status: statusOf(online?.[which]), label: t(`graphStep.${which}.label`, { step: step.name }), problems: problemsOf(offline?.[which]) }}
        />
      </div>
    );
  };

  const addCondition = (which: 'interlock' | 'supervision') => edit((b) => updateStep(b, step.name, (s) => ({ ...s, [which]: { elements: [] } })), t(`graphStep.undo.add_${which}`));
  const removeCondition = (which: 'interlock' | 'supervision') => edit((b) => updateStep(b, step.name, (s) => ({ ...s, [which]: null })), t(`graphStep.undo.remove_${which}`));
  const transitionCount = offline?.transitions.length ?? 0;

  return (
    <div className="graph-step" data-testid="graph-step-view" hidden={!active} dir={dir} lang={language} onKeyDown={onKeyDown}>
      <header className="graph-step__header">
        <label className="graph-step__field">
          <span>{t('graphStep.picker')}</span>
          <select
            className="input"
            data-testid="graph-step-picker"
            value={step.name}
            onChange={(event) => onSelect({ block: selection.block, sequencer: sequencerOf(event.target.value), item: { kind: 'step', name: event.target.value } })}
          >
            {steps.map((s) => (
              <option key={s.name} value={s.name}>
                {`S${s.number} ${s.name}`}
              </option>
            ))}
          </select>
        </label>
        <label className="graph-step__field">
          <span>{t('graphStep.name')}</span>
          <input key={`name-${step.name}`} className="input" data-testid="graph-step-name" defaultValue={step.name} readOnly={!editable} dir="ltr" spellCheck={false} onBlur={(event) => rename(event.target.value)} onKeyDown={(event) => event.key === 'Enter' && rename(event.currentTarget.value)} />
        </label>
        <label className="graph-step__field graph-step__field--number">
          <span>{t('graphStep.number')}</span>
          <input key={`number-${step.name}-${step.number}`} className="input" type="number" min={1} data-testid="graph-step-number-field" defaultValue={step.number} readOnly={!editable} dir="ltr" onBlur={(event) => renumber(event.target.value)} onKeyDown={(event) => event.key === 'Enter' && renumber(event.currentTarget.value)} />
        </label>
        <label className="graph-step__check">
          <input type="checkbox" checked={step.initial} disabled={!editable} data-testid="graph-step-initial" onChange={(event) => edit((b) => updateStep(b, step.name, (s) => ({ ...s, initial: event.target.checked })), t('graphStep.undo.initial'))} />
          {t('graphStep.initial')}
        </label>
        <label className="graph-step__field graph-step__field--comment">
          <span>{t('graphStep.comment')}</span>
          <input key={`comment-${step.name}-${step.comment}`} className="input" data-testid="graph-step-comment" defaultValue={step.comment} readOnly={!editable} dir="auto" onBlur={(event) => event.target.value !== step.comment && edit((b) => updateStep(b, step.name, (s) => ({ ...s, comment: event.target.value })), t('graphStep.undo.comment'))} />
        </label>
        <div className="graph-step__mode" role="group" aria-label={t('graphStep.mode')}>
          {(['LAD', 'FBD'] as const).map((m) => (
            <button key={m} type="button" className="button button--small" aria-pressed={mode === m} data-testid={`graph-condition-${m.toLowerCase()}`} onClick={() => setMode(m)}>
              {m}
            </button>
          ))}
        </div>
      </header>
      {stepStatus ? (
        <p className={`graph-step__online graph-step__online--${stepStatus.state}`} data-testid="graph-step-online" data-state={stepStatus.state} role="status">
          <span>{t(`graphStep.state.${stepStatus.state}`)}</span>
          <span>{t('graphStep.timeT', { time: formatTime(stepStatus.t_ms) })}</span>
          <span>{t('graphStep.timeU', { time: formatTime(stepStatus.u_ms) })}</span>
          {stepStatus.interlock_error ? <span className="graph-step__error">{t('graphStep.interlockError')}</span> : null}
          {stepStatus.supervision_error ? <span className="graph-step__error">{t('graphStep.supervisionError')}</span> : null}
        </p>
      ) : null}
      {notice ? (
        <p className="graph-step__notice" role="status" data-testid="graph-step-notice">
          {notice}
          <button type="button" className="button button--small" onClick={() => setNotice(null)}>
            {t('graphStep.dismiss')}
          </button>
        </p>
      ) : null}
      <section className="graph-step__section" aria-labelledby={titleId}>
        <h3 id={titleId}>{t('graphStep.actions.title')}</h3>
        <ActionsTable step={step} steps={steps} editable={editable} onChange={setActions} complete={complete} values={monitor?.status ? (monitor.elements ?? null) : null} formatValue={formatValue} />
      </section>
      {(['interlock', 'supervision'] as const).map((which) => (
        <section key={which} className="graph-step__section" data-testid={`graph-${which}`} aria-label={t(`graphStep.${which}.title`)}>
          <h3>
            {t(`graphStep.${which}.title`)}
            {step[which] !== null ? (
              <button type="button" className="button button--small" disabled={!editable} onClick={() => removeCondition(which)} data-testid={`graph-${which}-remove`}>
                {t(`graphStep.${which}.remove`)}
              </button>
            ) : null}
          </h3>
          {step[which] === null ? (
            <p className="graph-step__none">
              {t(`graphStep.${which}.none`)}{' '}
              <button type="button" className="button button--small" disabled={!editable} onClick={() => addCondition(which)} data-testid={`graph-${which}-add`}>
                {t(`graphStep.${which}.add`)}
              </button>
            </p>
          ) : (
            conditionEditor(which, 1)
          )}
        </section>
      ))}
      <section className="graph-step__section" data-testid="graph-step-transitions" aria-label={t('graphStep.transitions.title')}>
        <h3>{t('graphStep.transitions.title')}</h3>
        {transitionCount === 0 ? <p className="graph-step__none">{t('graphStep.transitions.none')}</p> : conditionEditor('transitions', transitionCount)}
      </section>
    </div>
  );
}
