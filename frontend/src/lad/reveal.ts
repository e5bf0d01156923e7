/**
 * Where a place asked for by line (a diagnostic, a cross-reference, a lesson check's failing
 * expectation) sits in a LAD/FBD file's blocks: the block whose header comes last before the
 * line, and the network (given, 1-based in its block, or the one whose NETWORK line comes last
 * before the line). The editor selects it, as the text editor puts its caret on the line.
 */
import { BLOCK_START } from './textEdit';

const NETWORK = /^\s*NETWORK(?!\w)/i;

export interface DiagramPlace {
  /** 0-based block and network of the editor's model. */
  block: number;
  network: number;
}

export function placeOfLine(text: string, line: number, network?: number | null): DiagramPlace {
  let block = -1;
  let counted = -1;
  text.split('\n').forEach((content, k) => {
    if (k + 1 > line) return;
    if (BLOCK_START.test(content)) {
      block += 1;
      counted = -1;
    } else if (NETWORK.test(content)) counted += 1;
  });
  return { block: Math.max(0, block), network: network != null && network > 0 ? network - 1 : Math.max(0, counted) };
}
