/**
 * Which addresses a signal may be wired to, as the backend's `wires_of` checks them
 * (backend/nasaq/plants/runtime.py): sensors and controls to inputs (I/E bits, IW/PIW words),
 * actuators to outputs or markers (Q/A/M bits, QW/PQW/MW words). The dialog says so at once; the
 * download checks it again.
 */
import type { PlantSignalInfo } from './types';

const INPUT_BIT = /^[IE]\s*\d+\.[0-7]$/;
const INPUT_WORD = /^P?[IE]\s*W\s*\d+$/;
const OUTPUT_BIT = /^[QAM]\s*\d+\.[0-7]$/;
const OUTPUT_WORD = /^(P?[QA]|M)\s*W\s*\d+$/;

export type WireProblem = 'input' | 'output' | 'bit' | 'word' | null;

/** The address as it is saved: trimmed, upper case, no inner spaces. */
export function normalAddress(text: string): string {
  return text.trim().toUpperCase().replace(/\s+/g, '');
}

/** Why `text` cannot be this signal's address, or null (an empty text: not connected). */
export function wireProblem(signal: Pick<PlantSignalInfo, 'direction' | 'kind'>, text: string): WireProblem {
  const address = normalAddress(text);
  if (address === '') return null;
  const input = signal.direction !== 'actuator';
  const bit = signal.kind === 'bool';
  const ok = input ? (bit ? INPUT_BIT : INPUT_WORD) : bit ? OUTPUT_BIT : OUTPUT_WORD;
  if (ok.test(address)) return null;
  const wrongSide = input ? OUTPUT_BIT.test(address) || OUTPUT_WORD.test(address) : INPUT_BIT.test(address) || INPUT_WORD.test(address);
  if (wrongSide) return input ? 'input' : 'output';
  return bit ? 'bit' : 'word';
}
