/** How the pane words a lesson's progress and a check's values. */
import type { Progress, ProgressStatus, Texts } from './api';

/** A progress to show: none yet reads as "not started". */
export function statusOf(progress: Progress | null | undefined): ProgressStatus {
  return progress?.status ?? 'not_started';
}

/** `0:42`, `12:05`, `1:02:09`: time spent in a lesson, as a clock shows it. */
export function clock(seconds: number): string {
  const total = Math.max(0, Math.round(seconds));
  const h = Math.floor(total / 3600);
  const m = Math.floor((total % 3600) / 60);
  const s = total % 60;
  const two = (n: number) => String(n).padStart(2, '0');
  return h > 0 ? `${h}:${two(m)}:${two(s)}` : `${m}:${two(s)}`;
}

/** A text in `language`, else English, else whichever the lesson has. */
export function pick(texts: Texts | null | undefined, language: string): string {
  if (!texts) return '';
  return texts[language] ?? texts.en ?? Object.values(texts).find((text) => typeof text === 'string') ?? '';
}

/** A value a check expected or found, as a PLC programmer reads it (`1`, `-407`, `{min: 10, max: 20}` → `10 … 20`). */
export function valueText(value: unknown): string {
  if (value === null || value === undefined) return '—';
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (typeof value === 'number' || typeof value === 'string') return String(value);
  if (Array.isArray(value)) return value.length === 0 ? '[]' : value.map(valueText).join(', ');
  if (typeof value === 'object') {
    const range = value as { min?: unknown; max?: unknown };
    if ('min' in range || 'max' in range) return `${range.min !== undefined ? valueText(range.min) : ''} … ${range.max !== undefined ? valueText(range.max) : ''}`.trim();
    return JSON.stringify(value);
  }
  return String(value);
}

/** `2.35 s`, `120 ms`: a virtual time of a scenario. */
export function virtualTime(ms: number): string {
  return ms >= 1000 ? `${(ms / 1000).toFixed(ms % 1000 === 0 ? 0 : 2)} s` : `${ms} ms`;
}
