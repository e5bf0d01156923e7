import { useEffect, useSyncExternalStore } from 'react';
import { useSession } from '../../cpu/SessionContext';
import { breakpoints as defaultStore, requestsFor, type BreakpointStore } from './breakpointStore';

/**
 * Keeps the session's breakpoints those of the store for the session's project: the client sets
 * them on the server, again after every reconnect and download. Mounted once (the debug panel).
 */
export function useBreakpointSync(store: BreakpointStore = defaultStore): void {
  const { session, client } = useSession();
  const list = useSyncExternalStore(store.subscribe, store.list, store.list);
  const projectId = session?.projectId ?? null;
  useEffect(() => {
    if (client && projectId !== null) client.setBreakpoints(requestsFor(list, projectId));
  }, [client, projectId, list]);
}
