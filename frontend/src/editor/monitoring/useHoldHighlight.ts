import { useEffect } from 'react';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import { useMonitor, useSession } from '../../cpu/SessionContext';

/** The line the CPU holds at, when it is in this file: highlighted, with an arrow, in view. */
export function useHoldHighlight(editor: MonacoEditor.IStandaloneCodeEditor, projectId: number, file: string): number | null {
  const { session } = useSession();
  const hold = useMonitor((state) => state.hold);
  const location = hold?.location;
  const line = session?.projectId === projectId && location?.file === file && location.line ? location.line : null;

  useEffect(() => {
    if (line === null || !hold) return;
    const decorations = editor.createDecorationsCollection([
      {
        range: { startLineNumber: line, startColumn: 1, endLineNumber: line, endColumn: 1 },
        options: { isWholeLine: true, className: 'nasaq-hold-line', glyphMarginClassName: 'nasaq-hold-arrow' },
      },
    ]);
    editor.revealLineInCenterIfOutsideViewport(line);
    return () => decorations.clear();
    // A new hold (a step) on the same line shows it again.
  }, [editor, line, hold]);
  return line;
}
