/**
 * The plant part of the session's frames: a frame brings the plant when it changed, a frame
 * without one keeps the last, and a download that took the plant away clears it.
 */
import { describe, expect, it } from 'vitest';
import { initialMonitorState, mergeFrame } from '../../../frontend/src/api/monitorClient';
import { frame } from '../monitorFakes';
import { tankFrame } from './plantFixtures';

describe('the plant in the frames', () => {
  it('keeps the newest plant until a download removes it', () => {
    let state = initialMonitorState();
    expect(state.plant).toBeNull();
    state = mergeFrame(state, frame({ seq: 1, plant: tankFrame(10) }));
    expect(state.plant?.state.level).toBe(10);
    state = mergeFrame(state, frame({ seq: 2, plant: tankFrame(12) }));
    expect(state.plant?.state.level).toBe(12);
    const unchanged = mergeFrame(state, frame({ seq: 3 }));
    expect(unchanged.plant).toBe(state.plant);
    const removed = mergeFrame(unchanged, frame({ seq: 4, plant_removed: true }));
    expect(removed.plant).toBeNull();
  });
});
