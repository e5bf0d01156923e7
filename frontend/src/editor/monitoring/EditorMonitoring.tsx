import { useCallback, useState } from 'react';
import { createPortal } from 'react-dom';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { Problem } from '../../api/monitorClient';
import { useSession } from '../../cpu/SessionContext';
import type { MonacoApi } from '../monaco/load';
import { BreakpointDialog } from './BreakpointDialog';
import { StlStatusPane } from './StlStatusPane';
import { useBlockFollower } from './useBlockFollower';
import { useBreakpointGlyphs } from './useBreakpointGlyphs';
import { useHoldHighlight } from './useHoldHighlight';
import { useInlineValues } from './useInlineValues';
import './monitoring.css';

export interface EditorMonitoringProps {
  editor: MonacoEditor.IStandaloneCodeEditor;
  monaco: MonacoApi;
  projectId: number;
  /** The project file the editor shows. */
  file: string;
  language: 'stl' | 'scl';
  /** The tab's monitoring toggle is on and the tab is in front. */
  monitoring: boolean;
  lineHeight: number;
  /** Why the block cannot be monitored (MON613: not in the downloaded program), or null. */
  onProblem?: (problem: Problem | null) => void;
}

const ignore = () => undefined;

/**
 * Everything online in a source editor: breakpoints in the glyph margin, the line the CPU holds
 * at, and while monitoring is on the block status of the block at the caret (STL status columns,
 * SCL values after the lines).
 */
export function EditorMonitoring({ editor, monaco, projectId, file, language, monitoring, lineHeight, onProblem = ignore }: EditorMonitoringProps) {
  const { session, client } = useSession();
  const [editing, setEditing] = useState<number | null>(null);
  const closeDialog = useCallback(() => setEditing(null), []);
  useBreakpointGlyphs({ editor, monaco, projectId, file, onEditCondition: setEditing });
  useHoldHighlight(editor, projectId, file);
  const online = monitoring && client !== null && session?.projectId === projectId;
  const block = useBlockFollower({ editor, client, projectId, file, enabled: online, onProblem });
  useInlineValues(editor, online && language === 'scl' ? client : null, block);

  return (
    <>
      {online && language === 'stl' && client ? <StlStatusPane editor={editor} client={client} block={block} lineHeight={lineHeight} /> : null}
      {/* In the page's body: the editor's frame is always left to right, the dialog is not. */}
      {editing !== null
        ? createPortal(<BreakpointDialog projectId={projectId} file={file} line={editing} onClose={closeDialog} />, document.body)
        : null}
    </>
  );
}
