/**
 * Writes Graph blocks in the `.graph` text format the server reads. A port of
 * backend/nasaq/lang/graph/text_print.py whose output is byte for byte the same (held by
 * tests/frontend/graphDocParity.test.ts against tests/frontend/fixtures/graph-parity.json), so
 * the editor saves what the server would write.
 *
 * The layout is canonical: per sequencer the steps in their order, each followed by the
 * transitions that leave it, never reordering `transitions` (the reader keeps the file's order).
 * Conditions and permanent networks are written by the LAD printer, one element a line; ids
 * equal to their reading-order number are left out. The per-item functions are what
 * `textEdit.ts` splices into a hand-written file.
 */
import { networkLines, oneLine, rstrip, seriesLines, strip } from '../lad/print';
import type { Action, GraphBlock, Network, Sequencer, Series, Settings, Step, Transition } from './model';

const INDENT = '  ';

export const DEFAULT_SETTINGS: Settings = {
  parameters: 'STANDARD',
  skip_steps: false,
  acknowledge_required: true,
  interlock_blocks: false,
};

function commentLines(text: string): string[] {
  return text ? text.split('\n').map((line) => rstrip(`COMMENT = ${line}`)) : [];
}

function names(list: readonly string[]): string {
  return list.length === 1 ? (list[0] ?? '') : `(${list.join(', ')})`;
}

/** One action row (without indentation); `number` is its 1-based place in the step. */
export function actionLine(action: Action, number: number): string {
  const parts: string[] = action.event ? [action.event] : [];
  parts.push(action.qualifier + (action.interlock ? 'C' : ''));
  parts.push(action.operand);
  let line = parts.join(' ');
  if (action.time !== null) line += `, ${action.time}`;
  if (action.id && action.id !== `a${number}`) line += ` @${action.id}`;
  line += ';';
  if (action.comment) line += `  // ${oneLine(action.comment)}`;
  return line;
}

function condition(opener: string, series: Series | null): string[] {
  if (series === null) return [];
  if (series.elements.length === 0) return [`${opener} END_${opener}`];
  return [opener, ...seriesLines(series, 1), `END_${opener}`];
}

export function stepLines(step: Step): string[] {
  const keyword = step.initial ? 'INITIAL_STEP' : 'STEP';
  const lines = [`${keyword} ${step.name} (${step.number})`, ...commentLines(step.comment)];
  lines.push(...condition('INTERLOCK', step.interlock));
  lines.push(...condition('SUPERVISION', step.supervision));
  if (step.actions.length > 0) {
    lines.push('ACTIONS');
    step.actions.forEach((action, index) => lines.push(INDENT + actionLine(action, index + 1)));
    lines.push('END_ACTIONS');
  }
  lines.push('END_STEP');
  return lines;
}

export function transitionLines(transition: Transition): string[] {
  let head = `TRANSITION ${transition.name} (${transition.number}) FROM ${names(transition.source)}`;
  if (transition.target.length === 0) head += ' STOP';
  else head += ` ${transition.jump ? 'JUMP' : 'TO'} ${names(transition.target)}`;
  const lines = [head, ...commentLines(transition.comment)];
  lines.push(...condition('CONDITION', transition.condition));
  lines.push('END_TRANSITION');
  return lines;
}

export type ChartItem = { kind: 'step'; step: Step } | { kind: 'transition'; transition: Transition };

/**
 * Steps and transitions interleaved: after each step, the transitions that follow in
 * `transitions` order as long as their first source is a step already written (or no step of
 * the sequencer); whatever is left comes last.
 */
export function chartOrder(sequencer: Sequencer): ChartItem[] {
  const known = new Set(sequencer.steps.map((step) => step.name));
  const written = new Set<string>();
  const pending = sequencer.transitions;
  const order: ChartItem[] = [];
  let index = 0;
  for (const step of sequencer.steps) {
    order.push({ kind: 'step', step });
    written.add(step.name);
    for (;;) {
      const next = pending[index];
      if (next === undefined) break;
      const first = next.source[0] ?? '';
      if (!written.has(first) && known.has(first)) break;
      order.push({ kind: 'transition', transition: next });
      index += 1;
    }
  }
  for (const transition of pending.slice(index)) order.push({ kind: 'transition', transition });
  return order;
}

export function itemLines(item: ChartItem): string[] {
  return item.kind === 'step' ? stepLines(item.step) : transitionLines(item.transition);
}

/** The sequencer's first lines: its name and comment. */
export function sequencerHeadLines(sequencer: Sequencer): string[] {
  return [`SEQUENCER ${sequencer.name}`, ...commentLines(sequencer.comment)];
}

export function sequencerLines(sequencer: Sequencer): string[] {
  const lines = sequencerHeadLines(sequencer);
  for (const item of chartOrder(sequencer)) lines.push('', ...itemLines(item));
  lines.push('', 'END_SEQUENCER');
  return lines;
}

export function sameSettings(a: Settings, b: Settings): boolean {
  return (
    a.parameters === b.parameters &&
    a.skip_steps === b.skip_steps &&
    a.acknowledge_required === b.acknowledge_required &&
    a.interlock_blocks === b.interlock_blocks
  );
}

/** The SETTINGS section; none for the default settings. */
export function settingsLines(settings: Settings): string[] {
  if (sameSettings(settings, DEFAULT_SETTINGS)) return [];
  const flag = (value: boolean) => (value ? 'TRUE' : 'FALSE');
  return [
    'SETTINGS',
    `${INDENT}PARAMETERS := ${settings.parameters};`,
    `${INDENT}SKIP_STEPS := ${flag(settings.skip_steps)};`,
    `${INDENT}ACKNOWLEDGE := ${flag(settings.acknowledge_required)};`,
    `${INDENT}INTERLOCK_BLOCKS := ${flag(settings.interlock_blocks)};`,
    'END_SETTINGS',
  ];
}

/** PERMANENT_PRE/POST with its networks; nothing when there are none. */
export function permanentLines(kind: 'PRE' | 'POST', networks: readonly Network[]): string[] {
  if (networks.length === 0) return [];
  const lines = [`PERMANENT_${kind}`];
  for (const network of networks) lines.push(...networkLines(network));
  lines.push(`END_PERMANENT_${kind}`);
  return lines;
}

/** The block's header: FUNCTION_BLOCK, title, comment, settings, declarations (up to BEGIN, excluded). */
export function headerLines(block: GraphBlock): string[] {
  const lines = [`FUNCTION_BLOCK ${block.name}`];
  if (block.title) lines.push(`TITLE = ${oneLine(block.title)}`);
  lines.push(...commentLines(block.comment));
  lines.push(...settingsLines(block.settings));
  if (strip(block.declarations)) lines.push(rstrip(block.declarations));
  return lines;
}

export function blockLines(block: GraphBlock): string[] {
  const lines = headerLines(block);
  lines.push('BEGIN');
  lines.push(...permanentLines('PRE', block.pre));
  for (const sequencer of block.sequencers) lines.push('', ...sequencerLines(sequencer));
  if (block.post.length > 0) lines.push('', ...permanentLines('POST', block.post));
  lines.push('END_FUNCTION_BLOCK');
  return lines;
}

/** The text of `blocks`, one blank line between blocks, ending with a newline. */
export function printGraph(blocks: readonly GraphBlock[]): string {
  return blocks.map((block) => `${blockLines(block).join('\n')}\n`).join('\n');
}
