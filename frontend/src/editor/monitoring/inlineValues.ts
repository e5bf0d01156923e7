/**
 * SCL monitoring: after each executed line, the values its code read or wrote
 * (`Level = 42.5  Pump = TRUE`), shown by the editor as muted text after the line.
 */
import type { BlockStatus } from '../../api/monitor';

type Value = boolean | number | string | null;

/** A value as SCL writes it: TRUE/FALSE, numbers without float noise, strings quoted. */
export function formatValue(value: Value): string {
  if (value === null) return '?';
  if (typeof value === 'boolean') return value ? 'TRUE' : 'FALSE';
  if (typeof value === 'number') {
    if (Number.isInteger(value)) return String(value);
    if (!Number.isFinite(value)) return String(value);
    return String(Number.parseFloat(value.toPrecision(7)));
  }
  return `'${value}'`;
}

/** The text after one line: its variables in name order, two spaces apart. */
export function inlineText(values: Readonly<Record<string, Value>>): string {
  return Object.keys(values)
    .sort((a, b) => a.localeCompare(b))
    .map((name) => `${name} = ${formatValue(values[name] ?? null)}`)
    .join('  ');
}

/** The text after each executed line of an SCL block status, by line. */
export function inlineTexts(block: BlockStatus | null): Map<number, string> {
  const texts = new Map<number, string>();
  if (!block || block.language !== 'scl') return texts;
  for (const status of block.lines) {
    const text = inlineText(status.values);
    if (text !== '') texts.set(status.line, text);
  }
  return texts;
}

/** Only the lines from `first` to `last`: the editor decorates what is in view. */
export function visibleTexts(texts: ReadonlyMap<number, string>, first: number, last: number): Array<[number, string]> {
  return [...texts].filter(([line]) => line >= first && line <= last).sort((a, b) => a[0] - b[0]);
}
