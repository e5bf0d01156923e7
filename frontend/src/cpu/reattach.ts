/**
 * A page attaching to a running session (a reload, a second tab, another browser) shows the
 * breakpoints the session holds: those its store lacks are added to it, so the editor's gutter
 * and the LAD/FBD networks mark them and the client sets them (the server answers with the ids
 * they already have). A breakpoint the store has, even disabled, is left as the user made it.
 */
import type { SessionBreakpoint } from '../api/monitorClient';
import type { BreakpointStore } from '../editor/monitoring/breakpointStore';
import { stepBreakpoints, type StepBreakpointStore } from '../graph/stepBreakpoints';

export function adoptSessionBreakpoints(
  store: Pick<BreakpointStore, 'find' | 'put'>,
  projectId: number,
  found: readonly SessionBreakpoint[],
  steps: Pick<StepBreakpointStore, 'add'> = stepBreakpoints,
): void {
  for (const bp of found) {
    const { location, condition } = bp;
    if (location.step) {
      // An S7-Graph step's activation (the Control Sequencer's breakpoint).
      steps.add({ projectId, block: location.block ?? bp.block, step: location.step });
    } else if (location.block && location.network && bp.file) {
      if (!store.find(projectId, bp.file, location.network, location.block)) {
        store.put(projectId, bp.file, location.network, { condition, enabled: true }, location.block);
      }
    } else if (location.file && location.line) {
      if (!store.find(projectId, location.file, location.line)) {
        store.put(projectId, location.file, location.line, { condition, enabled: true });
      }
    }
  }
}
