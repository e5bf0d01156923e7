/**
 * The network model a LAD/FBD editor holds for one file, kept in step with the file's text.
 *
 * The text is the file (the tab's autosave and live check work on it, as for STL and SCL); the
 * model is what the diagram shows and edits. An edit changes the model, and the text is changed
 * to match right away in the browser ({@link spliceText}), so it is drawn, saved and checked
 * without waiting for the server. A text that changed elsewhere (the text view, the server's
 * version after a conflict) is read again by the server's parser, the reference for the format;
 * a text that does not parse is not drawn, and the view says why.
 */
import { useCallback, useEffect, useRef, useState } from 'react';
import { asApiError, readLad, type ApiError } from '../api/client';
import type { Diagnostic } from '../api/types';
import { UndoHistory } from '../diagram/undo';
import type { LadBlock } from './model';
import { spliceText } from './textEdit';

export type Blocks = readonly LadBlock[];

export type LadDocState =
  | { status: 'loading' }
  | { status: 'ready' }
  | { status: 'unreadable'; problems: readonly Diagnostic[] }
  | { status: 'failed'; error: ApiError };

export interface LadDocument {
  state: LadDocState;
  /** The model, once the text has been read (also while a newer text is being read). */
  blocks: Blocks | null;
  /** The text changed elsewhere and is being read: the model is older than the text, edits wait. */
  pending: boolean;
  /** One edit of the model: one undo step. */
  edit: (change: (blocks: Blocks) => Blocks, label: string) => void;
  undo: () => void;
  redo: () => void;
  canUndo: boolean;
  canRedo: boolean;
  /** Reads the text again (after the server could not be reached). */
  retry: () => void;
}

/** `enabled`: a diagram or the STL view is shown (the text view alone needs no model). */
export function useLadDocument(name: string, text: string, setText: (text: string) => void, enabled = true): LadDocument {
  const history = useRef<UndoHistory<Blocks> | null>(null);
  /** The text the model stands for (what the editor printed last, or read last). */
  const modelText = useRef<string | null>(null);
  const [state, setState] = useState<LadDocState>({ status: 'loading' });
  const [, setVersion] = useState(0);
  const [attempt, setAttempt] = useState(0);
  const bump = useCallback(() => setVersion((v) => v + 1), []);
  const setTextRef = useRef(setText);
  setTextRef.current = setText;
  const textRef = useRef(text);
  textRef.current = text;

  useEffect(() => {
    if (!enabled || text === modelText.current) return;
    const request = new AbortController();
    const wanted = text;
    readLad(name, wanted, request.signal).then(
      (read) => {
        if (request.signal.aborted) return;
        const problems = read.diagnostics.filter((d) => d.severity === 'error');
        if (problems.length > 0) {
          setState({ status: 'unreadable', problems });
          return;
        }
        modelText.current = wanted;
        if (history.current) history.current.replace(read.blocks, 'text');
        else history.current = new UndoHistory<Blocks>(read.blocks);
        setState({ status: 'ready' });
        bump();
      },
      (error: unknown) => {
        if (request.signal.aborted || (error instanceof DOMException && error.name === 'AbortError')) return;
        setState({ status: 'failed', error: asApiError(error) });
      },
    );
    return () => request.abort();
  }, [name, text, attempt, bump, enabled]);

  const show = useCallback(
    (previous: Blocks, next: Blocks) => {
      const base = modelText.current ?? '';
      const written = spliceText(base, previous, next);
      modelText.current = written;
      textRef.current = written;
      setTextRef.current(written);
      bump();
    },
    [bump],
  );

  const edit = useCallback(
    (change: (blocks: Blocks) => Blocks, label: string) => {
      const current = history.current;
      if (!current || textRef.current !== modelText.current) return;
      const before = current.state;
      const after = change(before);
      if (after === before) return;
      current.push(after, label);
      show(before, after);
    },
    [show],
  );

  const undo = useCallback(() => {
    const current = history.current;
    if (!current || textRef.current !== modelText.current) return;
    const before = current.state;
    const after = current.undo();
    if (after) show(before, after);
  }, [show]);

  const redo = useCallback(() => {
    const current = history.current;
    if (!current || textRef.current !== modelText.current) return;
    const before = current.state;
    const after = current.redo();
    if (after) show(before, after);
  }, [show]);

  const retry = useCallback(() => {
    setState({ status: 'loading' });
    setAttempt((n) => n + 1);
  }, []);

  const blocks = history.current?.state ?? null;
  return {
    state,
    blocks,
    pending: text !== modelText.current,
    edit,
    undo,
    redo,
    canUndo: history.current?.canUndo ?? false,
    canRedo: history.current?.canRedo ?? false,
    retry,
  };
}
