/**
 * A project's `<kind>.plant` file: the plant's PlantConfig as YAML (backend/nasaq/plants/runtime.py).
 * The browser writes it in block style, one item a line, so it diffs well; it reads what it wrote
 * and what a lesson writes (block or flow maps `{start: I0.0}`, lists `[a, b]` or `- a`).
 * Anything else is refused with the line, never guessed.
 */
import type { PlantConfig } from './types';

export const PLANT_SUFFIX = '.plant';

export function isPlantFile(name: string): boolean {
  return name.toLowerCase().endsWith(PLANT_SUFFIX) && name.length > PLANT_SUFFIX.length;
}

/** The file name for a plant of `kind`. */
export function plantFileName(kind: string): string {
  return `${kind}${PLANT_SUFFIX}`;
}

const PLAIN = /^[A-Za-z0-9_.#%-]+$/;

function scalar(value: string | number): string {
  if (typeof value === 'number') return String(value);
  return PLAIN.test(value) && !/^(true|false|yes|no|on|off|null|~)$/i.test(value) && !/^[-\d.]/.test(value)
    ? value
    : JSON.stringify(value);
}

/** The file's text for `config`: kind, wiring, params, faults (empty parts left out). */
export function writePlantFile(config: PlantConfig): string {
  const lines = [`kind: ${scalar(config.kind)}`];
  const wiring = Object.entries(config.wiring).filter(([, address]) => address.trim() !== '');
  if (wiring.length > 0) {
    lines.push('wiring:');
    for (const [name, address] of wiring) lines.push(`  ${scalar(name)}: ${scalar(address.trim())}`);
  }
  const params = Object.entries(config.params);
  if (params.length > 0) {
    lines.push('params:');
    for (const [name, value] of params) lines.push(`  ${scalar(name)}: ${scalar(value)}`);
  }
  if (config.faults.length > 0) {
    lines.push('faults:');
    for (const fault of config.faults) lines.push(`  - ${scalar(fault)}`);
  }
  return `${lines.join('\n')}\n`;
}

export class PlantFileError extends Error {
  constructor(
    readonly line: number,
    message: string,
  ) {
    super(`line ${line}: ${message}`);
    this.name = 'PlantFileError';
  }
}

function unquote(text: string): string {
  const trimmed = text.trim();
  if (trimmed.startsWith('"') && trimmed.endsWith('"') && trimmed.length >= 2) return JSON.parse(trimmed) as string;
  if (trimmed.startsWith("'") && trimmed.endsWith("'") && trimmed.length >= 2) return trimmed.slice(1, -1).replace(/''/g, "'");
  return trimmed;
}

function withoutComment(line: string): string {
  let quote: string | null = null;
  for (let i = 0; i < line.length; i += 1) {
    const char = line[i];
    if (quote) {
      if (char === quote) quote = null;
    } else if (char === '"' || char === "'") quote = char;
    else if (char === '#' && (i === 0 || /\s/.test(line[i - 1] ?? ''))) return line.slice(0, i);
  }
  return line;
}

function splitFlow(body: string): string[] {
  return body
    .split(',')
    .map((part) => part.trim())
    .filter((part) => part !== '');
}

function flowMap(text: string, line: number): Record<string, string> {
  const body = text.trim();
  if (!body.startsWith('{') || !body.endsWith('}')) throw new PlantFileError(line, 'expected a map');
  const map: Record<string, string> = {};
  for (const part of splitFlow(body.slice(1, -1))) {
    const colon = part.indexOf(':');
    if (colon <= 0) throw new PlantFileError(line, `"${part}" is not "name: value"`);
    map[unquote(part.slice(0, colon))] = unquote(part.slice(colon + 1));
  }
  return map;
}

function flowList(text: string, line: number): string[] {
  const body = text.trim();
  if (!body.startsWith('[') || !body.endsWith(']')) throw new PlantFileError(line, 'expected a list');
  return splitFlow(body.slice(1, -1)).map(unquote);
}

function numberOf(text: string, line: number, name: string): number {
  const value = Number(text);
  if (text.trim() === '' || !Number.isFinite(value)) throw new PlantFileError(line, `parameter ${name} is not a number`);
  return value;
}

/** Reads a plant file; a shape it does not know raises {@link PlantFileError} with the line. */
export function readPlantFile(text: string): PlantConfig {
  const config: PlantConfig = { kind: '', wiring: {}, params: {}, faults: [] };
  let section: 'wiring' | 'params' | 'faults' | null = null;
  const rows = text.split(/\r?\n/);
  rows.forEach((raw, index) => {
    const number = index + 1;
    const line = withoutComment(raw).replace(/\s+$/, '');
    if (line.trim() === '') return;
    const indented = /^\s/.test(line);
    const item = line.trim();
    // A list may start at the key's own indentation (`faults:` then `- code`), as PyYAML writes it.
    if (!indented && section === 'faults' && item.startsWith('-')) {
      config.faults.push(unquote(item.slice(1)));
      return;
    }
    if (!indented) {
      const colon = item.indexOf(':');
      if (colon <= 0) throw new PlantFileError(number, `"${item}" is not "name: value"`);
      const key = item.slice(0, colon).trim();
      const rest = item.slice(colon + 1).trim();
      section = null;
      if (key === 'kind') config.kind = unquote(rest);
      else if (key === 'wiring' || key === 'params') {
        if (rest === '') section = key;
        else {
          const map = flowMap(rest, number);
          if (key === 'wiring') config.wiring = map;
          else config.params = Object.fromEntries(Object.entries(map).map(([k, v]) => [k, numberOf(v, number, k)]));
        }
      } else if (key === 'faults') {
        if (rest === '') section = 'faults';
        else config.faults = flowList(rest, number);
      } else throw new PlantFileError(number, `unknown key "${key}"`);
      return;
    }
    if (section === null) throw new PlantFileError(number, 'indented line outside wiring, params or faults');
    if (section === 'faults') {
      if (!item.startsWith('-')) throw new PlantFileError(number, 'expected "- fault"');
      config.faults.push(unquote(item.slice(1)));
      return;
    }
    const colon = item.indexOf(':');
    if (colon <= 0) throw new PlantFileError(number, `"${item}" is not "name: value"`);
    const key = unquote(item.slice(0, colon));
    const value = unquote(item.slice(colon + 1));
    if (section === 'wiring') config.wiring[key] = value;
    else config.params[key] = numberOf(value, number, key);
  });
  if (config.kind === '') throw new PlantFileError(1, 'the plant has no kind');
  return config;
}
