import { createContext, useCallback, useContext, useMemo, useState, type ReactNode } from 'react';

/** What an editor tab shows. Block editors (STL, SCL, LAD/FBD, Graph) join this list later. */
export type EditorTabKind = 'start';

export interface EditorTab {
  id: string;
  kind: EditorTabKind;
}

interface EditorTabsValue {
  tabs: readonly EditorTab[];
  activeId: string | null;
  activate: (id: string) => void;
  close: (id: string) => void;
  /** Opens the Start page, or brings it to the front if it is already open. */
  openStart: () => void;
}

const START_TAB: EditorTab = { id: 'start', kind: 'start' };

const EditorTabsContext = createContext<EditorTabsValue | null>(null);

/** The open editor tabs, shared by the editor area and the menus that open tabs. */
export function EditorTabsProvider({ children }: { children: ReactNode }) {
  const [tabs, setTabs] = useState<readonly EditorTab[]>([START_TAB]);
  const [activeId, setActiveId] = useState<string | null>(START_TAB.id);

  const activate = useCallback((id: string) => setActiveId(id), []);

  const close = useCallback(
    (id: string) => {
      const index = tabs.findIndex((tab) => tab.id === id);
      if (index < 0) return;
      const remaining = tabs.filter((tab) => tab.id !== id);
      setTabs(remaining);
      if (activeId === id) {
        const neighbour = remaining[Math.min(index, remaining.length - 1)];
        setActiveId(neighbour ? neighbour.id : null);
      }
    },
    [tabs, activeId],
  );

  const openStart = useCallback(() => {
    setTabs((current) => (current.some((tab) => tab.id === START_TAB.id) ? current : [START_TAB, ...current]));
    setActiveId(START_TAB.id);
  }, []);

  const value = useMemo(
    () => ({ tabs, activeId, activate, close, openStart }),
    [tabs, activeId, activate, close, openStart],
  );
  return <EditorTabsContext.Provider value={value}>{children}</EditorTabsContext.Provider>;
}

export function useEditorTabs(): EditorTabsValue {
  const value = useContext(EditorTabsContext);
  if (!value) throw new Error('useEditorTabs needs an <EditorTabsProvider> above it');
  return value;
}
