import { useCallback } from 'react';
import type { Diagnostic } from '../api/types';
import { useActiveProject } from '../projects/ActiveProject';
import { useProjectContents } from '../projects/projectContents';
import { useOpenProjectFile } from './useOpenProjectFile';

const NONE: readonly Diagnostic[] = [];

/**
 * The compiler's diagnostics of the active project (the one selected in the tree): of its saved
 * files, and of the unsaved text of each open editor tab as it is typed. For the Diagnostics
 * panel; the list stays empty while no project is active.
 */
export function useProjectDiagnostics(): readonly Diagnostic[] {
  const { projectId } = useActiveProject();
  return useProjectContents(projectId)?.diagnostics ?? NONE;
}

/**
 * Opens the file of a diagnostic of the active project at its line and column (for a click or
 * Enter on a row of the Diagnostics panel). False when the diagnostic has no file to open.
 */
export function useOpenDiagnostic(): (diagnostic: Diagnostic) => boolean {
  const { projectId } = useActiveProject();
  const openFile = useOpenProjectFile();
  return useCallback(
    (diagnostic: Diagnostic) => {
      const span = diagnostic.span;
      if (projectId === null || !span?.file) return false;
      const at = span.line != null ? { line: span.line, column: span.column ?? 1 } : null;
      openFile(projectId, span.file, at).catch(() => undefined);
      return true;
    },
    [projectId, openFile],
  );
}
