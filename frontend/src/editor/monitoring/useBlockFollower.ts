import { useEffect, useRef, useState } from 'react';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { MonitorClient, Problem } from '../../api/monitorClient';
import { problemOf } from '../../cpu/SessionContext';
import { projectContents, type ProjectContentsStore } from '../../projects/projectContents';
import { blockName, blockToMonitor } from './blockAtLine';
import { visibleLines } from './statusColumnPane';

/** How long the caret or the scroll position must rest before another block is opened. */
export const FOLLOW_DELAY_MS = 150;

interface FollowOptions {
  editor: MonacoEditor.IStandaloneCodeEditor;
  client: MonitorClient | null;
  projectId: number;
  file: string;
  enabled: boolean;
  onProblem: (problem: Problem | null) => void;
  contents?: ProjectContentsStore;
}

/**
 * While monitoring is on, opens the block at the caret (or, scrolled away from it, the first
 * visible one) and follows the caret and the scrolling to the file's other blocks; closes the
 * block when monitoring stops. Returns the opened block's name.
 */
export function useBlockFollower({ editor, client, projectId, file, enabled, onProblem, contents = projectContents }: FollowOptions): string | null {
  const [opened, setOpened] = useState<string | null>(null);
  const problemRef = useRef(onProblem);
  problemRef.current = onProblem;

  useEffect(() => {
    if (!enabled || !client) return;
    let current: string | null | undefined;
    let timer: ReturnType<typeof setTimeout> | null = null;
    let live = true;
    const choose = () => {
      timer = null;
      const blocks = contents.get(projectId)?.blocks ?? [];
      const caret = editor.getPosition()?.lineNumber ?? 1;
      const block = blockToMonitor(blocks, file, caret, visibleLines(editor));
      const name = block ? blockName(block) : null;
      if (name === current) return;
      current = name;
      setOpened(name);
      client
        .openBlock(name)
        .then(() => live && problemRef.current(null))
        .catch((error: unknown) => live && problemRef.current(problemOf(error)));
    };
    const later = () => {
      if (timer !== null) clearTimeout(timer);
      timer = setTimeout(choose, FOLLOW_DELAY_MS);
    };
    contents.ensure(projectId);
    choose();
    const subscriptions = [editor.onDidChangeCursorPosition(later), editor.onDidScrollChange(later)];
    const unsubscribe = contents.subscribe(later);
    return () => {
      live = false;
      if (timer !== null) clearTimeout(timer);
      subscriptions.forEach((subscription) => subscription.dispose());
      unsubscribe();
      setOpened(null);
      problemRef.current(null);
      client.openBlock(null).catch(() => undefined);
    };
  }, [editor, client, projectId, file, enabled, contents]);
  return opened;
}
