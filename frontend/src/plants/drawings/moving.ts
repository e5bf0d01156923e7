import type { PlantFrame } from '../types';

export interface MovingItem {
  /** Where along the line (the model's unit, e.g. mm). */
  at: number;
  /** Its fill in % (0 when the model gives none). */
  fill: number;
}

/**
 * The moving items a plant's state lists in one string, as `"600:40,350:0"` (centre:fill) or
 * `"600,350"` (centres only): the state holds plain values only, so a list travels as text.
 */
export function itemsOf(plant: PlantFrame, key: string): MovingItem[] {
  const text = plant.state[key];
  if (typeof text !== 'string' || text.trim() === '') return [];
  const items: MovingItem[] = [];
  for (const part of text.split(',')) {
    const [at, fill] = part.split(':');
    const position = Number(at);
    if (at === undefined || at.trim() === '' || !Number.isFinite(position)) continue;
    const amount = Number(fill ?? 0);
    items.push({ at: position, fill: Number.isFinite(amount) ? amount : 0 });
  }
  return items;
}
