/**
 * The S7-Graph model an editor holds for one `.graph` file, kept in step with the file's text.
 *
 * Same design as the LAD/FBD document (`lad/useLadDocument.ts`): the text is the file (the tab's
 * autosave with its version check and the text view work on it); the model is what the chart and
 * the step view show and edit. An edit changes the model and, right away in the browser, the text
 * (`spliceText`: only the changed steps, transitions, settings, permanent sections and a
 * sequencer's added or removed items are printed again). A text changed elsewhere (the text view,
 * the server's version after a conflict) is read again by the server, the reference for the
 * format; a text with syntax errors is not drawn, and the views say why.
 *
 * The undo history keeps the text with each model, so an undo writes back the very text the file
 * had before the edit: undoing every edit gives the original file byte for byte, comments and
 * layout included. The checker's findings (`problems`) and the parts' lines (`places`) come from
 * the server: after a read, and again shortly after each edit (only the findings; the model stays
 * the one edited).
 */
import { useCallback, useEffect, useRef, useState } from 'react';
import { asApiError, readGraph, type ApiError } from '../api/client';
import type { Diagnostic } from '../api/types';
import { UndoHistory } from '../diagram/undo';
import type { GraphBlock } from './model';
import { spliceText } from './textEdit';

export type Blocks = readonly GraphBlock[];

export type GraphDocState =
  | { status: 'loading' }
  | { status: 'ready' }
  | { status: 'unreadable'; problems: readonly Diagnostic[] }
  | { status: 'failed'; error: ApiError };

export interface GraphDocument {
  state: GraphDocState;
  /** The model, once the text has been read (also while a newer text is being read). */
  blocks: Blocks | null;
  /** The checker's findings (GRA2xx) of the last text the server read. */
  problems: readonly Diagnostic[];
  /** Per block, the line of each part (BLOCK, SETTINGS, SEQ:<name>, S<n>, T<n> ...) of that text. */
  places: readonly Record<string, number>[];
  /** The text changed elsewhere and is being read: the model is older than the text, edits wait. */
  pending: boolean;
  /** One edit of the model: one undo step. `label` is a key of `graphDoc.edit` (see EDIT_LABELS). */
  edit: (change: (blocks: Blocks) => Blocks, label: string) => void;
  undo: () => void;
  redo: () => void;
  canUndo: boolean;
  canRedo: boolean;
  /** What an undo/redo would take back or make again (a label given to `edit`), for tooltips. */
  undoLabel?: string | null;
  redoLabel?: string | null;
  /** Reads the text again (after the server could not be reached). */
  retry: () => void;
}

/** The labels of the editors' edits: keys of `graphDoc.edit` in the locale files. */
export const EDIT_LABELS = [
  'insertStep',
  'insertAlternative',
  'insertSimultaneous',
  'insertJump',
  'insertEnd',
  'delete',
  'moveBranch',
  'renumber',
  'rename',
  'editStep',
  'editTransition',
  'editActions',
  'editCondition',
  'settings',
  'permanent',
  'addSequencer',
  'text',
] as const;

export type EditLabel = (typeof EDIT_LABELS)[number];

interface Snapshot {
  blocks: Blocks;
  /** The file's text for `blocks`. */
  text: string;
}

/** How long after an edit the server checks the new text (edits in a row are checked once). */
const CHECK_DELAY_MS = 400;

/** `enabled`: a graphical view is shown (the text view alone needs no model). */
export function useGraphDocument(name: string, text: string, setText: (text: string) => void, enabled = true): GraphDocument {
  const history = useRef<UndoHistory<Snapshot> | null>(null);
  /** The text the model stands for (what the editor wrote last, or read last). */
  const modelText = useRef<string | null>(null);
  const [state, setState] = useState<GraphDocState>({ status: 'loading' });
  const [findings, setFindings] = useState<{ text: string | null; problems: readonly Diagnostic[]; places: readonly Record<string, number>[] }>({
    text: null,
    problems: [],
    places: [],
  });
  const [, setVersion] = useState(0);
  const [attempt, setAttempt] = useState(0);
  const bump = useCallback(() => setVersion((v) => v + 1), []);
  const setTextRef = useRef(setText);
  setTextRef.current = setText;
  const textRef = useRef(text);
  textRef.current = text;

  // A text the model does not stand for: read it.
  useEffect(() => {
    if (!enabled || text === modelText.current) return;
    const request = new AbortController();
    const wanted = text;
    readGraph(name, wanted, request.signal).then(
      (read) => {
        if (request.signal.aborted) return;
        const errors = read.diagnostics.filter((d) => d.severity === 'error');
        if (errors.length > 0) {
          setState({ status: 'unreadable', problems: errors });
          return;
        }
        modelText.current = wanted;
        const snapshot = { blocks: read.blocks, text: wanted };
        if (history.current) history.current.replace(snapshot, 'text');
        else history.current = new UndoHistory<Snapshot>(snapshot);
        setFindings({ text: wanted, problems: read.problems, places: read.places });
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

  // The model's own text (after an edit, undo or redo): the server checks it again, shortly.
  const stale = enabled && text === modelText.current && findings.text !== text;
  useEffect(() => {
    if (!stale) return;
    const request = new AbortController();
    const wanted = text;
    const timer = window.setTimeout(() => {
      readGraph(name, wanted, request.signal).then(
        (read) => {
          if (request.signal.aborted || modelText.current !== wanted) return;
          setFindings({ text: wanted, problems: read.problems, places: read.places });
        },
        () => undefined, // the findings stay those of the last check; the next edit checks again
      );
    }, CHECK_DELAY_MS);
    return () => {
      window.clearTimeout(timer);
      request.abort();
    };
  }, [name, text, stale]);

  const show = useCallback(
    (written: string) => {
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
      const after = change(before.blocks);
      if (after === before.blocks) return;
      const written = spliceText(modelText.current ?? before.text, before.blocks, after);
      current.push({ blocks: after, text: written }, label);
      show(written);
    },
    [show],
  );

  const undo = useCallback(() => {
    const current = history.current;
    if (!current || textRef.current !== modelText.current) return;
    const back = current.undo();
    if (back) show(back.text);
  }, [show]);

  const redo = useCallback(() => {
    const current = history.current;
    if (!current || textRef.current !== modelText.current) return;
    const again = current.redo();
    if (again) show(again.text);
  }, [show]);

  const retry = useCallback(() => {
    setState({ status: 'loading' });
    setAttempt((n) => n + 1);
  }, []);

  return {
    state,
    blocks: history.current?.state.blocks ?? null,
    problems: findings.problems,
    places: findings.places,
    pending: text !== modelText.current,
    edit,
    undo,
    redo,
    canUndo: history.current?.canUndo ?? false,
    canRedo: history.current?.canRedo ?? false,
    undoLabel: history.current?.undoLabel ?? null,
    redoLabel: history.current?.redoLabel ?? null,
    retry,
  };
}
