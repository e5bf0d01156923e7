/**
 * The text of `cpu.properties` (format: `backend/nasaq/workbench/cpu_properties.py`): `key = value`
 * lines, `#` comments. The page changes a file as a person would: only the value of the line that
 * sets a key is replaced (its comment stays), a key not in the file is appended, and every other
 * line (comments, lines the page does not understand) is kept as it is.
 */

export const CPU_PROPERTIES_FILE = 'cpu.properties';

export const PROPERTY_KEYS = [
  'profile',
  'cycle_monitoring_time',
  'cycle_time',
  'clock_memory',
  'retentive_markers',
  'retentive_timers',
  'retentive_counters',
  'startup',
] as const;
export type PropertyKey = (typeof PROPERTY_KEYS)[number];

/** The values the server read from the text (`POST /api/cpu-properties/check`). */
export interface CpuProperties {
  profile: 'S7-300' | 'S7-400' | 'S7-1500';
  cycle_monitoring_time: number;
  cycle_time: number;
  clock_memory: number | null;
  retentive_markers: number;
  retentive_timers: number;
  retentive_counters: number;
  startup: 'warm' | 'cold';
}

/** What a new project's file holds: the defaults of an S7-300, each said once. */
export const DEFAULT_TEXT = `# Nasaq CPU properties (STEP 7: HW Config, Properties - CPU)
profile = S7-300
cycle_monitoring_time = 150
cycle_time = 10
clock_memory = none
retentive_markers = 16
retentive_timers = 0
retentive_counters = 8
startup = warm
`;

// indent, key, separator (one space after it at most: the rest is the value's), value, comment
const LINE = /^(\s*)([A-Za-z_][A-Za-z0-9_]*)([ \t]*[=:][ \t]?)([^#]*?)([ \t]*(?:#.*)?)$/;

/** The line (0-based) that sets `key`, or -1. */
export function lineOf(text: string, key: PropertyKey): number {
  return text.split('\n').findIndex((line) => LINE.exec(line)?.[2]?.toLowerCase() === key);
}

/** `text` with `key` set to `value` (written as the file writes it). */
export function setProperty(text: string, key: PropertyKey, value: string): string {
  const lines = text.split('\n');
  const index = lineOf(text, key);
  if (index >= 0) {
    const match = LINE.exec(lines[index] ?? '');
    if (match) {
      const [, indent, name, separator, , rest] = match;
      const comment = value !== '' && rest?.startsWith('#') ? ` ${rest}` : rest;
      lines[index] = `${indent}${name}${separator}${value}${comment}`;
      return lines.join('\n');
    }
  }
  const body = text === '' || text.endsWith('\n') ? text : `${text}\n`;
  return `${body}${key} = ${value}\n`;
}

/** How the file writes a value the page holds. */
export function propertyText(key: PropertyKey, value: CpuProperties[PropertyKey]): string {
  if (key === 'clock_memory') return value === null ? 'none' : `MB${value}`;
  return String(value);
}
