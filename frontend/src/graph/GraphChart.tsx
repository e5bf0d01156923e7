/**
 * The sequencer chart of an S7-Graph FB (S7-Graph's sequencer view): the sequencers of the block
 * as tabs, the chart of one laid out by elkjs in the worker (`chartGraph.ts`) and drawn in SVG
 * left to right whatever the page's direction, the toolbar and S7-Graph's keys (`chartKeys.ts`)
 * editing through the document's pure edits (`edits.ts`), undo and redo, an inline dialog to
 * rename or renumber (F2) and one to pick a jump's target. Online, active steps are green,
 * disturbed ones red with their active time under them, and each transition shows whether its
 * condition holds (power-flow colours). The checker's findings mark the steps and transitions they
 * concern, with the finding as tooltip.
 */
import { memo, useCallback, useEffect, useMemo, useRef, useState, type KeyboardEvent, type ReactNode } from 'react';
import type { TFunction } from 'i18next';
import { useTranslation } from 'react-i18next';
import type { GraphStepStatus, GraphTransitionStatus } from '../api/monitor';
import type { Diagnostic } from '../api/types';
import { layoutGraph } from '../diagram/elk/elkClient';
import { arrowDirection, nextInDirection, type NavItem } from '../diagram/navigation';
import { flowClass } from '../diagram/powerFlow';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { ChartToolbar } from './ChartToolbar';
import {
  STEP_BOX_H,
  STEP_H,
  STEP_NAME_X,
  TRANS_BAR,
  TRANS_H,
  TRANS_TEXT_X,
  TRANS_X,
  conditionText,
  jumpLabel,
  stepName,
  layoutSequencer,
  transitionLabel,
  type BranchLine,
  type ChartLayout,
  type PlacedEdge,
  type PlacedStep,
  type PlacedTransition,
} from './chartGraph';
import { chartCommand, type ChartCommand } from './chartKeys';
import { problemsByItem, type ItemKey } from './chartProblems';
import * as edits from './edits';
import type { GraphBlock, Sequencer } from './model';
import { sameItem, type GraphItem, type GraphSelection } from './selection';
import type { GraphDocument } from './useGraphDocument';
import type { GraphMonitor } from './useGraphMonitoring';
import './chart.css';

export interface GraphChartProps {
  doc: GraphDocument;
  selection: GraphSelection;
  onSelect: (selection: GraphSelection) => void;
  onOpenStep: (step: string) => void;
  monitor: GraphMonitor | null;
  readOnly: boolean;
  /** Opens the block settings (the shell holds the dialog); absent: the button is off. */
  onSettings?: () => void;
  /** Opens the Control Sequencer (the shell holds the dialog); absent: the button is off. */
  onControl?: () => void;
}

/** The performance mark the chart leaves each time it has drawn a new layout: `make bench` reads it. */
export const CHART_DRAWN_MARK = 'nasaq:graph-chart-drawn';
const NOTICE_MS = 4000;
/** The drawing stays left to right on right-to-left pages (React's SVG types lack `dir`). */
const LTR = { dir: 'ltr' } as Record<string, string>;

type Inserted = { block: GraphBlock; select: GraphItem | null };

function itemKeyOf(item: GraphItem): string {
  return `${item.kind}:${item.name}`;
}

/** `problem` when an error is among the findings, `warning` otherwise: the class an item is marked with. */
function worst(problems: readonly Diagnostic[]): 'problem' | 'warning' {
  return problems.some((p) => p.severity === 'error') ? 'problem' : 'warning';
}

function formatTime(ms: number): string {
  return ms < 10000 ? (ms / 1000).toFixed(1) : String(Math.floor(ms / 1000));
}

// -- drawn items (memoised: online, only the items whose status changed draw again) -------------
// They get the chart's `t` rather than each asking i18next for its own: hundreds of
// `useTranslation` hooks cost a large chart a good part of its first draw.

interface StepShapeProps {
  placed: PlacedStep;
  selected: boolean;
  status: GraphStepStatus | null | undefined;
  problems: readonly Diagnostic[] | undefined;
  problemText: string;
  onPick: (item: GraphItem) => void;
  onOpen: (name: string) => void;
  t: TFunction;
}

const StepShape = memo(function StepShape({ placed, selected, status, problems, problemText, onPick, onOpen, t }: StepShapeProps) {
  const { step, x, y, width } = placed;
  const state = status ? status.state : 'inactive';
  const cx = x + width / 2;
  const title = [`S${step.number} ${step.name}`, step.comment, problemText].filter(Boolean).join('\n');
  const item: GraphItem = { kind: 'step', name: step.name };
  const showTime = status && status.state !== 'inactive';
  return (
    <g
      className={`graph-step graph-step--${state}${selected ? ' graph-step--selected' : ''}${problems ? ` graph-step--${worst(problems)}` : ''}`}
      data-testid={`graph-step-${step.number}`}
      data-state={state}
      data-initial={step.initial}
      data-item-key={itemKeyOf(item)}
      role="option"
      aria-selected={selected}
      aria-label={t('graphChart.step', { number: step.number, name: step.name })}
      onClick={(event) => {
        event.stopPropagation();
        onPick(item);
      }}
      onDoubleClick={(event) => {
        event.stopPropagation();
        onOpen(step.name);
      }}
    >
      <title>{title}</title>
      <rect className="graph-step__box" x={x} y={y} width={width} height={STEP_BOX_H} />
      {step.initial ? <rect className="graph-step__inner" x={x + 4} y={y + 4} width={width - 8} height={STEP_BOX_H - 8} /> : null}
      <text className="graph-step__number" x={x + 10} y={y + STEP_BOX_H / 2 + 4}>
        {`S${step.number}`}
      </text>
      <text className="graph-step__name" x={x + STEP_NAME_X} y={y + STEP_BOX_H / 2 + 4}>
        {stepName(step.name)}
      </text>
      {step.interlock ? (
        <text className="graph-step__marker" x={x + width - 20} y={y + 12}>
          C
        </text>
      ) : null}
      {step.supervision ? (
        <text className="graph-step__marker" x={x + width - 10} y={y + 12}>
          V
        </text>
      ) : null}
      {problems ? <circle className={`graph-chart__problem graph-chart__problem--${worst(problems)}`} cx={x + width - 4} cy={y + STEP_BOX_H - 4} r={4} /> : null}
      <line className="graph-chart__wire" x1={cx} y1={y + STEP_BOX_H} x2={cx} y2={y + STEP_H} />
      {showTime ? (
        <text className="graph-step__time" x={cx + 6} y={y + STEP_BOX_H + 12} data-testid={`graph-step-time-${step.number}`}>
          {t('graphChart.time', { seconds: formatTime(status.t_ms) })}
        </text>
      ) : null}
    </g>
  );
});

interface TransitionShapeProps {
  placed: PlacedTransition;
  selected: boolean;
  status: GraphTransitionStatus | null | undefined;
  online: boolean;
  problems: readonly Diagnostic[] | undefined;
  problemText: string;
  onPick: (item: GraphItem) => void;
  t: TFunction;
}

const TransitionShape = memo(function TransitionShape({ placed, selected, status, online, problems, problemText, onPick, t }: TransitionShapeProps) {
  const { transition, x, y, width, height, jumpTo } = placed;
  const bx = x + TRANS_X;
  const by = y + TRANS_H / 2;
  const flow = online ? (status ? (status.tt ? 1 : 0) : null) : undefined;
  const condition = conditionText(transition.condition);
  const title = [`T${transition.number} ${transition.name}`, condition, transition.comment, problemText].filter(Boolean).join('\n');
  const item: GraphItem = { kind: 'transition', name: transition.name };
  const end = !transition.jump && transition.target.length === 0;
  return (
    <g
      className={`graph-transition ${flowClass(flow)}${selected ? ' graph-transition--selected' : ''}${problems ? ` graph-transition--${worst(problems)}` : ''}`}
      data-testid={`graph-transition-${transition.number}`}
      data-tt={online && status ? String(status.tt) : undefined}
      data-item-key={itemKeyOf(item)}
      role="option"
      aria-selected={selected}
      aria-label={t('graphChart.transition', { number: transition.number, name: transition.name })}
      onClick={(event) => {
        event.stopPropagation();
        onPick(item);
      }}
    >
      <title>{title}</title>
      <rect className="graph-transition__hit" x={x} y={y} width={width} height={height} />
      <line className="graph-chart__wire" x1={bx} y1={y} x2={bx} y2={transition.jump || end ? by + 10 : y + height} />
      <line className="graph-transition__bar" x1={bx - TRANS_BAR} y1={by} x2={bx + TRANS_BAR} y2={by} />
      <text className="graph-transition__label" x={x + TRANS_TEXT_X} y={by + 4}>
        {transitionLabel(transition)}
      </text>
      {problems ? <circle className={`graph-chart__problem graph-chart__problem--${worst(problems)}`} cx={x + TRANS_TEXT_X - 8} cy={by - 8} r={4} /> : null}
      {transition.jump ? (
        <>
          <line className="graph-chart__wire" x1={bx} y1={by + 10} x2={bx} y2={by + 26} />
          <path className="graph-chart__arrow" d={`M${bx - 5},${by + 22} L${bx},${by + 30} L${bx + 5},${by + 22} Z`} />
          <text className="graph-transition__jump" x={bx + 10} y={by + 30} data-testid={`graph-jump-${transition.number}`}>
            {jumpLabel(transition.target[0] ?? '', jumpTo?.number ?? null)}
          </text>
        </>
      ) : null}
      {end ? (
        <>
          <line className="graph-chart__wire" x1={bx} y1={by + 10} x2={bx} y2={by + 14} />
          <line className="graph-chart__end" x1={bx - 8} y1={by + 15} x2={bx + 8} y2={by + 15} />
        </>
      ) : null}
    </g>
  );
});

function EdgeShape({ edge }: { edge: PlacedEdge }) {
  return <polyline className="graph-chart__wire graph-chart__edge" data-edge={edge.id} points={edge.points.map((p) => `${p.x},${p.y}`).join(' ')} />;
}

function BranchShape({ line }: { line: BranchLine }) {
  if (line.kind === 'alternative') return <line className="graph-chart__branch" data-branch="alternative" x1={line.x1} y1={line.y} x2={line.x2} y2={line.y} />;
  return (
    <g className="graph-chart__branch graph-chart__branch--double" data-branch="simultaneous">
      <line x1={line.x1 - 6} y1={line.y - 2} x2={line.x2 + 6} y2={line.y - 2} />
      <line x1={line.x1 - 6} y1={line.y + 2} x2={line.x2 + 6} y2={line.y + 2} />
    </g>
  );
}

// -- the inline dialogs ---------------------------------------------------------------------------

function InlineDialog({ at, label, testId, onClose, children }: { at: { x: number; y: number }; label: string; testId: string; onClose: () => void; children: ReactNode }) {
  const { dir, language } = useUiLanguage();
  return (
    <div
      className="graph-inline-dialog"
      role="dialog"
      aria-label={label}
      data-testid={testId}
      dir={dir}
      lang={language}
      style={{ left: at.x, top: at.y }}
      onClick={(event) => event.stopPropagation()}
      onKeyDown={(event) => {
        event.stopPropagation();
        if (event.key === 'Escape') onClose();
      }}
    >
      {children}
    </div>
  );
}

function RenameDialog({ at, kind, name, number, onApply, onClose }: { at: { x: number; y: number }; kind: GraphItem['kind']; name: string; number: number; onApply: (name: string, number: number) => string | null; onClose: () => void }) {
  const { t } = useTranslation();
  const [newName, setNewName] = useState(name);
  const [newNumber, setNewNumber] = useState(String(number));
  const [error, setError] = useState<string | null>(null);
  const submit = () => {
    const parsed = Number(newNumber);
    if (!Number.isInteger(parsed) || parsed < 1) {
      setError(t('graphChart.rename.badNumber'));
      return;
    }
    const refused = onApply(newName.trim(), parsed);
    if (refused) setError(refused);
  };
  return (
    <InlineDialog at={at} label={t(kind === 'step' ? 'graphChart.rename.stepTitle' : 'graphChart.rename.transitionTitle')} testId="graph-rename-dialog" onClose={onClose}>
      <form
        onSubmit={(event) => {
          event.preventDefault();
          submit();
        }}
      >
        <label>
          {t('graphChart.rename.name')}
          <input dir="ltr" autoFocus value={newName} onChange={(event) => setNewName(event.target.value)} data-testid="graph-rename-name" aria-invalid={error ? true : undefined} />
        </label>
        <label>
          {t('graphChart.rename.number')}
          <input dir="ltr" type="number" min={1} value={newNumber} onChange={(event) => setNewNumber(event.target.value)} data-testid="graph-rename-number" />
        </label>
        {error ? (
          <p className="graph-inline-dialog__error" role="alert">
            {error}
          </p>
        ) : null}
        <div className="graph-inline-dialog__actions">
          <button type="submit" className="button button--small button--primary" data-testid="graph-rename-ok">
            {t('graphChart.ok')}
          </button>
          <button type="button" className="button button--small" onClick={onClose}>
            {t('graphChart.cancel')}
          </button>
        </div>
      </form>
    </InlineDialog>
  );
}

function JumpDialog({ at, steps, onApply, onClose }: { at: { x: number; y: number }; steps: readonly { name: string; number: number }[]; onApply: (target: string) => void; onClose: () => void }) {
  const { t } = useTranslation();
  const [target, setTarget] = useState(steps[0]?.name ?? '');
  return (
    <InlineDialog at={at} label={t('graphChart.jump.title')} testId="graph-jump-dialog" onClose={onClose}>
      <form
        onSubmit={(event) => {
          event.preventDefault();
          if (target) onApply(target);
        }}
      >
        <label>
          {t('graphChart.jump.target')}
          <select dir="ltr" autoFocus value={target} onChange={(event) => setTarget(event.target.value)} data-testid="graph-jump-target">
            {steps.map((step) => (
              <option key={step.name} value={step.name}>
                {`S${step.number} ${step.name}`}
              </option>
            ))}
          </select>
        </label>
        <div className="graph-inline-dialog__actions">
          <button type="submit" className="button button--small button--primary" data-testid="graph-jump-ok" disabled={!target}>
            {t('graphChart.ok')}
          </button>
          <button type="button" className="button button--small" onClick={onClose}>
            {t('graphChart.cancel')}
          </button>
        </div>
      </form>
    </InlineDialog>
  );
}

// -- the chart -------------------------------------------------------------------------------------

/** The laid-out chart of the sequencer on screen; the previous one stays drawn while the next is laid out. */
function useChartLayout(sequencer: Sequencer | null): { layout: ChartLayout | null; failed: boolean } {
  const [shown, setShown] = useState<{ layout: ChartLayout | null; failed: boolean }>({ layout: null, failed: false });
  useEffect(() => {
    if (!sequencer) return;
    let live = true;
    layoutSequencer(sequencer, layoutGraph).then(
      (layout) => {
        if (live) setShown({ layout, failed: false });
      },
      () => {
        if (live) setShown((current) => ({ layout: current.layout, failed: true }));
      },
    );
    return () => {
      live = false;
    };
  }, [sequencer]);
  return shown;
}

export function GraphChart({ doc, selection, onSelect, onOpenStep, monitor, readOnly, onSettings, onControl }: GraphChartProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const message = useDiagnosticMessage();
  const blocks = doc.blocks ?? [];
  const blockIndex = blocks[selection.block] ? selection.block : 0;
  const block = blocks[blockIndex] ?? null;
  const seqIndex = block?.sequencers[selection.sequencer] ? selection.sequencer : 0;
  const sequencer = block?.sequencers[seqIndex] ?? null;
  const { layout, failed } = useChartLayout(sequencer);
  const [dialog, setDialog] = useState<{ kind: 'rename' | 'jump'; item: GraphItem } | null>(null);
  const [notice, setNotice] = useState<string | null>(null);
  const chartRef = useRef<HTMLDivElement | null>(null);
  const item = selection.item;

  useEffect(() => {
    if (!layout || typeof performance.mark !== 'function') return;
    performance.mark(CHART_DRAWN_MARK, { detail: { steps: layout.steps.length } });
  }, [layout]);

  useEffect(() => {
    if (!notice) return;
    const timer = setTimeout(() => setNotice(null), NOTICE_MS);
    return () => clearTimeout(timer);
  }, [notice]);

  // The selected item in view (arrows, a selection made in the step view).
  useEffect(() => {
    if (!item) return;
    const key = itemKeyOf(item);
    const node = [...(chartRef.current?.querySelectorAll('[data-item-key]') ?? [])].find((n) => n.getAttribute('data-item-key') === key);
    if (node && 'scrollIntoView' in node && typeof node.scrollIntoView === 'function') node.scrollIntoView({ block: 'nearest', inline: 'nearest' });
  }, [item, layout]);

  const online = monitor !== null;
  const status = monitor?.status ?? null;
  const stepStatus = useMemo(() => new Map((status?.steps ?? []).map((s) => [s.number, s])), [status]);
  const transitionStatus = useMemo(() => new Map((status?.transitions ?? []).map((s) => [s.number, s])), [status]);
  // Errors and warnings mark their items; notes (severity info) stay in the problems panel.
  const shown = useMemo(() => doc.problems.filter((p) => p.severity === 'error' || p.severity === 'warning'), [doc.problems]);
  const problems = useMemo(() => problemsByItem(shown, doc.places, blockIndex), [shown, doc.places, blockIndex]);
  const problemText = useCallback((list: readonly Diagnostic[] | undefined) => (list ? list.map((p) => `${p.code} ${message(p)}`).join('\n') : ''), [message]);

  const select = useCallback((next: GraphItem | null) => onSelect({ block: blockIndex, sequencer: seqIndex, item: next }), [onSelect, blockIndex, seqIndex]);
  const pick = useCallback(
    (next: GraphItem) => {
      select(next);
      chartRef.current?.focus({ preventScroll: true });
    },
    [select],
  );

  const editable = !readOnly && doc.state.status === 'ready' && !doc.pending && block !== null && sequencer !== null;
  const stepOf = (name: string) => sequencer?.steps.find((s) => s.name === name) ?? null;
  const transitionOf = (name: string) => sequencer?.transitions.find((tr) => tr.name === name) ?? null;
  // A selection the model no longer has (deleted, undone) stands for nothing.
  const current = item && (item.kind === 'step' ? stepOf(item.name) : transitionOf(item.name)) ? item : null;

  const enabled = new Set<ChartCommand | 'addSequencer'>();
  if (!readOnly && doc.canUndo) enabled.add('undo');
  if (!readOnly && doc.canRedo) enabled.add('redo');
  if (editable) {
    enabled.add('renumber');
    enabled.add('addSequencer');
    if (current) {
      enabled.add('insertStep');
      enabled.add('delete');
      enabled.add('rename');
      if (current.kind === 'step') ['alternative', 'jump', 'end'].forEach((c) => enabled.add(c as ChartCommand));
      else ['simultaneous', 'moveLeft', 'moveRight'].forEach((c) => enabled.add(c as ChartCommand));
    }
  }
  if (current) enabled.add('open');

  /** One edit of the block on screen, undoable as one step; a refused edit says so and changes nothing. */
  const apply = (change: (block: GraphBlock) => Inserted | GraphBlock | null, label: string, selectAfter?: GraphItem | null) => {
    if (!block || !editable) return;
    let result: Inserted | GraphBlock | null;
    try {
      result = change(block);
    } catch {
      result = null;
    }
    if (!result) {
      setNotice(t('graphChart.refused'));
      return;
    }
    const next = 'select' in result && 'block' in result ? result : { block: result as GraphBlock, select: selectAfter === undefined ? current : selectAfter };
    doc.edit((all) => all.map((b, k) => (k === blockIndex ? next.block : b)), label);
    select(next.select);
  };

  const anchorOf = (target: GraphItem): { x: number; y: number } => {
    const placed = target.kind === 'step' ? layout?.steps.find((s) => s.step.name === target.name) : layout?.transitions.find((tr) => tr.transition.name === target.name);
    return placed ? { x: placed.x + 12, y: placed.y + Math.min(placed.height, STEP_H) + 4 } : { x: 16, y: 16 };
  };

  const run = (command: ChartCommand | 'addSequencer') => {
    if (!enabled.has(command)) return;
    const at = current;
    switch (command) {
      case 'undo':
        doc.undo();
        return;
      case 'redo':
        doc.redo();
        return;
      case 'open':
        if (!at) return;
        if (at.kind === 'step') onOpenStep(at.name);
        else {
          const source = transitionOf(at.name)?.source[0];
          if (source) onOpenStep(source);
        }
        return;
      case 'rename':
      case 'jump':
        if (at) setDialog({ kind: command, item: at });
        return;
      case 'renumber':
        apply((b) => edits.renumber(b), t('graphChart.undo.renumber'));
        return;
      case 'addSequencer': {
        if (!block) return;
        let added: Inserted;
        try {
          added = edits.addSequencer(block);
        } catch {
          setNotice(t('graphChart.refused'));
          return;
        }
        doc.edit((all) => all.map((b, k) => (k === blockIndex ? added.block : b)), t('graphChart.undo.addSequencer'));
        onSelect({ block: blockIndex, sequencer: added.block.sequencers.length - 1, item: added.select });
        return;
      }
    }
    if (!at) return;
    switch (command) {
      case 'insertStep':
        apply((b) => edits.insertStepAfter(b, seqIndex, at), t('graphChart.undo.insertStep'));
        return;
      case 'alternative':
        apply((b) => edits.insertAlternativeBranch(b, seqIndex, at), t('graphChart.undo.alternative'));
        return;
      case 'simultaneous':
        apply((b) => edits.insertSimultaneousBranch(b, seqIndex, at), t('graphChart.undo.simultaneous'));
        return;
      case 'end':
        apply((b) => edits.insertSequenceEnd(b, seqIndex, at), t('graphChart.undo.end'));
        return;
      case 'delete':
        apply((b) => edits.deleteItem(b, seqIndex, at), t('graphChart.undo.delete'));
        return;
      case 'moveLeft':
      case 'moveRight':
        apply((b) => edits.moveBranch(b, seqIndex, at, command === 'moveLeft' ? -1 : 1), t('graphChart.undo.move'), at);
        return;
    }
  };

  const applyRename = (target: GraphItem, name: string, number: number): string | null => {
    if (!block) return null;
    const step = target.kind === 'step';
    const old = step ? stepOf(target.name) : transitionOf(target.name);
    if (!old) return null;
    let next: GraphBlock | null = block;
    if (name !== old.name) {
      next = step ? edits.renameStep(next, old.name, name) : edits.renameTransition(next, old.name, name);
      if (!next) return t('graphChart.rename.nameTaken', { name });
    }
    if (number !== old.number) {
      next = step ? edits.setStepNumber(next, name, number) : edits.setTransitionNumber(next, name, number);
      if (!next) return t('graphChart.rename.numberTaken', { number });
    }
    setDialog(null);
    if (next !== block) {
      const renamed = next;
      doc.edit((all) => all.map((b, k) => (k === blockIndex ? renamed : b)), t('graphChart.undo.rename'));
      select({ kind: target.kind, name });
    }
    chartRef.current?.focus({ preventScroll: true });
    return null;
  };

  const navItems = useMemo<NavItem<GraphItem>[]>(() => {
    if (!layout) return [];
    return [
      ...layout.steps.map((s) => ({ key: { kind: 'step', name: s.step.name } as GraphItem, x: s.x, y: s.y, width: s.width, height: s.height })),
      ...layout.transitions.map((tr) => ({ key: { kind: 'transition', name: tr.transition.name } as GraphItem, x: tr.x, y: tr.y, width: TRANS_X * 2, height: TRANS_H })),
    ];
  }, [layout]);

  const onKeyDown = (event: KeyboardEvent<HTMLDivElement>) => {
    if (event.target !== event.currentTarget) return;
    const direction = !event.altKey && !event.ctrlKey && !event.metaKey && !event.shiftKey ? arrowDirection(event.key) : null;
    if (direction) {
      event.preventDefault();
      const from = current ? navItems.find((n) => sameItem(n.key, current)) : undefined;
      if (!from) {
        const first = layout?.steps.find((s) => s.step.initial) ?? layout?.steps[0];
        if (first) select({ kind: 'step', name: first.step.name });
        return;
      }
      const next = nextInDirection(navItems, from, direction);
      if (next) select(next.key);
      return;
    }
    if (event.key === 'Escape' && current) {
      select(null);
      return;
    }
    const command = chartCommand(event);
    if (!command) return;
    event.preventDefault();
    run(command);
  };

  if (!block) return <p className="diagram-views__loading">{t('graphChart.empty')}</p>;
  const dialogItem = dialog && (dialog.item.kind === 'step' ? stepOf(dialog.item.name) : transitionOf(dialog.item.name));

  return (
    <div className="graph-chart-view">
      <ChartToolbar enabled={enabled} onCommand={run} onSettings={onSettings && !readOnly ? onSettings : null} onControl={onControl ?? null} status={online ? status : undefined} notice={notice} />
      <div className="graph-chart-view__tabs" dir={dir} lang={language}>
        {blocks.length > 1 ? (
          <select
            className="graph-chart-view__block"
            aria-label={t('graphChart.block')}
            data-testid="graph-block-picker"
            value={blockIndex}
            dir="ltr"
            onChange={(event) => onSelect({ block: Number(event.target.value), sequencer: 0, item: null })}
          >
            {blocks.map((b, k) => (
              <option key={k} value={k}>
                {b.title ? `${b.name} — ${b.title}` : b.name}
              </option>
            ))}
          </select>
        ) : null}
        <div role="tablist" aria-label={t('graphChart.sequencers')} className="graph-chart-view__tablist">
          {block.sequencers.map((seq, k) => (
            <button
              key={k}
              type="button"
              role="tab"
              aria-selected={k === seqIndex}
              className="graph-chart-view__tab"
              dir="ltr"
              onClick={() => onSelect({ block: blockIndex, sequencer: k, item: null })}
            >
              {seq.name}
            </button>
          ))}
        </div>
      </div>
      <div
        ref={chartRef}
        className="graph-chart"
        dir="ltr"
        tabIndex={0}
        data-testid="graph-chart"
        aria-label={t('graphChart.label', { name: sequencer?.name ?? '' })}
        aria-busy={!layout || undefined}
        onKeyDown={onKeyDown}
        onClick={() => select(null)}
      >
        {failed && !layout ? <p role="alert">{t('graphChart.layoutFailed')}</p> : null}
        {layout ? (
          <svg
            {...LTR}
            className="graph-chart__svg"
            width={layout.width}
            height={layout.height}
            viewBox={`0 0 ${layout.width} ${layout.height}`}
            role="listbox"
            aria-label={t('graphChart.items')}
          >
            <g className="graph-chart__edges">
              {layout.edges.map((edge) => (
                <EdgeShape key={edge.id} edge={edge} />
              ))}
              {layout.branches.map((line, k) => (
                <BranchShape key={k} line={line} />
              ))}
            </g>
            {layout.transitions.map((placed) => {
              const list = problems.get(`T${placed.transition.number}` as ItemKey);
              return (
                <TransitionShape
                  key={placed.transition.name}
                  placed={placed}
                  selected={current?.kind === 'transition' && current.name === placed.transition.name}
                  status={online ? transitionStatus.get(placed.transition.number) ?? null : undefined}
                  online={online && status !== null}
                  problems={list}
                  problemText={problemText(list)}
                  onPick={pick}
                  t={t}
                />
              );
            })}
            {layout.steps.map((placed) => {
              const list = problems.get(`S${placed.step.number}` as ItemKey);
              return (
                <StepShape
                  key={placed.step.name}
                  placed={placed}
                  selected={current?.kind === 'step' && current.name === placed.step.name}
                  status={online ? stepStatus.get(placed.step.number) ?? null : undefined}
                  problems={list}
                  problemText={problemText(list)}
                  onPick={pick}
                  onOpen={onOpenStep}
                  t={t}
                />
              );
            })}
          </svg>
        ) : !failed ? (
          <p className="diagram-views__loading">{t('graphChart.drawing')}</p>
        ) : null}
        {dialog && dialogItem ? (
          dialog.kind === 'rename' ? (
            <RenameDialog
              at={anchorOf(dialog.item)}
              kind={dialog.item.kind}
              name={dialogItem.name}
              number={dialogItem.number}
              onApply={(name, number) => applyRename(dialog.item, name, number)}
              onClose={() => {
                setDialog(null);
                chartRef.current?.focus({ preventScroll: true });
              }}
            />
          ) : (
            <JumpDialog
              at={anchorOf(dialog.item)}
              steps={sequencer?.steps ?? []}
              onApply={(target) => {
                const from = dialog.item;
                setDialog(null);
                apply((b) => edits.insertJump(b, seqIndex, from, target), t('graphChart.undo.jump'));
                chartRef.current?.focus({ preventScroll: true });
              }}
              onClose={() => {
                setDialog(null);
                chartRef.current?.focus({ preventScroll: true });
              }}
            />
          )
        ) : null}
      </div>
    </div>
  );
}
