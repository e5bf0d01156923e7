import { useEffect, useSyncExternalStore } from 'react';
import { useSession } from '../../cpu/SessionContext';
import { stepBreakpoints, stepRequestsFor, type StepBreakpointStore } from '../../graph/stepBreakpoints';
import { breakpoints as defaultStore, requestsFor, type BreakpointStore } from './breakpointStore';

/**
 * Keeps the session's breakpoints those of the store for the session's project: the client sets
 * them on the server, again after every reconnect and download. Mounted once (the debug panel).
 */
export function useBreakpointSync(store: BreakpointStore = defaultStore, steps: StepBreakpointStore = stepBreakpoints): void {
  const { session, client } = useSession();
  const list = useSyncExternalStore(store.subscribe, store.list, store.list);
  // S7-Graph step breakpoints (the Control Sequencer's) go with them.
  const stepList = useSyncExternalStore(steps.subscribe, steps.list, steps.list);
  const projectId = session?.projectId ?? null;
  useEffect(() => {
    if (client && projectId !== null) client.setBreakpoints([...requestsFor(list, projectId), ...stepRequestsFor(stepList, projectId)]);
  }, [client, projectId, list, stepList]);
}
