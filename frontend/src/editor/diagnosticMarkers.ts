import { useCallback } from 'react';
import { useTranslation } from 'react-i18next';
import type { Diagnostic } from '../api/types';
import type { EditorMarker } from './CodeEditor';

/**
 * A diagnostic's message in the interface language: the catalogue's `problems.<key>` with the
 * diagnostic's parameters when the catalogue has the key, else the compiler's English text.
 */
export function useDiagnosticMessage(): (diagnostic: Diagnostic) => string {
  const { t, i18n } = useTranslation();
  return useCallback(
    (diagnostic: Diagnostic) => {
      const key = `problems.${diagnostic.key}`;
      return i18n.exists(key) ? t(key, { ...diagnostic.params }) : diagnostic.message;
    },
    // `t` changes with the language, so the markers are translated again.
    [t, i18n],
  );
}

/** The end of the word at `column` (1-based) in `line`: where a marker without an end stops. */
function wordEnd(line: string, column: number): number {
  let index = column - 1;
  if (index >= line.length) return column + 1;
  while (index < line.length && !/[\s;,()]/.test(line[index] ?? ' ')) index += 1;
  return Math.max(index + 1, column + 1);
}

/**
 * The markers of one file's diagnostics. A span without a column marks the line's text; one
 * without an end marks the word it starts at; one without a line marks the first line.
 */
export function markersFor(
  diagnostics: readonly Diagnostic[],
  file: string,
  text: string,
  message: (diagnostic: Diagnostic) => string,
): EditorMarker[] {
  const lines = text.split('\n');
  const markers: EditorMarker[] = [];
  for (const diagnostic of diagnostics) {
    const span = diagnostic.span;
    if (!span || span.file !== file) continue;
    const line = Math.min(Math.max(span.line ?? 1, 1), Math.max(lines.length, 1));
    const content = (lines[line - 1] ?? '').replace(/\r$/, '');
    let column = span.column ?? null;
    let endLine = span.end_line ?? line;
    let endColumn = span.end_column ?? null;
    if (column === null) {
      const indent = content.length - content.trimStart().length;
      column = indent + 1;
      endColumn = endColumn ?? content.trimEnd().length + 1;
    }
    if (endColumn === null || (endLine === line && endColumn <= column)) {
      endLine = line;
      endColumn = wordEnd(content, column);
    }
    markers.push({
      line,
      column,
      endLine,
      endColumn,
      severity: diagnostic.severity,
      code: diagnostic.code,
      message: message(diagnostic),
    });
  }
  return markers;
}
