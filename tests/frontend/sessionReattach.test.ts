/**
 * A page attaching to a running session shows the breakpoints the session holds: those its
 * breakpoint store lacks are added (STL/SCL lines and LAD/FBD networks), those it has are left
 * as the user made them (a disabled one stays disabled). The hold the server sends again after
 * each command of the attaching page stays one object while it does not change.
 */
import { describe, expect, it } from 'vitest';
import type { HoldState } from '../../frontend/src/api/monitor';
import { initialMonitorState, mergeFrame } from '../../frontend/src/api/monitorClient';
import { adoptSessionBreakpoints } from '../../frontend/src/cpu/reattach';
import { createBreakpointStore } from '../../frontend/src/editor/monitoring/breakpointStore';

describe('adopting the session breakpoints', () => {
  it('adds the lines and networks the store lacks and keeps the ones it has', () => {
    const store = createBreakpointStore(null);
    store.put(4, 'Scale.scl', 17, { enabled: false });
    adoptSessionBreakpoints(store, 4, [
      { id: 1, location: { file: 'Scale.scl', line: 17 }, condition: null, block: 'FC1', file: 'Scale.scl' },
      { id: 2, location: { file: 'Main.awl', line: 9 }, condition: 'MW10 > 5', block: 'OB1', file: 'Main.awl' },
      { id: 3, location: { block: 'FC 2', network: 3 }, condition: null, block: 'FC2', file: 'Motor.lad' },
    ]);
    expect(store.list()).toEqual([
      { projectId: 4, file: 'Main.awl', line: 9, condition: 'MW10 > 5', enabled: true },
      { projectId: 4, file: 'Motor.lad', line: 3, block: 'FC 2', condition: null, enabled: true },
      { projectId: 4, file: 'Scale.scl', line: 17, condition: null, enabled: false },
    ]);
  });
});

describe('the hold sent again at attach', () => {
  it('keeps the same object while the hold is unchanged, a new one when it changes', () => {
    const hold = {
      reason: 'breakpoint',
      breakpoint: 1,
      location: { block: 'OB1', instruction: 6, line: 19, file: 'OB1.awl', network: 1 },
      registers: {},
      locals: [],
      call_stack: [],
    } as unknown as HoldState;
    const first = mergeFrame(initialMonitorState(), { type: 'frame', seq: 1, cpu: null, watch: null, block: null, trend: null, hold, released: false, diagnostics: null, plant: null, plant_removed: false });
    const again = mergeFrame(first, { type: 'frame', seq: 2, cpu: null, watch: null, block: null, trend: null, hold: { ...hold }, released: false, diagnostics: null, plant: null, plant_removed: false });
    expect(again.hold).toBe(first.hold);
    const moved = { ...hold, breakpoint: 2 } as HoldState;
    const next = mergeFrame(again, { type: 'frame', seq: 3, cpu: null, watch: null, block: null, trend: null, hold: moved, released: false, diagnostics: null, plant: null, plant_removed: false });
    expect(next.hold).toBe(moved);
  });
});
