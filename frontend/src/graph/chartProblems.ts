/**
 * The checker's findings (GRA2xx) on the chart: each finding's line, looked up in the places the
 * reader gave (`S3`, `S3/A1`, `T2` ... with their lines, per block), names the step or transition
 * it is about, whose box is marked with the finding as its tooltip.
 */
import type { Diagnostic } from '../api/types';

/** `S<number>` or `T<number>`: what the chart marks. */
export type ItemKey = `S${number}` | `T${number}`;

/** The findings of block `block`, by the step or transition they concern. */
export function problemsByItem(problems: readonly Diagnostic[], places: readonly Record<string, number>[], block: number): Map<ItemKey, Diagnostic[]> {
  const found = new Map<ItemKey, Diagnostic[]>();
  const here = places[block];
  if (!here) return found;
  const start = here.BLOCK ?? 0;
  const next = places[block + 1]?.BLOCK ?? Infinity;
  const lines = Object.entries(here).sort((a, b) => a[1] - b[1]);
  for (const problem of problems) {
    const line = problem.span?.line;
    if (!line || line < start || line >= next) continue;
    let place: string | null = null;
    for (const [key, at] of lines) {
      if (at > line) break;
      place = key;
    }
    const item = place ? /^([ST]\d+)(?:\/|$)/.exec(place)?.[1] : undefined;
    if (!item) continue;
    const key = item as ItemKey;
    found.set(key, [...(found.get(key) ?? []), problem]);
  }
  return found;
}
