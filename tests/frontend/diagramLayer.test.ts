/**
 * The diagram layer every graphical editor stands on (frontend/src/diagram/): the undo history,
 * arrow-key movement between drawn items, the power-flow states.
 */
import { describe, expect, it } from 'vitest';
import { nextInDirection, arrowDirection, type NavItem } from '../../frontend/src/diagram/navigation';
import { andFlow, flowClass, flowState } from '../../frontend/src/diagram/powerFlow';
import { UndoHistory } from '../../frontend/src/diagram/undo';

describe('UndoHistory', () => {
  it('undoes and redoes whole states, and a new edit drops what was undone', () => {
    const history = new UndoHistory<string>('a');
    history.push('b', 'first');
    history.push('c', 'second');
    expect(history.undoLabel).toBe('second');
    expect(history.undo()).toBe('b');
    expect(history.undo()).toBe('a');
    expect(history.undo()).toBeNull();
    expect(history.redo()).toBe('b');
    expect(history.redoLabel).toBe('second');
    history.push('d', 'third');
    expect(history.canRedo).toBe(false);
    expect(history.state).toBe('d');
  });

  it('ignores an edit that changed nothing and keeps at most its depth', () => {
    const history = new UndoHistory<number>(0, 3);
    history.push(0, 'nothing');
    expect(history.canUndo).toBe(false);
    for (let k = 1; k <= 5; k += 1) history.push(k, `step ${k}`);
    const seen: number[] = [];
    for (let value = history.undo(); value !== null; value = history.undo()) seen.push(value);
    expect(seen).toEqual([4, 3, 2]);
  });
});

describe('arrow keys', () => {
  const item = (key: string, x: number, y: number): NavItem<string> => ({ key, x, y, width: 100, height: 70 });
  const rung = [item('a', 0, 0), item('b', 100, 0), item('c', 200, 0), item('branch', 100, 70), item('coil', 400, 0)];

  it('go to the nearest item in that direction, straight ahead first', () => {
    expect(nextInDirection(rung, rung[0]!, 'right')?.key).toBe('b');
    expect(nextInDirection(rung, rung[1]!, 'down')?.key).toBe('branch');
    expect(nextInDirection(rung, rung[3]!, 'up')?.key).toBe('b');
    expect(nextInDirection(rung, rung[3]!, 'right')?.key).toBe('c');
    expect(nextInDirection(rung, rung[4]!, 'right')).toBeNull();
    expect(arrowDirection('ArrowLeft')).toBe('left');
    expect(arrowDirection('Enter')).toBeNull();
  });
});

describe('power flow', () => {
  it('has a class and a state for on, off, not processed and offline', () => {
    expect([1, 0, null, undefined].map((flow) => flowState(flow as 0 | 1 | null | undefined))).toEqual(['on', 'off', 'none', 'offline']);
    expect(flowClass(1)).toBe('pf-on');
    expect(flowClass(undefined)).toBe('');
    expect(andFlow(1, 0)).toBe(0);
    expect(andFlow(1, null)).toBeNull();
  });
});
