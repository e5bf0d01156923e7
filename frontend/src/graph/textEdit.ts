/**
 * The Graph editors write the `.graph` file by changing only what an edit changed: an edited
 * step or transition is printed again in place, a new one is printed next to the item it
 * follows in the chart, a deleted one is cut out (with the blank and comment lines just before
 * it), SETTINGS and PERMANENT_PRE/POST are printed again in place, a new sequencer is added after
 * the last one. Every other line (the file's header comment, comments between steps, hand-made
 * layout of the items not edited) stays byte for byte.
 *
 * Where the parts are is found by a small scanner over the current text (the server's `places`
 * belong to the last text the server read, and several edits are spliced without reading again).
 * It follows the structure words at the start of lines (FUNCTION_BLOCK, SETTINGS, BEGIN,
 * PERMANENT_PRE/POST, SEQUENCER, STEP/INITIAL_STEP/TRANSITION and their END_ words ending a
 * line). When what it finds does not match the model the text was read as (a layout it does not
 * follow, `(* *)` comments that may hide structure words), or an edit changes a block's header,
 * the affected block or the whole text is printed again: correct, only comments there are lost.
 */
import type { GraphBlock, Sequencer, Step, Transition } from './model';
import {
  blockLines,
  chartOrder,
  itemLines,
  permanentLines,
  printGraph,
  sameSettings,
  sequencerHeadLines,
  sequencerLines,
  settingsLines,
  type ChartItem,
} from './print';

/** Lines [start, end) of the text. */
export interface Span {
  start: number;
  end: number;
}

export interface ItemSpan extends Span {
  kind: 'step' | 'transition';
  name: string;
}

export interface SequencerSpan extends Span {
  name: string;
  /** After the SEQUENCER line and its COMMENT lines. */
  headEnd: number;
  items: ItemSpan[];
  /** The END_SEQUENCER line (`end` is the line after it). */
  endLine: number;
}

export interface BlockSpan extends Span {
  /** Where SETTINGS would be inserted: after the FUNCTION_BLOCK line and its TITLE/COMMENT lines. */
  settingsAt: number;
  settings: Span | null;
  begin: number;
  pre: Span | null;
  sequencers: SequencerSpan[];
  post: Span | null;
  /** The END_FUNCTION_BLOCK line (`end` is the line after it). */
  endLine: number;
}

const starts = (word: string) => new RegExp(`^\\s*${word}(?!\\w)`, 'i');
/** A line that ends with `word` (a `//` comment may follow). */
const ends = (word: string) => new RegExp(`(?:^|[\\s)"';])${word}\\s*(?://[^\\n]*)?$`, 'i');
const alone = (word: string) => new RegExp(`^\\s*${word}\\s*(?://[^\\n]*)?$`, 'i');

const BLOCK_START = starts('FUNCTION_BLOCK');
const BLOCK_END = alone('END_FUNCTION_BLOCK');
const TITLE_OR_COMMENT = starts('(?:TITLE|COMMENT)');
const SETTINGS_START = starts('SETTINGS');
const SETTINGS_END = ends('END_SETTINGS');
const BEGIN = alone('BEGIN');
const VAR = starts('VAR');
const PRE_START = starts('PERMANENT_PRE');
const PRE_END = ends('END_PERMANENT_PRE');
const POST_START = starts('PERMANENT_POST');
const POST_END = ends('END_PERMANENT_POST');
const SEQUENCER_START = /^\s*SEQUENCER\s+([A-Za-z_]\w*)\s*(?:\/\/[^\n]*)?$/i;
const SEQUENCER_END = alone('END_SEQUENCER');
const COMMENT = starts('COMMENT');
const ITEM_START = /^\s*(INITIAL_STEP|STEP|TRANSITION)\s+([A-Za-z_]\w*)/i;
const STEP_END = ends('END_STEP');
const TRANSITION_END = ends('END_TRANSITION');

/** The text's lines, and which of them hold only blanks or comments. */
interface Source {
  lines: readonly string[];
  trivia: readonly boolean[];
}

/**
 * The lines that hold only blanks or comments (`//`, or `(* *)` opening at a line's start and
 * closing at a line's end); null when a `(* *)` comment stands where it may hide structure words.
 */
function triviaLines(lines: readonly string[]): boolean[] | null {
  const trivia = new Array<boolean>(lines.length).fill(false);
  for (let k = 0; k < lines.length; k += 1) {
    const line = lines[k] ?? '';
    const trimmed = line.trim();
    if (trimmed.startsWith('(*')) {
      let close = k;
      while (close < lines.length && !(lines[close] ?? '').includes('*)')) close += 1;
      const closing = lines[close] ?? '';
      if (close >= lines.length || !/\*\)\s*$/.test(closing) || closing.indexOf('*)') !== closing.lastIndexOf('*)')) return null;
      if (line.indexOf('(*') !== line.lastIndexOf('(*')) return null;
      for (let j = k; j <= close; j += 1) trivia[j] = true;
      k = close;
      continue;
    }
    if (trimmed.includes('(*')) return null;
    trivia[k] = trimmed === '' || trimmed.startsWith('//');
  }
  return trivia;
}

function sectionEnd(src: Source, start: number, end: RegExp, stop: number): number | null {
  for (let k = start; k < stop; k += 1) {
    if (k > start && src.trivia[k] === true) continue;
    if (end.test(src.lines[k] ?? '')) return k + 1;
    if (k > start && (ITEM_START.test(src.lines[k] ?? '') || BLOCK_START.test(src.lines[k] ?? ''))) return null;
  }
  return null;
}

function scanSequencer(src: Source, start: number, stop: number): SequencerSpan | null {
  const head = SEQUENCER_START.exec(src.lines[start] ?? '');
  if (!head) return null;
  let k = start + 1;
  while (k < stop && COMMENT.test(src.lines[k] ?? '')) k += 1;
  const span: SequencerSpan = { name: head[1] ?? '', start, headEnd: k, items: [], endLine: -1, end: -1 };
  while (k < stop) {
    const line = src.lines[k] ?? '';
    if (src.trivia[k] === true) {
      k += 1;
      continue;
    }
    if (SEQUENCER_END.test(line)) {
      span.endLine = k;
      span.end = k + 1;
      return span;
    }
    const item = ITEM_START.exec(line);
    if (!item) return null;
    const kind = (item[1] ?? '').toUpperCase() === 'TRANSITION' ? 'transition' : 'step';
    const end = sectionEnd(src, k, kind === 'step' ? STEP_END : TRANSITION_END, stop);
    if (end === null) return null;
    span.items.push({ kind, name: item[2] ?? '', start: k, end });
    k = end;
  }
  return null;
}

function scanBlock(src: Source, start: number): BlockSpan | null {
  let k = start + 1;
  while (k < src.lines.length && TITLE_OR_COMMENT.test(src.lines[k] ?? '')) k += 1;
  const settingsAt = k;
  let settings: Span | null = null;
  let inDeclarations = false;
  for (; k < src.lines.length && !BEGIN.test(src.lines[k] ?? ''); k += 1) {
    const line = src.lines[k] ?? '';
    if (src.trivia[k] === true) continue;
    if (BLOCK_START.test(line) || SEQUENCER_START.test(line)) return null;
    if (VAR.test(line)) inDeclarations = true;
    if (!inDeclarations && SETTINGS_START.test(line)) {
      if (settings) return null;
      const end = sectionEnd(src, k, SETTINGS_END, src.lines.length);
      if (end === null) return null;
      settings = { start: k, end };
      k = end - 1;
    }
  }
  if (k >= src.lines.length) return null;
  const block: BlockSpan = {
    start,
    end: -1,
    settingsAt,
    settings,
    begin: k,
    pre: null,
    sequencers: [],
    post: null,
    endLine: -1,
  };
  k += 1;
  while (k < src.lines.length) {
    const line = src.lines[k] ?? '';
    if (src.trivia[k] === true) {
      k += 1;
    } else if (BLOCK_END.test(line)) {
      block.endLine = k;
      block.end = k + 1;
      return block;
    } else if (PRE_START.test(line) || POST_START.test(line)) {
      const pre = PRE_START.test(line);
      if (pre ? block.pre : block.post) return null;
      const end = sectionEnd(src, k, pre ? PRE_END : POST_END, src.lines.length);
      if (end === null) return null;
      if (pre) block.pre = { start: k, end };
      else block.post = { start: k, end };
      k = end;
    } else if (SEQUENCER_START.test(line)) {
      const sequencer = scanSequencer(src, k, src.lines.length);
      if (!sequencer) return null;
      block.sequencers.push(sequencer);
      k = sequencer.end;
    } else {
      return null;
    }
  }
  return null;
}

/** Whether the spans found are those of `block` as read (same parts, same names, same order). */
function matches(span: BlockSpan, block: GraphBlock): boolean {
  if ((block.pre.length > 0 && !span.pre) || (block.post.length > 0 && !span.post)) return false;
  if (span.sequencers.length !== block.sequencers.length) return false;
  return block.sequencers.every((sequencer, index) => {
    const found = span.sequencers[index];
    if (!found || found.name !== sequencer.name) return false;
    const steps = found.items.filter((item) => item.kind === 'step').map((item) => item.name);
    const transitions = found.items.filter((item) => item.kind === 'transition').map((item) => item.name);
    return same(steps, sequencer.steps.map((step) => step.name)) && same(transitions, sequencer.transitions.map((t) => t.name));
  });
}

function same(a: readonly string[], b: readonly string[]): boolean {
  return a.length === b.length && a.every((value, index) => value === b[index]);
}

/** The spans of each block of `text`, read as `blocks`; null when the scanner cannot follow it. */
export function scanText(text: string, blocks: readonly GraphBlock[]): BlockSpan[] | null {
  const lines = text.split('\n');
  const trivia = triviaLines(lines);
  if (!trivia) return null;
  const src: Source = { lines, trivia };
  const found: BlockSpan[] = [];
  let k = 0;
  while (k < lines.length) {
    if (!BLOCK_START.test(lines[k] ?? '')) {
      if (found.length > 0 && !trivia[k]) return null;
      k += 1;
      continue;
    }
    const block = scanBlock(src, k);
    if (!block) return null;
    found.push(block);
    k = block.end;
  }
  if (found.length !== blocks.length) return null;
  return found.every((span, index) => matches(span, blocks[index] as GraphBlock)) ? found : null;
}

interface Replacement {
  start: number;
  end: number;
  lines: string[];
}

type Item = Step | Transition;

/** An item of the new sequencer text: lines of the old text (a range) or printed lines. */
interface Piece {
  kind: 'step' | 'transition';
  name: string;
  item: Item;
  /** The blank and comment lines before it. */
  lead: Span | readonly string[];
  body: Span | readonly string[];
}

const NEW_LEAD: readonly string[] = [''];

function pushLines(out: string[], lines: readonly string[], part: Span | readonly string[]): void {
  if ('start' in part) {
    for (let k = part.start; k < part.end; k += 1) out.push(lines[k] ?? '');
  } else {
    for (const line of part) out.push(line);
  }
}

/**
 * The new lines of a sequencer whose steps or transitions changed; null when its items cannot be
 * placed keeping the model's order (the caller prints the sequencer again).
 */
function sequencerPieces(lines: readonly string[], span: SequencerSpan, before: Sequencer, after: Sequencer): string[] | null {
  const byIndex = before.steps.length === after.steps.length && before.transitions.length === after.transitions.length;
  const byName = new Map<string, Item>();
  if (!byIndex) {
    for (const step of after.steps) if (!byName.has(`s:${step.name}`)) byName.set(`s:${step.name}`, step);
    for (const t of after.transitions) if (!byName.has(`t:${t.name}`)) byName.set(`t:${t.name}`, t);
  }
  const counters = { step: 0, transition: 0 };
  const nextOf = (kind: 'step' | 'transition', name: string): Item | null => {
    const index = counters[kind]++;
    if (byIndex) return (kind === 'step' ? after.steps : after.transitions)[index] ?? null;
    return byName.get(`${kind === 'step' ? 's' : 't'}:${name}`) ?? null;
  };
  const previous = (kind: 'step' | 'transition', index: number): Item | undefined =>
    (kind === 'step' ? before.steps : before.transitions)[index];
  const kept = new Set<Item>();
  const pieces: Piece[] = [];
  // An item moved among its kind (a branch's priority) keeps its written lines.
  const written = new Map<Item, Span>();
  const counted = { step: 0, transition: 0 };
  for (const item of span.items) {
    const old = previous(item.kind, counted[item.kind]++);
    if (old) written.set(old, item);
  }
  let at = span.headEnd;
  for (const item of span.items) {
    const lead = { start: at, end: item.start };
    at = item.end;
    const next = nextOf(item.kind, item.name);
    if (!next) continue; // deleted, with its lead
    kept.add(next);
    const body = written.get(next) ?? itemLines(asChartItem(item.kind, next));
    pieces.push({ kind: item.kind, name: next.name, item: next, lead, body });
  }
  const tail = { start: at, end: span.endLine };
  // A new item goes between its neighbours of its kind (the reader keeps each kind's order),
  // as close after the item it follows in the chart as they allow.
  const order = chartOrder(after);
  const pieceOf = (item: Item) => pieces.findIndex((piece) => piece.item === item);
  order.forEach((entry, index) => {
    const item = entry.kind === 'step' ? entry.step : entry.transition;
    if (kept.has(item)) return;
    const list: readonly Item[] = entry.kind === 'step' ? after.steps : after.transitions;
    const at = list.indexOf(item);
    const before = at > 0 ? pieceOf(list[at - 1] as Item) : -1;
    let low = before + 1;
    let high = pieces.length;
    for (const later of list.slice(at + 1)) {
      const found = pieceOf(later);
      if (found >= 0) {
        high = found;
        break;
      }
    }
    if (low > high) low = high;
    let place = low;
    for (let back = index - 1; back >= 0; back -= 1) {
      const anchor = order[back] as ChartItem;
      const found = pieceOf(anchor.kind === 'step' ? anchor.step : anchor.transition);
      if (found >= 0) {
        place = Math.min(Math.max(found + 1, low), high);
        break;
      }
    }
    pieces.splice(place, 0, { kind: entry.kind, name: item.name, item, lead: NEW_LEAD, body: itemLines(entry) });
    kept.add(item);
  });
  const names = (kind: 'step' | 'transition') => pieces.filter((piece) => piece.kind === kind).map((piece) => piece.name);
  if (!same(names('step'), after.steps.map((s) => s.name)) || !same(names('transition'), after.transitions.map((t) => t.name))) {
    return null;
  }
  const out: string[] = [];
  pushLines(out, lines, before.name === after.name && before.comment === after.comment ? { start: span.start, end: span.headEnd } : sequencerHeadLines(after));
  for (const piece of pieces) {
    pushLines(out, lines, piece.lead);
    pushLines(out, lines, piece.body);
  }
  pushLines(out, lines, tail);
  out.push(lines[span.endLine] ?? 'END_SEQUENCER');
  return out;
}

function asChartItem(kind: 'step' | 'transition', item: Item): ChartItem {
  return kind === 'step' ? { kind: 'step', step: item as Step } : { kind: 'transition', transition: item as Transition };
}

function sameHeader(a: GraphBlock, b: GraphBlock): boolean {
  return a.name === b.name && a.title === b.title && a.comment === b.comment && a.declarations === b.declarations;
}

function blockReplacements(lines: readonly string[], span: BlockSpan, before: GraphBlock, after: GraphBlock): Replacement[] {
  const whole = [{ start: span.start, end: span.end, lines: blockLines(after) }];
  if (!sameHeader(before, after)) return whole;
  const out: Replacement[] = [];
  if (!sameSettings(before.settings, after.settings)) {
    const printed = settingsLines(after.settings);
    if (span.settings) out.push({ ...span.settings, lines: printed });
    else out.push({ start: span.settingsAt, end: span.settingsAt, lines: printed });
  }
  if (before.pre !== after.pre) {
    const printed = permanentLines('PRE', after.pre);
    if (span.pre) out.push({ ...span.pre, lines: printed });
    else out.push({ start: span.begin + 1, end: span.begin + 1, lines: printed });
  }
  const count = before.sequencers.length;
  if (after.sequencers.length < count) return whole;
  for (let index = 0; index < count; index += 1) {
    const old = before.sequencers[index] as Sequencer;
    const next = after.sequencers[index] as Sequencer;
    const found = span.sequencers[index] as SequencerSpan;
    if (old === next) continue;
    const printed = sequencerPieces(lines, found, old, next) ?? sequencerLines(next);
    out.push({ start: found.start, end: found.end, lines: printed });
  }
  if (after.sequencers.length > count) {
    const last = span.sequencers[span.sequencers.length - 1];
    const at = last ? last.end : span.pre ? span.pre.end : span.begin + 1;
    const added = after.sequencers.slice(count).flatMap((sequencer) => ['', ...sequencerLines(sequencer)]);
    out.push({ start: at, end: at, lines: added });
  }
  if (before.post !== after.post) {
    const printed = permanentLines('POST', after.post);
    if (span.post) {
      // The blank line the printer puts before the section goes with it.
      const blank = printed.length === 0 && span.post.start > 0 && (lines[span.post.start - 1] ?? '').trim() === '';
      out.push({ start: blank ? span.post.start - 1 : span.post.start, end: span.post.end, lines: printed });
    } else if (printed.length > 0) {
      out.push({ start: span.endLine, end: span.endLine, lines: ['', ...printed] });
    }
  }
  return out;
}

/**
 * The text of `after`, written into `text` (which reads as `before`) by changing only the lines
 * of the parts that changed; the whole text printed again when its structure cannot be followed.
 */
export function spliceText(text: string, before: readonly GraphBlock[], after: readonly GraphBlock[]): string {
  if (before === after) return text;
  if (before.length !== after.length) return printGraph(after);
  const spans = scanText(text, before);
  if (!spans) return printGraph(after);
  const lines = text.split('\n');
  const eol = text.includes('\r\n') ? '\r' : '';
  const replacements: Replacement[] = [];
  before.forEach((block, index) => {
    const next = after[index] as GraphBlock;
    if (block !== next) replacements.push(...blockReplacements(lines, spans[index] as BlockSpan, block, next));
  });
  // In order of their lines; at one line, insertions in the order made (settings before the
  // pre-instructions, which follow BEGIN).
  const ordered = replacements.map((replacement, order) => ({ replacement, order })).sort((a, b) => a.replacement.start - b.replacement.start || a.order - b.order);
  const out: string[] = [];
  let at = 0;
  for (const { replacement } of ordered) {
    for (; at < replacement.start; at += 1) out.push(lines[at] ?? '');
    for (const line of replacement.lines) out.push(eol && !line.endsWith('\r') ? line + eol : line);
    at = Math.max(at, replacement.end);
  }
  for (; at < lines.length; at += 1) out.push(lines[at] ?? '');
  return out.join('\n');
}
