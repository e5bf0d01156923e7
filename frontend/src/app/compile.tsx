import { createContext, useCallback, useContext, useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import type { Diagnostic } from '../api/types';
import { problemOf, useSession } from '../cpu/SessionContext';
import { flushFile } from '../editor/autosave';
import { panelTab } from '../panels/panelTab';
import { useActiveProject } from '../projects/ActiveProject';
import { projectContents, type ProjectContentsStore } from '../projects/projectContents';
import { isCommandKey } from './shortcuts';

/** What a compile found; `failed` when the server could not check the project at all. */
export type CompileResult = { errors: number; warnings: number; failed: false } | { failed: true; code: string };

export interface CompileValue {
  compiling: boolean;
  result: CompileResult | null;
  /** Saves the open editors' changes, checks the whole project and shows its diagnostics. */
  compile: () => Promise<void>;
}

const CompileContext = createContext<CompileValue>({ compiling: false, result: null, compile: async () => undefined });

export function countProblems(diagnostics: readonly Diagnostic[]): { errors: number; warnings: number } {
  let errors = 0;
  let warnings = 0;
  for (const diagnostic of diagnostics) {
    if (diagnostic.severity === 'error') errors += 1;
    else if (diagnostic.severity === 'warning') warnings += 1;
  }
  return { errors, warnings };
}

interface CompileProviderProps {
  children: ReactNode;
  store?: ProjectContentsStore;
}

/**
 * "Compile" of the active project, as STEP 7's Ctrl+F7 / TIA Portal's compile: the server
 * compiles the saved files, so unsaved editor text is saved first; then the project's block
 * tree and diagnostics are read again (`/blocks`) and the Diagnostics panel comes forward.
 */
export function CompileProvider({ children, store = projectContents }: CompileProviderProps) {
  const { projectId } = useActiveProject();
  const { report } = useSession();
  const [compiling, setCompiling] = useState(false);
  const [result, setResult] = useState<CompileResult | null>(null);
  const busy = useRef(false);

  const compile = useCallback(async () => {
    if (projectId === null || busy.current) return;
    busy.current = true;
    setCompiling(true);
    setResult(null);
    try {
      await flushFile(projectId).catch(() => undefined);
      await store.reload(projectId);
      const contents = store.get(projectId);
      panelTab.show('diagnostics');
      if (contents?.status === 'error' && contents.error) {
        report(problemOf(contents.error));
        setResult({ failed: true, code: contents.error.code });
      } else {
        setResult({ ...countProblems(contents?.diagnostics ?? []), failed: false });
      }
    } finally {
      busy.current = false;
      setCompiling(false);
    }
  }, [projectId, store, report]);

  // Another project, another result.
  useEffect(() => setResult(null), [projectId]);

  // Ctrl+F7 (Cmd+F7 on a Mac) compiles, wherever the focus is.
  useEffect(() => {
    const onKey = (event: KeyboardEvent) => {
      if (!isCommandKey(event, 'F7')) return;
      event.preventDefault();
      void compile();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [compile]);

  const value = useMemo(() => ({ compiling, result, compile }), [compiling, result, compile]);
  return <CompileContext.Provider value={value}>{children}</CompileContext.Provider>;
}

export function useCompile(): CompileValue {
  return useContext(CompileContext);
}
