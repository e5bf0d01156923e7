import { useCallback, useEffect, useRef, useState } from 'react';
import { asApiError, getFile, saveFile, type ApiError } from '../api/client';
import type { FileOut } from '../api/types';
import { Autosaver, registerAutosaver } from '../editor/autosave';
import type { SaveState } from '../editor/EditorTabsContext';
import { projectContents } from '../projects/projectContents';
import { parseWatchTable, printWatchTable, type WatchLine, type WatchTableFile } from './format';

export interface WatchTableSession {
  status: 'loading' | 'ready' | 'error';
  table: WatchTableFile | null;
  error: ApiError | null;
  save: SaveState;
  /** Changes the lines; the file saves itself (the editors' autosave, with the version check). */
  update: (change: (lines: readonly WatchLine[]) => WatchLine[]) => void;
  /** After a conflict: keep these rows over the newer file. */
  overwrite: () => void;
  /** After a conflict: load the newer file. */
  reload: () => void;
}

function infoOf(file: FileOut) {
  const { name, language, size, version, created_at, updated_at } = file;
  return { name, language, size, version, created_at, updated_at };
}

/**
 * One watch table file of a project, read into rows, saved like a source tab: the same
 * Autosaver (after a pause, on flush, with the version check and the conflict choice), so
 * the table is flushed before a rename and when the page is left.
 */
export function useWatchTableFile(projectId: number | null, name: string | null): WatchTableSession {
  const [table, setTable] = useState<WatchTableFile | null>(null);
  const [status, setStatus] = useState<WatchTableSession['status']>('loading');
  const [error, setError] = useState<ApiError | null>(null);
  const [save, setSave] = useState<SaveState>({ status: 'saved', error: null });
  const saverRef = useRef<Autosaver | null>(null);
  const [generation, setGeneration] = useState(0);

  useEffect(() => {
    if (projectId === null || name === null) return;
    const request = new AbortController();
    let saver: Autosaver | null = null;
    let unregister = () => {};
    setStatus('loading');
    setTable(null);
    setError(null);
    setSave({ status: 'saved', error: null });
    getFile(projectId, name, request.signal).then(
      (file) => {
        if (request.signal.aborted) return;
        saver = new Autosaver({
          text: file.text,
          version: file.version,
          save: (text, baseVersion, options) => saveFile(projectId, name, { text, base_version: baseVersion }, options),
          onState: setSave,
          onSaved: (info) => projectContents.putFile(projectId, info),
        });
        saverRef.current = saver;
        unregister = registerAutosaver(`watch:${projectId}:${name}`, () => ({ projectId, path: name }), saver);
        setTable(parseWatchTable(file.text));
        setStatus('ready');
      },
      (caught: unknown) => {
        if (request.signal.aborted) return;
        setError(asApiError(caught));
        setStatus('error');
      },
    );
    return () => {
      request.abort();
      unregister();
      if (saver) void saver.dispose();
      saverRef.current = null;
    };
  }, [projectId, name, generation]);

  const update = useCallback((change: (lines: readonly WatchLine[]) => WatchLine[]) => {
    setTable((current) => {
      if (!current) return current;
      const next = { ...current, lines: change(current.lines) };
      saverRef.current?.change(printWatchTable(next));
      return next;
    });
  }, []);

  const overwrite = useCallback(() => {
    void saverRef.current?.overwrite();
  }, []);

  const reload = useCallback(() => {
    if (projectId === null || name === null) return;
    getFile(projectId, name).then(
      (file) => {
        saverRef.current?.reloaded(file.text, file.version);
        projectContents.putFile(projectId, infoOf(file));
        setTable(parseWatchTable(file.text));
      },
      () => setGeneration((value) => value + 1),
    );
  }, [projectId, name]);

  return { status, table, error, save, update, overwrite, reload };
}
