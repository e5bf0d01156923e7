import { useEffect, useState } from 'react';

type Listener = (tab: string) => void;

/**
 * Requests to bring a tab of the bottom panel forward, from outside the panel (a compile shows
 * the Diagnostics list). The panel keeps its own choice; a request only changes it.
 */
export interface PanelTabRequests {
  show: (tab: string) => void;
  subscribe: (listener: Listener) => () => void;
}

export function createPanelTabRequests(): PanelTabRequests {
  const listeners = new Set<Listener>();
  return {
    show: (tab) => listeners.forEach((listener) => listener(tab)),
    subscribe: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** The workbench's one bottom panel. */
export const panelTab = createPanelTabRequests();

/** The panel's shown tab: `initial` at first, then the user's choice or the last request. */
export function usePanelTab<T extends string>(
  initial: T,
  requests: PanelTabRequests = panelTab,
): [T, (tab: T) => void] {
  const [selected, setSelected] = useState<T>(initial);
  useEffect(() => requests.subscribe((tab) => setSelected(tab as T)), [requests]);
  return [selected, setSelected];
}
