import type { TFunction } from 'i18next';

/**
 * A problem's parameters in the interface language. The server sends a fixed phrase inside a
 * parameter (a reason, an action, a place) as the English text plus `<name>_key` and
 * `<name>_params` (backend `nasaq/diagnostics/phrases.py`): here each such parameter becomes
 * `phrases.<key>` translated with its own parameters (which may hold phrases in turn). A
 * `<name>_key` that names a catalogued problem instead (`problems.<key>`, e.g. the first compile
 * error of MON611) is translated too, after `<name>_prefix` (its place and code). A key this
 * catalogue lacks leaves the English text.
 */
export function translateParams(
  t: TFunction,
  exists: (key: string) => boolean,
  params: Readonly<Record<string, unknown>> | undefined,
): Record<string, unknown> {
  const out: Record<string, unknown> = { ...params };
  if (!params) return out;
  for (const [name, value] of Object.entries(params)) {
    if (!name.endsWith('_key') || typeof value !== 'string') continue;
    const base = name.slice(0, -'_key'.length);
    if (!(base in params)) continue;
    const nested = params[`${base}_params`];
    const inner = translateParams(t, exists, isRecord(nested) ? nested : undefined);
    if (exists(`phrases.${value}`)) {
      out[base] = t(`phrases.${value}`, inner);
    } else if (exists(`problems.${value}`)) {
      const prefix = params[`${base}_prefix`];
      const text = t(`problems.${value}`, inner);
      out[base] = typeof prefix === 'string' && prefix ? `${prefix} ${text}` : text;
    }
  }
  return out;
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}
