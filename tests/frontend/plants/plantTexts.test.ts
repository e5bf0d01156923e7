/**
 * Every plant the backend defines is named in the four languages: its kind, each signal (the
 * drawing's labels and the operator panel's buttons) and each fault (the red message). Read from
 * the plant modules themselves, so a new signal without its texts fails here, not in a classroom.
 */
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import ar from '../../../frontend/src/plants/locales/ar.json';
import en from '../../../frontend/src/plants/locales/en.json';
import fa from '../../../frontend/src/plants/locales/fa.json';
import vi from '../../../frontend/src/plants/locales/vi.json';
import { DRAWINGS } from '../../../frontend/src/plants/drawings';

const folder = path.resolve(__dirname, '../../../backend/nasaq/plants');
const NOT_PLANTS = new Set(['__init__.py', 'base.py', 'registry.py', 'runtime.py', 'wiring.py', 'plant_file.py']);

interface Declared {
  kind: string;
  signals: string[];
  faults: string[];
}

function declared(): Declared[] {
  return readdirSync(folder)
    .filter((name) => name.endsWith('.py') && !NOT_PLANTS.has(name) && !name.startsWith('_'))
    .map((name) => readFileSync(path.join(folder, name), 'utf8'))
    .map((text) => ({
      kind: /^\s+kind\s*=\s*"(\w+)"/m.exec(text)?.[1] ?? '',
      signals: [...text.matchAll(/Signal\(\s*"(\w+)"/g)].map((match) => match[1]!),
      faults: [...text.matchAll(/Fault\(\s*"(\w+)"/g)].map((match) => match[1]!),
    }))
    .filter((plant) => plant.kind !== '');
}

/** S1, H3: named as on the wiring diagram, the same in every language (no text needed). */
const DIAGRAM_NAME = /^[a-z]\d$/;

const CATALOGUES = { en: en.plants, ar: ar.plants, fa: fa.plants, vi: vi.plants } as const;

describe('the plant texts', () => {
  const plants = declared();

  it('finds the plants of the course', () => {
    expect(plants.map((plant) => plant.kind)).toEqual(expect.arrayContaining(['tank', 'motor', 'bottle_conveyor', 'traffic_light', 'car_park', 'drill', 'mixer']));
    for (const plant of plants) expect(plant.signals.length, plant.kind).toBeGreaterThan(0);
  });

  it.each(Object.keys(CATALOGUES) as Array<keyof typeof CATALOGUES>)('names every kind, signal and fault in %s', (language) => {
    const texts = CATALOGUES[language] as { kind: Record<string, string>; signal: Record<string, string>; fault: Record<string, string> };
    const missing: string[] = [];
    for (const plant of plants) {
      if (!texts.kind[plant.kind]?.trim()) missing.push(`kind.${plant.kind}`);
      for (const signal of plant.signals) if (!DIAGRAM_NAME.test(signal) && !texts.signal[signal]?.trim()) missing.push(`${plant.kind}: signal.${signal}`);
      for (const fault of plant.faults) if (!texts.fault[fault]?.trim()) missing.push(`${plant.kind}: fault.${fault}`);
    }
    expect(missing).toEqual([]);
  });

  it('has a drawing of its own for every plant', () => {
    expect(plants.map((plant) => plant.kind).filter((kind) => !(kind in DRAWINGS))).toEqual([]);
  });
});
