import { useEffect, useRef } from 'react';
import { useTranslation } from 'react-i18next';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { MonacoApi } from '../editor/monaco/load';
import { operandAt } from './operandAt';
import { openRename, showReferences } from './xrefRequests';

interface Props {
  editor: MonacoEditor.IStandaloneCodeEditor;
  monaco: MonacoApi;
  projectId: number;
  /** Says that there is no operand under the caret (the editor's status line). */
  onNothing?: (text: string) => void;
}

/**
 * Shift+F12 (cross-references, as TIA Portal) and F2 (rename) on the operand under the caret
 * of an STL or SCL editor, also in its context menu. They replace Monaco's own "references" and
 * "rename", which know nothing of the project.
 */
export function XrefEditorActions({ editor, monaco, projectId, onNothing }: Props) {
  const { t } = useTranslation();
  const nothing = useRef(onNothing);
  nothing.current = onNothing;

  useEffect(() => {
    const operand = (): string | null => {
      const position = editor.getPosition();
      const text = position ? editor.getModel()?.getLineContent(position.lineNumber) : undefined;
      const found = position && text !== undefined ? operandAt(text, position.column) : null;
      if (!found) nothing.current?.(t('xref.editor.nothing'));
      return found;
    };
    const references = editor.addAction({
      id: 'nasaq.xref.references',
      label: t('xref.editor.references'),
      keybindings: [monaco.KeyMod.Shift | monaco.KeyCode.F12],
      contextMenuGroupId: 'navigation',
      contextMenuOrder: 2,
      run: () => {
        const found = operand();
        if (found) showReferences(projectId, found);
      },
    });
    const rename = editor.addAction({
      id: 'nasaq.xref.rename',
      label: t('xref.editor.rename'),
      keybindings: [monaco.KeyCode.F2],
      contextMenuGroupId: 'navigation',
      contextMenuOrder: 3,
      run: () => {
        const found = operand();
        if (found) openRename(projectId, found);
      },
    });
    return () => {
      references.dispose();
      rename.dispose();
    };
  }, [editor, monaco, projectId, t]);

  return null;
}
