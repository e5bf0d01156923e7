import type { TreeBlock } from '../../api/types';

/** The blocks the CPU executes, whose status can be monitored. */
const CODE_KINDS = new Set(['OB', 'FB', 'FC']);

/** The name the monitoring protocol knows a block by: `OB1`, `FC10`. */
export function blockName(block: Pick<TreeBlock, 'kind' | 'number'>): string {
  return `${block.kind}${block.number}`;
}

/** `FC 10`, `fc10` and `FC10` all name the same block. */
export function sameBlockName(a: string, b: string): boolean {
  return a.replace(/\s+/g, '').toUpperCase() === b.replace(/\s+/g, '').toUpperCase();
}

/** The code blocks defined in `file`, by their header line. */
export function codeBlocksOf(blocks: readonly TreeBlock[], file: string): TreeBlock[] {
  return blocks
    .filter((block) => block.file === file && block.line != null && CODE_KINDS.has(block.kind))
    .sort((a, b) => (a.line ?? 0) - (b.line ?? 0));
}

/**
 * The code block of `file` that `line` belongs to: the last block header at or above it. A line
 * above every header (a comment at the top of the file) belongs to the first block.
 */
export function blockAtLine(blocks: readonly TreeBlock[], file: string, line: number): TreeBlock | null {
  const ordered = codeBlocksOf(blocks, file);
  let found: TreeBlock | null = ordered[0] ?? null;
  for (const block of ordered) {
    if ((block.line ?? 0) <= line) found = block;
    else break;
  }
  return found;
}

/**
 * The block to monitor: the caret's while the caret is in view, otherwise the one the first
 * visible line belongs to (the user scrolled away from the caret).
 */
export function blockToMonitor(
  blocks: readonly TreeBlock[],
  file: string,
  caretLine: number,
  visible: { first: number; last: number } | null,
): TreeBlock | null {
  if (!visible || (caretLine >= visible.first && caretLine <= visible.last)) return blockAtLine(blocks, file, caretLine);
  return blockAtLine(blocks, file, visible.first);
}
