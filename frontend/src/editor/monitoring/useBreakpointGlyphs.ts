import { useEffect, useMemo, useRef, useSyncExternalStore } from 'react';
import { useTranslation } from 'react-i18next';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { BreakpointReport } from '../../api/monitorClient';
import { useMonitor } from '../../cpu/SessionContext';
import { useProblemText } from '../../cpu/useProblemText';
import type { MonacoApi } from '../monaco/load';
import { breakpoints as defaultStore, keyOf, type Breakpoint, type BreakpointStore } from './breakpointStore';

/** The glyph's classes: red dot, hollow with a marker when conditional, grey when refused or off. */
export function glyphClass(bp: Breakpoint, report: BreakpointReport | undefined): string {
  const classes = ['nasaq-bp'];
  if (bp.condition) classes.push('nasaq-bp--conditional');
  if (!bp.enabled) classes.push('nasaq-bp--disabled');
  else if (report?.state === 'refused') classes.push('nasaq-bp--refused');
  return classes.join(' ');
}

/** The breakpoints of one file, read from the store. */
export function useFileBreakpoints(projectId: number, file: string, store: BreakpointStore = defaultStore): readonly Breakpoint[] {
  const all = useSyncExternalStore(store.subscribe, store.list, store.list);
  return useMemo(() => all.filter((bp) => bp.projectId === projectId && bp.file === file), [all, projectId, file]);
}

interface GlyphOptions {
  editor: MonacoEditor.IStandaloneCodeEditor;
  monaco: MonacoApi;
  projectId: number;
  file: string;
  /** Opens the condition dialog for a line. */
  onEditCondition: (line: number) => void;
  store?: BreakpointStore;
}

/**
 * Breakpoints in the glyph margin: a click toggles one, a right-click edits its condition, F9
 * toggles the one at the caret and the context menu offers both.
 */
export function useBreakpointGlyphs({ editor, monaco, projectId, file, onEditCondition, store = defaultStore }: GlyphOptions): void {
  const { t } = useTranslation();
  const problemText = useProblemText();
  const mine = useFileBreakpoints(projectId, file, store);
  const reports = useMonitor((state) => state.breakpoints);
  const editRef = useRef(onEditCondition);
  editRef.current = onEditCondition;
  const collection = useRef<MonacoEditor.IEditorDecorationsCollection | null>(null);

  useEffect(() => {
    editor.updateOptions({ glyphMargin: true });
    collection.current = editor.createDecorationsCollection();
    return () => {
      collection.current?.clear();
      collection.current = null;
    };
  }, [editor]);

  useEffect(() => {
    const lines = editor.getModel()?.getLineCount() ?? 0;
    collection.current?.set(
      mine
        .filter((bp) => bp.line <= lines)
        .map((bp) => {
          const report = reports[keyOf(bp)];
          const hover = [
            bp.condition ? t('debug.breakpoint.conditionHover', { condition: bp.condition }) : t('debug.breakpoint.hover'),
            !bp.enabled ? t('debug.breakpoint.disabled') : '',
            report?.state === 'refused' && report.problem ? `${report.problem.code}: ${problemText(report.problem)}` : '',
          ]
            .filter(Boolean)
            .join('\n\n');
          return {
            range: { startLineNumber: bp.line, startColumn: 1, endLineNumber: bp.line, endColumn: 1 },
            options: {
              glyphMarginClassName: glyphClass(bp, report),
              glyphMarginHoverMessage: { value: hover },
              stickiness: monaco.editor.TrackedRangeStickiness.NeverGrowsWhenTypingAtEdges,
            },
          };
        }),
    );
  }, [editor, monaco, mine, reports, t, problemText]);

  useEffect(() => {
    const glyphMargin = monaco.editor.MouseTargetType.GUTTER_GLYPH_MARGIN;
    const down = editor.onMouseDown((event) => {
      const line = event.target.position?.lineNumber;
      if (event.target.type !== glyphMargin || !line || event.event.rightButton) return;
      store.toggle(projectId, file, line);
    });
    const menu = editor.onContextMenu((event) => {
      const line = event.target.position?.lineNumber;
      if (event.target.type !== glyphMargin || !line) return;
      event.event.preventDefault();
      editRef.current(line);
    });
    const caretLine = (ed: MonacoEditor.ICodeEditor) => ed.getPosition()?.lineNumber ?? null;
    const toggle = editor.addAction({
      id: 'nasaq.toggleBreakpoint',
      label: t('debug.breakpoint.toggle'),
      keybindings: [monaco.KeyCode.F9],
      contextMenuGroupId: '9_debug',
      contextMenuOrder: 1,
      run: (ed) => {
        const line = caretLine(ed);
        if (line) store.toggle(projectId, file, line);
      },
    });
    const condition = editor.addAction({
      id: 'nasaq.editBreakpointCondition',
      label: t('debug.breakpoint.editCondition'),
      contextMenuGroupId: '9_debug',
      contextMenuOrder: 2,
      run: (ed) => {
        const line = caretLine(ed);
        if (line) editRef.current(line);
      },
    });
    return () => {
      down.dispose();
      menu.dispose();
      toggle.dispose();
      condition.dispose();
    };
  }, [editor, monaco, projectId, file, store, t]);
}
