/**
 * The edits of a Graph block, as S7-Graph's editor offers them on the chart: each takes a block
 * and gives a new one (immutable: untouched steps, transitions and sequencers are the same
 * objects, which `textEdit.ts` relies on to re-print only what changed). The chart, the step view
 * and the dialogs call these, never change the model by hand.
 *
 * Every edit keeps the chart legal as the checker sees it (`check_structure.py`): each step is
 * left by a transition, FROM/TO name existing steps of the sequencer, names and numbers stay
 * unique in the FB, a JUMP names one step. An edit that cannot keep that refuses (returns null,
 * or the block unchanged for the inserts): the user sees nothing happen rather than a broken
 * chart. New transitions have no condition (the checker's GRA245 then reminds the user to write
 * one, as S7-Graph shows an unprogrammed transition).
 *
 * Decisions where S7-Graph leaves a choice:
 * - Deleting a step deletes it with the transition below it: the transitions that led to the
 *   step lead where that transition led. When the step has several exits (an alternative
 *   divergence) it is deleted with the transition above it instead, and its exits leave from the
 *   step before. The initial mark moves to the next step when the initial step goes.
 * - Deleting a transition: an alternative branch, a jump or a sequence end whose steps stay
 *   reachable and left goes alone; a link of a chain goes with the step below it (whose exits
 *   then leave from the step above).
 * - Renumbering follows the chart (the printer's order), across the FB's sequencers; names are
 *   kept (S7-Graph renumbers without renaming).
 * - Renaming or renumbering a step updates FROM/TO lists, ON/OFF operands and step variables
 *   (`Name.T`, `S3.X`) in conditions, actions and permanent instructions.
 * - Deleting a step that a condition or an ON/OFF action names leaves that reference as written:
 *   the checker points at it (GRA288, GRA235), as S7-Graph's consistency check does, rather than
 *   the edit silently rewriting the user's logic. Likewise a new jump closing a loop of
 *   transitions without conditions is made, and reported (GRA212) until a condition is written.
 */
import type { Action, GraphBlock, Network, Sequencer, Series, Settings, Step, Transition } from './model';
import { allSteps, allTransitions, isValidName, newSequencerName, newStepName, newTransitionName, sameName, usedNames } from './names';
import { chartOrder, sameSettings } from './print';
import type { GraphItem } from './selection';

export interface Inserted {
  block: GraphBlock;
  select: GraphItem;
}

export interface Deleted {
  block: GraphBlock;
  select: GraphItem | null;
}

// ---- helpers ----------------------------------------------------------------------------------

function sequencerOf(block: GraphBlock, seq: number): Sequencer | null {
  return block.sequencers[seq] ?? null;
}

function withSequencer(block: GraphBlock, seq: number, sequencer: Sequencer): GraphBlock {
  return { ...block, sequencers: block.sequencers.map((old, index) => (index === seq ? sequencer : old)) };
}

function stepIndex(sequencer: Sequencer, name: string): number {
  return sequencer.steps.findIndex((step) => sameName(step.name, name));
}

function has(names: readonly string[], name: string): boolean {
  return names.some((other) => sameName(other, name));
}

function unique(names: readonly string[]): string[] {
  const out: string[] = [];
  for (const name of names) if (!has(out, name)) out.push(name);
  return out;
}

function replaceName(names: readonly string[], name: string, by: readonly string[]): string[] {
  return unique(names.flatMap((other) => (sameName(other, name) ? by : [other])));
}

function newStep(block: GraphBlock): Step {
  const { name, number } = newStepName(block);
  return { number, name, initial: false, comment: '', interlock: null, supervision: null, actions: [] };
}

function newTransition(block: GraphBlock, source: string[], target: string[], jump = false): Transition {
  const { name, number } = newTransitionName(block);
  return { number, name, comment: '', source, target, jump: jump && target.length === 1, condition: null };
}

/** The block with `step` and `transition` names reserved (for a second new name). */
function reserving(block: GraphBlock, seq: number, steps: Step[], transitions: Transition[] = []): GraphBlock {
  const sequencer = sequencerOf(block, seq) as Sequencer;
  return withSequencer(block, seq, {
    ...sequencer,
    steps: [...sequencer.steps, ...steps],
    transitions: [...sequencer.transitions, ...transitions],
  });
}

/**
 * Where a new transition leaving `from` goes in `transitions`: after those that leave it already
 * (lowest priority, the rightmost branch), else before the first transition leaving a later step.
 */
function transitionPlace(sequencer: Sequencer, from: string): number {
  const { transitions } = sequencer;
  let last = -1;
  transitions.forEach((t, index) => {
    if (sameName(t.source[0] ?? '', from)) last = index;
  });
  if (last >= 0) return last + 1;
  const at = stepIndex(sequencer, from);
  const later = transitions.findIndex((t) => stepIndex(sequencer, t.source[0] ?? '') > at);
  return later < 0 ? transitions.length : later;
}

function insertAt<T>(list: readonly T[], index: number, item: T): T[] {
  return [...list.slice(0, index), item, ...list.slice(index)];
}

function addTransition(sequencer: Sequencer, transition: Transition): Sequencer {
  const place = transitionPlace(sequencer, transition.source[0] ?? '');
  return { ...sequencer, transitions: insertAt(sequencer.transitions, place, transition) };
}

function mapTransitions(sequencer: Sequencer, change: (t: Transition) => Transition): Sequencer {
  let changed = false;
  const transitions = sequencer.transitions.map((t) => {
    const next = change(t);
    changed ||= next !== t;
    return next;
  });
  return changed ? { ...sequencer, transitions } : sequencer;
}

function mapAllTransitions(block: GraphBlock, change: (t: Transition) => Transition): GraphBlock {
  let changed = false;
  const sequencers = block.sequencers.map((sequencer) => {
    const next = mapTransitions(sequencer, change);
    changed ||= next !== sequencer;
    return next;
  });
  return changed ? { ...block, sequencers } : block;
}

function stepItem(name: string): GraphItem {
  return { kind: 'step', name };
}

function transitionItem(name: string): GraphItem {
  return { kind: 'transition', name };
}

// ---- inserts ----------------------------------------------------------------------------------

/**
 * A step+transition pair. At a step S: S -Tnew-> Snew, and S's former exits leave from Snew. At a
 * transition T (to X): T -> Snew -Tnew-> X. Selects the new step.
 */
export function insertStepAfter(block: GraphBlock, seq: number, at: GraphItem): Inserted {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer) return { block, select: at };
  const step = newStep(block);
  if (at.kind === 'step') {
    const index = stepIndex(sequencer, at.name);
    if (index < 0) return { block, select: at };
    const source = sequencer.steps[index] as Step;
    const transition = newTransition(reserving(block, seq, [step]), [source.name], [step.name]);
    let next: Sequencer = mapTransitions(sequencer, (t) =>
      has(t.source, source.name) ? { ...t, source: replaceName(t.source, source.name, [step.name]) } : t,
    );
    next = { ...next, steps: insertAt(next.steps, index + 1, step) };
    next = addTransition(next, transition);
    return { block: withSequencer(block, seq, next), select: stepItem(step.name) };
  }
  const old = sequencer.transitions.find((t) => sameName(t.name, at.name));
  if (!old) return { block, select: at };
  const transition = newTransition(reserving(block, seq, [step]), [step.name], old.target, old.jump);
  const from = stepIndex(sequencer, old.source[0] ?? '');
  const to = stepIndex(sequencer, old.target[0] ?? '');
  const place = to > from ? to : from >= 0 ? from + 1 : sequencer.steps.length;
  let next: Sequencer = mapTransitions(sequencer, (t) => (t === old ? { ...t, target: [step.name], jump: false } : t));
  next = { ...next, steps: insertAt(next.steps, place, step) };
  next = addTransition(next, transition);
  return { block: withSequencer(block, seq, next), select: stepItem(step.name) };
}

/**
 * An alternative branch at step S: a new transition from S (lowest priority, right of the
 * others) to a new step, whose own new transition closes into the target of S's first exit (or
 * ends the sequence when S has none). Selects the new step.
 */
export function insertAlternativeBranch(block: GraphBlock, seq: number, at: GraphItem): Inserted {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer || at.kind !== 'step') return { block, select: at };
  const source = sequencer.steps[stepIndex(sequencer, at.name)];
  if (!source) return { block, select: at };
  const first = sequencer.transitions.find((t) => has(t.source, source.name));
  const closing = first ? first.target : [];
  const step = newStep(block);
  const opening = newTransition(reserving(block, seq, [step]), [source.name], [step.name]);
  const closeTo = stepIndex(sequencer, closing[0] ?? '');
  const jump = closing.length === 1 && (closeTo <= stepIndex(sequencer, source.name) || (first?.jump ?? false));
  const close = newTransition(reserving(block, seq, [step], [opening]), [step.name], closing, jump);
  const place = closeTo > stepIndex(sequencer, source.name) ? closeTo : sequencer.steps.length;
  let next: Sequencer = { ...sequencer, steps: insertAt(sequencer.steps, place, step) };
  next = addTransition(next, opening);
  next = addTransition(next, close);
  return { block: withSequencer(block, seq, next), select: stepItem(step.name) };
}

/**
 * A simultaneous branch at transition T: T gets one more target, a new step, which joins the
 * sources of the transitions that leave T's first target (a simultaneous convergence), or ends
 * the sequence when there are none. Selects the new step.
 */
export function insertSimultaneousBranch(block: GraphBlock, seq: number, at: GraphItem): Inserted {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer || at.kind !== 'transition') return { block, select: at };
  const old = sequencer.transitions.find((t) => sameName(t.name, at.name));
  if (!old) return { block, select: at };
  const step = newStep(block);
  const branchOf = old.target[0];
  const joins = branchOf === undefined ? [] : sequencer.transitions.filter((t) => t !== old && has(t.source, branchOf));
  let next: Sequencer = mapTransitions(sequencer, (t) => {
    if (t === old) return { ...t, target: [...t.target, step.name], jump: false };
    if (joins.includes(t)) return { ...t, source: [...t.source, step.name] };
    return t;
  });
  const after = branchOf === undefined ? -1 : stepIndex(sequencer, branchOf);
  const source = stepIndex(sequencer, old.source[0] ?? '');
  const place = after >= 0 ? after + 1 : source >= 0 ? source + 1 : sequencer.steps.length;
  next = { ...next, steps: insertAt(next.steps, place, step) };
  if (joins.length === 0) next = addTransition(next, newTransition(reserving(block, seq, [step]), [step.name], []));
  return { block: withSequencer(block, seq, next), select: stepItem(step.name) };
}

function exitFrom(block: GraphBlock, seq: number, from: GraphItem, target: string[], jump: boolean): Inserted {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer || from.kind !== 'step') return { block, select: from };
  const source = sequencer.steps[stepIndex(sequencer, from.name)];
  if (!source) return { block, select: from };
  const transition = newTransition(block, [source.name], target, jump);
  return { block: withSequencer(block, seq, addTransition(sequencer, transition)), select: transitionItem(transition.name) };
}

/** A jump from step `from` to step `to` (a new transition, the lowest priority). */
export function insertJump(block: GraphBlock, seq: number, from: GraphItem, to: string): Inserted {
  const target = allSteps(block).find((step) => sameName(step.name, to));
  if (!target) return { block, select: from };
  return exitFrom(block, seq, from, [target.name], true);
}

/** A sequence end (S7-Graph's branch stop) after step `from`: a new transition without target. */
export function insertSequenceEnd(block: GraphBlock, seq: number, from: GraphItem): Inserted {
  return exitFrom(block, seq, from, [], false);
}

/** A new sequencer at the end: an initial step and a sequence end. Selects the step. */
export function addSequencer(block: GraphBlock): Inserted {
  const step: Step = { ...newStep(block), initial: true };
  const sequencer: Sequencer = { name: newSequencerName(block), comment: '', steps: [step], transitions: [] };
  const withStep = { ...block, sequencers: [...block.sequencers, sequencer] };
  const transition = newTransition(withStep, [step.name], []);
  const seq = block.sequencers.length;
  return { block: withSequencer(withStep, seq, { ...sequencer, transitions: [transition] }), select: stepItem(step.name) };
}

// ---- delete and move --------------------------------------------------------------------------

function incoming(block: GraphBlock, name: string): Transition[] {
  return allTransitions(block).filter((t) => has(t.target, name));
}

/** Marks a step initial when the sequencer would otherwise lose its only initial step. */
function keepInitial(sequencer: Sequencer, removed: Step, successor: string | undefined): Sequencer {
  if (!removed.initial || sequencer.steps.some((step) => step.initial && step !== removed)) return sequencer;
  if (successor === undefined) return sequencer;
  return { ...sequencer, steps: sequencer.steps.map((step) => (sameName(step.name, successor) ? { ...step, initial: true } : step)) };
}

function deleteStep(block: GraphBlock, seq: number, sequencer: Sequencer, step: Step): Deleted | null {
  if (sequencer.steps.length <= 1) return null;
  const exits = sequencer.transitions.filter((t) => has(t.source, step.name));
  const entries = incoming(block, step.name);
  const only = exits.length === 1 ? exits[0] : undefined;
  if (only && only.source.length === 1 && !has(only.target, step.name) && !entries.includes(only)) {
    // The step goes with the transition below it; what led to it leads where that one led.
    let next = keepInitial(sequencer, step, only.target.find((name) => stepIndex(sequencer, name) >= 0));
    next = { ...next, steps: next.steps.filter((s) => s.name !== step.name), transitions: next.transitions.filter((t) => t !== only) };
    let result = withSequencer(block, seq, next);
    result = mapAllTransitions(result, (t) => {
      if (!has(t.target, step.name)) return t;
      const target = replaceName(t.target, step.name, only.target);
      return { ...t, target, jump: (t.jump || only.jump) && target.length === 1 };
    });
    const select = only.target[0] !== undefined ? stepItem(only.target[0]) : entries[0] ? transitionItem(entries[0].name) : null;
    return { block: result, select };
  }
  const entry = entries.length === 1 ? entries[0] : undefined;
  const above = entry && entry.source.length === 1 && entry.target.length === 1 ? entry.source[0] : undefined;
  if (exits.length > 1 && entry && above !== undefined && !step.initial && !sameName(above, step.name) && stepIndex(sequencer, above) >= 0) {
    // Several exits: the step goes with the transition above it, its exits leave from the step before.
    if (exits.some((t) => has(t.source, above) || has(t.target, step.name))) return null;
    let next: Sequencer = { ...sequencer, steps: sequencer.steps.filter((s) => s !== step), transitions: sequencer.transitions.filter((t) => t !== entry) };
    next = mapTransitions(next, (t) => (has(t.source, step.name) ? { ...t, source: replaceName(t.source, step.name, [above]) } : t));
    return { block: withSequencer(block, seq, next), select: stepItem(above) };
  }
  return null;
}

function deleteTransition(block: GraphBlock, seq: number, sequencer: Sequencer, transition: Transition): Deleted | null {
  const rest = allTransitions(block).filter((t) => t !== transition);
  const left = transition.source.every((name) => rest.some((t) => has(t.source, name)));
  const entered = transition.target.every((name) => {
    const step = allSteps(block).find((s) => sameName(s.name, name));
    return step?.initial === true || rest.some((t) => has(t.target, name));
  });
  if (left && entered) {
    const select = transition.source[0] !== undefined ? stepItem(transition.source[0]) : null;
    return { block: withSequencer(block, seq, { ...sequencer, transitions: sequencer.transitions.filter((t) => t !== transition) }), select };
  }
  // A link of a chain: it goes with the step below it, whose exits then leave from the step above.
  const above = transition.source.length === 1 ? transition.source[0] : undefined;
  const below = transition.target.length === 1 ? sequencer.steps[stepIndex(sequencer, transition.target[0] ?? '')] : undefined;
  if (above === undefined || !below || below.initial || sameName(above, below.name)) return null;
  if (incoming(block, below.name).length !== 1) return null;
  const exits = sequencer.transitions.filter((t) => t !== transition && has(t.source, below.name));
  if (exits.length === 0 && !rest.some((t) => has(t.source, above))) return null;
  if (exits.some((t) => has(t.source, above) || has(t.target, below.name))) return null;
  let next: Sequencer = {
    ...sequencer,
    steps: sequencer.steps.filter((s) => s !== below),
    transitions: sequencer.transitions.filter((t) => t !== transition),
  };
  next = mapTransitions(next, (t) => (has(t.source, below.name) ? { ...t, source: replaceName(t.source, below.name, [above]) } : t));
  return { block: withSequencer(block, seq, next), select: stepItem(above) };
}

/** Deletes a step or a transition keeping the chart connected; null when it cannot. */
export function deleteItem(block: GraphBlock, seq: number, item: GraphItem): Deleted | null {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer) return null;
  if (item.kind === 'step') {
    const step = sequencer.steps.find((s) => sameName(s.name, item.name));
    return step ? deleteStep(block, seq, sequencer, step) : null;
  }
  const transition = sequencer.transitions.find((t) => sameName(t.name, item.name));
  return transition ? deleteTransition(block, seq, sequencer, transition) : null;
}

/**
 * Moves an alternative branch one place left (-1, a higher priority) or right (+1) among the
 * transitions leaving the same step; null when there is no branch on that side.
 */
export function moveBranch(block: GraphBlock, seq: number, item: GraphItem, delta: -1 | 1): GraphBlock | null {
  const sequencer = sequencerOf(block, seq);
  if (!sequencer || item.kind !== 'transition') return null;
  const index = sequencer.transitions.findIndex((t) => sameName(t.name, item.name));
  const moved = sequencer.transitions[index];
  if (!moved) return null;
  const from = moved.source[0] ?? '';
  const siblings = sequencer.transitions.flatMap((t, k) => (sameName(t.source[0] ?? '', from) ? [k] : []));
  const other = siblings[siblings.indexOf(index) + delta];
  if (other === undefined) return null;
  const transitions = [...sequencer.transitions];
  transitions[index] = sequencer.transitions[other] as Transition;
  transitions[other] = moved;
  return withSequencer(block, seq, { ...sequencer, transitions });
}

// ---- references -------------------------------------------------------------------------------

function escape(text: string): string {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

/** Replaces the step/transition variables `old.<member>` in an operand by `now.<member>`. */
function variableRenamer(old: string, now: string): (text: string) => string {
  const pattern = new RegExp(`(?<![\\w#."])${escape(old)}(?=\\.[A-Za-z_])`, 'gi');
  const wanted = old.toUpperCase();
  return (text) => (text.length > wanted.length && text.toUpperCase().includes(wanted) ? text.replace(pattern, now) : text);
}

/** Every string of a LAD structure (operands, pin values), ids and kinds aside. */
function mapStrings<T>(value: T, change: (text: string) => string): T {
  if (typeof value === 'string') return change(value) as T;
  if (Array.isArray(value)) {
    let changed = false;
    const out = value.map((item: unknown) => {
      const next = mapStrings(item, change);
      changed ||= next !== item;
      return next;
    });
    return (changed ? out : value) as T;
  }
  if (value !== null && typeof value === 'object') {
    let changed = false;
    const out: Record<string, unknown> = {};
    for (const [key, item] of Object.entries(value as Record<string, unknown>)) {
      const next = key === 'id' || key === 'kind' ? item : mapStrings(item, change);
      changed ||= next !== item;
      out[key] = next;
    }
    return (changed ? out : value) as T;
  }
  return value;
}

function mapSeries(series: Series | null, change: (text: string) => string): Series | null {
  return series === null ? null : mapStrings(series, change);
}

/** Changes the operands of the whole block: conditions, actions, permanent networks. */
function mapOperands(block: GraphBlock, change: (text: string) => string, action: (a: Action) => Action): GraphBlock {
  const step = (s: Step): Step => {
    const interlock = mapSeries(s.interlock, change);
    const supervision = mapSeries(s.supervision, change);
    let changed = interlock !== s.interlock || supervision !== s.supervision;
    const actions = s.actions.map((a) => {
      const next = action(a);
      changed ||= next !== a;
      return next;
    });
    return changed ? { ...s, interlock, supervision, actions } : s;
  };
  const transition = (t: Transition): Transition => {
    const condition = mapSeries(t.condition, change);
    return condition === t.condition ? t : { ...t, condition };
  };
  const sequencers = block.sequencers.map((sequencer) => {
    const steps = sequencer.steps.map(step);
    const transitions = sequencer.transitions.map(transition);
    const same = steps.every((s, k) => s === sequencer.steps[k]) && transitions.every((t, k) => t === sequencer.transitions[k]);
    return same ? sequencer : { ...sequencer, steps, transitions };
  });
  const pre = mapStrings(block.pre, change);
  const post = mapStrings(block.post, change);
  const same = sequencers.every((s, k) => s === block.sequencers[k]) && pre === block.pre && post === block.post;
  return same ? block : { ...block, sequencers, pre, post };
}

function actionOperands(a: Action, change: (text: string) => string, stepOperand: (operand: string) => string): Action {
  const operand = a.qualifier === 'ON' || a.qualifier === 'OFF' ? stepOperand(a.operand) : change(a.operand);
  const time = a.time === null ? null : change(a.time);
  return operand === a.operand && time === a.time ? a : { ...a, operand, time };
}

/** Step references by number (`S3` in ON/OFF, `S3.X` in operands) mapped through `numbers`. */
function renumberReferences(block: GraphBlock, numbers: ReadonlyMap<number, number>): GraphBlock {
  if ([...numbers].every(([old, now]) => old === now)) return block;
  const named = usedNames(block);
  const byNumber = (word: string): string => {
    const found = /^S(\d+)$/i.exec(word);
    if (!found || named.has(word.toUpperCase())) return word;
    const now = numbers.get(Number(found[1]));
    return now === undefined ? word : `${word[0] ?? 'S'}${now}`;
  };
  const change = (text: string) => text.replace(/(?<![\w#."])S\d+(?=\.[A-Za-z_])/gi, byNumber);
  const stepOperand = (operand: string) => {
    const trimmed = operand.trim();
    const now = byNumber(trimmed);
    return now === trimmed ? operand : operand.replace(trimmed, now);
  };
  return mapOperands(block, change, (a) => actionOperands(a, change, stepOperand));
}

// ---- updates ----------------------------------------------------------------------------------

function mapStep(block: GraphBlock, name: string, change: (step: Step) => Step): GraphBlock {
  let changed = false;
  const sequencers = block.sequencers.map((sequencer) => {
    const index = sequencer.steps.findIndex((step) => step.name === name);
    const old = sequencer.steps[index];
    if (!old || changed) return sequencer;
    const next = change(old);
    if (next === old) return sequencer;
    changed = true;
    return { ...sequencer, steps: sequencer.steps.map((step, k) => (k === index ? next : step)) };
  });
  return changed ? { ...block, sequencers } : block;
}

function mapTransition(block: GraphBlock, name: string, change: (t: Transition) => Transition): GraphBlock {
  let changed = false;
  const sequencers = block.sequencers.map((sequencer) => {
    const index = sequencer.transitions.findIndex((t) => t.name === name);
    const old = sequencer.transitions[index];
    if (!old || changed) return sequencer;
    const next = change(old);
    if (next === old) return sequencer;
    changed = true;
    return { ...sequencer, transitions: sequencer.transitions.map((t, k) => (k === index ? next : t)) };
  });
  return changed ? { ...block, sequencers } : block;
}

/**
 * The step named `name` changed by `change` (actions, conditions, comment, initial mark). Its
 * name and number change through `renameStep`/`setStepNumber`, which update the references.
 */
export function updateStep(block: GraphBlock, name: string, change: (step: Step) => Step): GraphBlock {
  return mapStep(block, name, change);
}

/** The transition named `name` changed by `change` (its condition, comment). */
export function updateTransition(block: GraphBlock, name: string, change: (t: Transition) => Transition): GraphBlock {
  return mapTransition(block, name, change);
}

function nameFree(block: GraphBlock, name: string, now: string): boolean {
  return isValidName(now) && (sameName(name, now) || !usedNames(block).has(now.toUpperCase()));
}

/** Renames a step and every reference to it; null when the name is invalid or taken. */
export function renameStep(block: GraphBlock, name: string, now: string): GraphBlock | null {
  if (!allSteps(block).some((step) => step.name === name) || !nameFree(block, name, now)) return null;
  if (name === now) return block;
  let next = mapStep(block, name, (step) => ({ ...step, name: now }));
  next = mapAllTransitions(next, (t) =>
    has(t.source, name) || has(t.target, name) ? { ...t, source: replaceName(t.source, name, [now]), target: replaceName(t.target, name, [now]) } : t,
  );
  const change = variableRenamer(name, now);
  const stepOperand = (operand: string) => (sameName(operand.trim(), name) ? operand.replace(operand.trim(), now) : operand);
  return mapOperands(next, change, (a) => actionOperands(a, change, stepOperand));
}

/** Gives a step another number (unique in the FB); `S<n>` references follow. Null when refused. */
export function setStepNumber(block: GraphBlock, name: string, number: number): GraphBlock | null {
  const step = allSteps(block).find((s) => s.name === name);
  if (!step || !Number.isInteger(number) || number < 1) return null;
  if (step.number === number) return block;
  if (allSteps(block).some((s) => s.number === number)) return null;
  const next = mapStep(block, name, (s) => ({ ...s, number }));
  return renumberReferences(next, new Map([[step.number, number]]));
}

/** Renames a transition (and its `.TT` references); null when the name is invalid or taken. */
export function renameTransition(block: GraphBlock, name: string, now: string): GraphBlock | null {
  if (!allTransitions(block).some((t) => t.name === name) || !nameFree(block, name, now)) return null;
  if (name === now) return block;
  const next = mapTransition(block, name, (t) => ({ ...t, name: now }));
  const change = variableRenamer(name, now);
  return mapOperands(next, change, (a) => actionOperands(a, change, (operand) => operand));
}

/** Gives a transition another number (unique in the FB); null when refused. */
export function setTransitionNumber(block: GraphBlock, name: string, number: number): GraphBlock | null {
  const transition = allTransitions(block).find((t) => t.name === name);
  if (!transition || !Number.isInteger(number) || number < 1) return null;
  if (transition.number === number) return block;
  if (allTransitions(block).some((t) => t.number === number)) return null;
  return mapTransition(block, name, (t) => ({ ...t, number }));
}

/** Steps 1..n and transitions 1..n in chart order, sequencer after sequencer. */
export function renumber(block: GraphBlock): GraphBlock {
  const steps = new Map<Step, number>();
  const transitions = new Map<Transition, number>();
  for (const sequencer of block.sequencers) {
    for (const item of chartOrder(sequencer)) {
      if (item.kind === 'step') steps.set(item.step, steps.size + 1);
      else transitions.set(item.transition, transitions.size + 1);
    }
  }
  const numbers = new Map<number, number>();
  for (const [step, number] of steps) if (!numbers.has(step.number)) numbers.set(step.number, number);
  let changed = false;
  const sequencers = block.sequencers.map((sequencer) => {
    const nextSteps = sequencer.steps.map((step) => (steps.get(step) === step.number ? step : { ...step, number: steps.get(step) ?? step.number }));
    const nextTransitions = sequencer.transitions.map((t) => (transitions.get(t) === t.number ? t : { ...t, number: transitions.get(t) ?? t.number }));
    const same = nextSteps.every((s, k) => s === sequencer.steps[k]) && nextTransitions.every((t, k) => t === sequencer.transitions[k]);
    changed ||= !same;
    return same ? sequencer : { ...sequencer, steps: nextSteps, transitions: nextTransitions };
  });
  if (!changed) return block;
  return renumberReferences({ ...block, sequencers }, numbers);
}

export function setSettings(block: GraphBlock, settings: Settings): GraphBlock {
  return sameSettings(block.settings, settings) ? block : { ...block, settings };
}

export function setPermanent(block: GraphBlock, which: 'pre' | 'post', networks: Network[]): GraphBlock {
  return block[which] === networks ? block : { ...block, [which]: networks };
}
