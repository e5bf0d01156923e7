/** `POST /api/cpu-properties/check` (backend `nasaq.api.cpu_properties`): what a text means. */
import { request } from '../api/client';
import type { Diagnostic } from '../api/types';
import type { CpuProperties } from './format';

export interface PropertiesCheck {
  /** The values the CPU would run with; a key on a bad line keeps its default. */
  properties: CpuProperties;
  diagnostics: Diagnostic[];
}

export function checkProperties(text: string, signal?: AbortSignal): Promise<PropertiesCheck> {
  return request<PropertiesCheck>('/api/cpu-properties/check', {
    method: 'POST',
    body: JSON.stringify({ text }),
    signal: signal ?? null,
  });
}
