import { createContext, useContext, useMemo, useState, type ReactNode } from 'react';

/**
 * The project the workbench works on: the one last selected in the project tree. The editor
 * opens its files, the CPU panel downloads it. Null until the user picks one.
 */
export interface ActiveProject {
  projectId: number | null;
  setProjectId: (id: number | null) => void;
}

const ActiveProjectContext = createContext<ActiveProject>({
  projectId: null,
  setProjectId: () => undefined,
});

export function ActiveProjectProvider({ children }: { children: ReactNode }) {
  const [projectId, setProjectId] = useState<number | null>(null);
  const value = useMemo(() => ({ projectId, setProjectId }), [projectId]);
  return <ActiveProjectContext.Provider value={value}>{children}</ActiveProjectContext.Provider>;
}

export function useActiveProject(): ActiveProject {
  return useContext(ActiveProjectContext);
}
