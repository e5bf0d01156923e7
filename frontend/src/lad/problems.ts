/**
 * The compiler's diagnostics of a LAD/FBD file placed where the editor shows them: on an element
 * (the diagnostic's span names it), on a network (its number in the block), or on a block. The
 * block is the one whose header line comes last before the diagnostic's line.
 */
import type { Diagnostic } from '../api/types';
import type { RungProblem } from './LadRung';
import { BLOCK_START } from './textEdit';

export interface Problems {
  block: Map<number, RungProblem[]>;
  networks: Map<string, { network: RungProblem[]; elements: Map<string, RungProblem[]>; elementCount: number }>;
}

/** The 1-based lines where the file's blocks start. */
export function blockLines(text: string): number[] {
  const starts: number[] = [];
  text.split('\n').forEach((line, k) => {
    if (BLOCK_START.test(line)) starts.push(k + 1);
  });
  return starts;
}

/** The file's diagnostics placed on blocks (by their line), networks and elements. */
export function problemsByNetwork(diagnostics: readonly Diagnostic[], file: string | null, blockStarts: readonly number[], message: (d: Diagnostic) => string): Problems {
  const out: Problems = { block: new Map(), networks: new Map() };
  if (!file) return out;
  const own = diagnostics.filter((d) => d.span?.file === file && d.severity !== 'info');
  if (own.length === 0) return out;
  for (const diagnostic of own) {
    const span = diagnostic.span;
    const problem: RungProblem = { code: diagnostic.code, message: message(diagnostic), severity: diagnostic.severity };
    const line = span?.line ?? 1;
    let b = 0;
    blockStarts.forEach((start, k) => {
      if (start <= line) b = k;
    });
    const network = span?.network ?? null;
    if (network === null) {
      const list = out.block.get(b) ?? [];
      list.push(problem);
      out.block.set(b, list);
      continue;
    }
    const key = `${b}:${network - 1}`;
    const entry = out.networks.get(key) ?? { network: [] as RungProblem[], elements: new Map<string, RungProblem[]>(), elementCount: 0 };
    const element = span?.element ?? null;
    if (element) {
      const list = entry.elements.get(element) ?? [];
      list.push(problem);
      entry.elements.set(element, list);
      entry.elementCount += 1;
    } else entry.network.push(problem);
    out.networks.set(key, entry);
  }
  return out;
}
