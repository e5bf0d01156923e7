/**
 * Keyboard movement between the items of a drawn diagram: the arrow keys go to the nearest item
 * in that direction, measured on the drawing, so LAD rungs, FBD box networks and Graph charts
 * move the same way without knowing each other's structure.
 */

export type Direction = 'left' | 'right' | 'up' | 'down';

/** An item the selection can stand on, with its box in the drawing's coordinates. */
export interface NavItem<K> {
  key: K;
  x: number;
  y: number;
  width: number;
  height: number;
}

const ARROWS: Record<string, Direction> = {
  ArrowLeft: 'left',
  ArrowRight: 'right',
  ArrowUp: 'up',
  ArrowDown: 'down',
};

/** The direction of an arrow key, or null for any other key. */
export function arrowDirection(key: string): Direction | null {
  return ARROWS[key] ?? null;
}

function centre<K>(item: NavItem<K>): { x: number; y: number } {
  return { x: item.x + item.width / 2, y: item.y + item.height / 2 };
}

/**
 * The item to move to from `from` in `direction`, or null at the edge. Items straight ahead
 * win over items off to the side: the distance across the direction counts three times.
 */
export function nextInDirection<K>(items: readonly NavItem<K>[], from: NavItem<K>, direction: Direction): NavItem<K> | null {
  const here = centre(from);
  let best: NavItem<K> | null = null;
  let bestScore = Infinity;
  for (const item of items) {
    if (item.key === from.key) continue;
    const there = centre(item);
    const along = direction === 'left' ? here.x - there.x : direction === 'right' ? there.x - here.x : direction === 'up' ? here.y - there.y : there.y - here.y;
    const across = direction === 'left' || direction === 'right' ? Math.abs(there.y - here.y) : Math.abs(there.x - here.x);
    if (along <= 0.5) continue;
    const score = along + 3 * across;
    if (score < bestScore) {
      best = item;
      bestScore = score;
    }
  }
  return best;
}
