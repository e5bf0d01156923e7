/**
 * The graphical editors write the `.lad`/`.fbd` file by changing only what the edit changed: a
 * network that was edited is printed again in place, a new one is printed where it was inserted,
 * a deleted one is cut out, and every other line (the user's `//` comments between networks, the
 * layout of networks written by hand, the file's header comment) stays as it was. So opening a
 * hand-written file, adding a contact and saving changes exactly that network's lines.
 *
 * The text is cut into spans by a small scanner that knows the file's structure words
 * (block headers, BEGIN, NETWORK, END_RUNG/END_STL, the block's end, comments). When the spans
 * do not match the model (a file the scanner reads differently from the parser), the whole text
 * is printed again: correct, only the comments are lost.
 */
import type { LadBlock, Network } from './model';
import { printLad } from './print';

interface NetworkSpan {
  /** Lines before the network's NETWORK line (blank lines, comments). */
  lead: string[];
  body: string[];
}

interface BlockSpan {
  /** Lines before the block's header. */
  lead: string[];
  /** From the header line up to and including BEGIN. */
  header: string[];
  networks: NetworkSpan[];
  /** Lines after the last network, before the block's end line. */
  tail: string[];
  end: string;
}

interface TextSpans {
  blocks: BlockSpan[];
  /** Lines after the last block (the final newline makes the last one empty). */
  after: string[];
}

/** A block's header line (the file's structure words, shared with the placing of problems). */
export const BLOCK_START = /^\s*(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)(?!\w)/i;
const BLOCK_END = /^\s*END_(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)(?!\w)/i;
const BEGIN = /^\s*BEGIN(?!\w)/i;
const NETWORK = /^\s*NETWORK(?!\w)/i;
const STL_START = /^\s*STL(?!\w)/i;
const STL_END = /^\s*END_STL(?!\w)/i;
const RUNG_END = /^\s*END_RUNG(?!\w)\s*(\/\/.*)?$/i;

/** Whether a line only holds a comment or nothing (it may belong to the gap between networks). */
function isTrivia(line: string): boolean {
  const trimmed = line.trim();
  return trimmed === '' || trimmed.startsWith('//');
}

/** The spans of a LAD text, or null when it has a structure the scanner does not follow. */
export function splitText(text: string): TextSpans | null {
  const lines = text.split('\n');
  const blocks: BlockSpan[] = [];
  let pending: string[] = [];
  let k = 0;
  const hasBlockComment = (line: string) => line.includes('(*');
  while (k < lines.length) {
    const line = lines[k] ?? '';
    if (hasBlockComment(line)) return null; // (* *) may hide structure words: print in full
    if (!BLOCK_START.test(line)) {
      pending.push(line);
      k += 1;
      continue;
    }
    const header: string[] = [];
    while (k < lines.length && !BEGIN.test(lines[k] ?? '')) {
      if (hasBlockComment(lines[k] ?? '') || NETWORK.test(lines[k] ?? '')) return null;
      header.push(lines[k] ?? '');
      k += 1;
    }
    if (k >= lines.length) return null;
    header.push(lines[k] ?? '');
    k += 1;
    const block: BlockSpan = { lead: pending, header, networks: [], tail: [], end: '' };
    pending = [];
    let gap: string[] = [];
    for (;;) {
      const current = lines[k];
      if (current === undefined) return null;
      if (hasBlockComment(current)) return null;
      if (BLOCK_END.test(current)) {
        block.tail = gap;
        block.end = current;
        k += 1;
        break;
      }
      if (!NETWORK.test(current)) {
        if (!isTrivia(current)) return null;
        gap.push(current);
        k += 1;
        continue;
      }
      const body: string[] = [current];
      k += 1;
      let closed = false;
      while (k < lines.length && !closed) {
        const item = lines[k] ?? '';
        if (hasBlockComment(item) || NETWORK.test(item) || BLOCK_END.test(item)) return null;
        body.push(item);
        k += 1;
        if (STL_START.test(item)) {
          while (k < lines.length && !STL_END.test(lines[k] ?? '')) {
            body.push(lines[k] ?? '');
            k += 1;
          }
          if (k >= lines.length) return null;
          body.push(lines[k] ?? '');
          k += 1;
          closed = true;
        } else if (RUNG_END.test(item)) {
          closed = true;
        }
      }
      if (!closed) return null;
      block.networks.push({ lead: gap, body });
      gap = [];
    }
    blocks.push(block);
  }
  return { blocks, after: pending };
}

/** The printed lines of one block's header (up to BEGIN) and of each network. */
function printedBlock(block: LadBlock, networks: readonly Network[]): { header: string[]; networks: string[][] } {
  const header = printLad([{ ...block, networks: [] }]).split('\n');
  const begin = header.findIndex((line) => BEGIN.test(line));
  const printed = networks.map((network) => {
    const lines = printLad([{ ...block, networks: [network] }]).split('\n');
    const start = lines.findIndex((line) => NETWORK.test(line));
    const end = lines.findIndex((line) => BLOCK_END.test(line));
    return lines.slice(start, end);
  });
  return { header: header.slice(0, begin + 1), networks: printed };
}

function sameHeader(a: LadBlock, b: LadBlock): boolean {
  return (
    a.language === b.language &&
    a.kind === b.kind &&
    a.name === b.name &&
    a.return_type === b.return_type &&
    a.title === b.title &&
    a.declarations === b.declarations
  );
}

/**
 * The text for `next`, made from `text` (which holds `previous`) by changing only the lines of
 * what changed: networks are matched by identity (an edit leaves untouched networks the same
 * objects), blocks by position.
 */
export function spliceText(text: string, previous: readonly LadBlock[], next: readonly LadBlock[]): string {
  const spans = splitText(text);
  if (
    !spans ||
    spans.blocks.length !== previous.length ||
    spans.blocks.some((span, k) => span.networks.length !== (previous[k]?.networks.length ?? -1)) ||
    previous.length !== next.length
  ) {
    return printLad([...next]);
  }
  const out: string[] = [];
  next.forEach((block, b) => {
    const span = spans.blocks[b] as BlockSpan;
    const before = previous[b] as LadBlock;
    out.push(...span.lead);
    const available = new Map<Network, NetworkSpan>();
    before.networks.forEach((network, k) => {
      const networkSpan = span.networks[k];
      if (networkSpan && !available.has(network)) available.set(network, networkSpan);
    });
    // Each old span is used once; a network that appears again (or is new) is printed.
    const reused = block.networks.map((network) => {
      const old = available.get(network);
      if (old) available.delete(network);
      return old ?? null;
    });
    const printed = printedBlock(
      block,
      block.networks.filter((_, k) => reused[k] === null),
    );
    out.push(...(sameHeader(before, block) ? span.header : printed.header));
    // A network edited in place keeps the comment lines above it (the lead of the old one at
    // its position, if that one was not kept elsewhere).
    const keptSpans = new Set(reused.filter((old): old is NetworkSpan => old !== null));
    let freshIndex = 0;
    reused.forEach((old, k) => {
      if (old) {
        out.push(...old.lead, ...old.body);
        return;
      }
      const replaced = span.networks[k];
      if (replaced && !keptSpans.has(replaced)) {
        keptSpans.add(replaced);
        out.push(...replaced.lead);
      }
      out.push(...(printed.networks[freshIndex] ?? []));
      freshIndex += 1;
    });
    out.push(...span.tail, span.end);
  });
  out.push(...spans.after);
  return out.join('\n');
}
