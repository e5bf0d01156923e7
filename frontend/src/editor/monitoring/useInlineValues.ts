import { useEffect } from 'react';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { BlockStatus } from '../../api/monitor';
import type { MonitorClient } from '../../api/monitorClient';
import { sameBlockName } from './blockAtLine';
import { inlineTexts, visibleTexts } from './inlineValues';
import { visibleLines } from './statusColumnPane';

/** At most this often the values after the lines change (frames come up to 30 times a second). */
export const INLINE_INTERVAL_MS = 250;

/**
 * SCL monitoring: the values of each executed line's variables after the line, as muted text
 * (decorations with `after` content) on the visible lines only; cleared when monitoring stops.
 */
export function useInlineValues(editor: MonacoEditor.IStandaloneCodeEditor, client: MonitorClient | null, block: string | null): void {
  useEffect(() => {
    if (!client || block === null) return;
    const decorations = editor.createDecorationsCollection();
    const statusOf = (): BlockStatus | null => {
      const status = client.getState().block;
      return status && sameBlockName(status.block, block) ? status : null;
    };
    let shown = statusOf();
    let texts = inlineTexts(shown);
    let applied = '';
    let timer: ReturnType<typeof setTimeout> | null = null;
    let lastRun = 0;
    const apply = () => {
      timer = null;
      lastRun = Date.now();
      const model = editor.getModel();
      const range = visibleLines(editor);
      if (!model || !range) return;
      const lineCount = model.getLineCount();
      const items = visibleTexts(texts, range.first, Math.min(range.last, lineCount));
      const signature = items.map(([line, text]) => `${line}\u0000${text}`).join('\u0001');
      if (signature === applied) return;
      applied = signature;
      decorations.set(
        items.map(([line, text]) => {
          const end = model.getLineMaxColumn(line);
          return {
            range: { startLineNumber: line, startColumn: end, endLineNumber: line, endColumn: end },
            options: { after: { content: `\u2003${text}`, inlineClassName: 'scl-inline-value' }, showIfCollapsed: true },
          };
        }),
      );
    };
    const schedule = () => {
      if (timer === null) timer = setTimeout(apply, Math.max(0, INLINE_INTERVAL_MS - (Date.now() - lastRun)));
    };
    const unsubscribe = client.subscribe(() => {
      const next = statusOf();
      if (next === shown) return;
      shown = next;
      texts = inlineTexts(shown);
      schedule();
    });
    const subscriptions = [editor.onDidScrollChange(schedule), editor.onDidChangeModelContent(schedule)];
    apply();
    return () => {
      if (timer !== null) clearTimeout(timer);
      unsubscribe();
      subscriptions.forEach((subscription) => subscription.dispose());
      decorations.clear();
    };
  }, [editor, client, block]);
}
