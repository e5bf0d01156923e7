import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { asApiError, checkSource, getFile, saveFile, type ApiError } from '../api/client';
import { projectContents, useProjectContents, type ProjectContentsStore } from '../projects/projectContents';
import { Autosaver, registerAutosaver } from './autosave';
import type { EditorMarker } from './CodeEditor';
import { markersFor, useDiagnosticMessage } from './diagnosticMarkers';
import { useEditorTabs, type SourceTab } from './EditorTabsContext';
import { LiveCheck } from './liveCheck';

export interface SourceFileSession {
  /** The markers of the file's diagnostics (the tab's own markers for a text without a file). */
  markers: readonly EditorMarker[];
  /** Saves now (the editor lost the focus). */
  flush: () => void;
  /** After a conflict: keep this text over the newer one on the server. */
  overwrite: () => void;
  /** After a conflict: take the server's text; rejects with the error when it cannot be read. */
  reload: () => Promise<void>;
  /** Why the server's text could not be read (after `reload`). */
  reloadError: ApiError | null;
}

/**
 * What a file tab does with its text besides showing it: the autosave (PUT with the version
 * check, ~1 s after the last change and on blur or close), diagnostics while typing (`/check`
 * ~400 ms after the last change) and the markers of the file's diagnostics, translated.
 */
export function useSourceFile(tab: SourceTab, store: ProjectContentsStore = projectContents): SourceFileSession {
  const { markSaved, setSaveState, replaceText } = useEditorTabs();
  const message = useDiagnosticMessage();
  const tabRef = useRef(tab);
  tabRef.current = tab;
  const file = tab.file;
  const projectId = file?.projectId ?? null;
  const fileKey = file ? `${file.projectId}` : null;
  const saverRef = useRef<Autosaver | null>(null);
  const checkRef = useRef<LiveCheck | null>(null);
  const [reloadError, setReloadError] = useState<ApiError | null>(null);
  const contents = useProjectContents(projectId, store);

  // One autosave and one live check per tab with a file, for as long as the tab is open. The
  // file's name may change (rename): they read it from the tab when they need it.
  useEffect(() => {
    if (fileKey === null) return;
    const id = tabRef.current.id;
    const currentFile = () => tabRef.current.file;
    const initial = tabRef.current;
    const saver = new Autosaver({
      text: initial.text,
      version: initial.version,
      saved: !initial.dirty,
      save: (text, baseVersion, options) => {
        const target = currentFile();
        if (!target) return Promise.reject(new Error('the tab has no file'));
        return saveFile(target.projectId, target.path, { text, base_version: baseVersion }, options);
      },
      onState: (state) => setSaveState(id, state),
      onSaved: (info, text) => {
        const target = currentFile();
        markSaved(id, undefined, { version: info.version, text });
        if (target) store.putFile(target.projectId, info);
      },
    });
    const check = new LiveCheck({
      check: (text, signal) => {
        const target = currentFile();
        if (!target) return Promise.reject(new Error('the tab has no file'));
        return checkSource(target.projectId, { name: target.path, text }, signal);
      },
      onResult: (build) => {
        const target = currentFile();
        if (target) store.applyBuild(target.projectId, build, target.path);
      },
    });
    // A text opened with changes is checked at once; a saved one after the usual pause: the
    // project's build has its diagnostics already, and a diagram being read goes first.
    check.change(initial.text, initial.dirty);
    saverRef.current = saver;
    checkRef.current = check;
    const unregister = registerAutosaver(id, currentFile, saver);
    return () => {
      unregister();
      check.dispose();
      void saver.dispose();
      const target = currentFile();
      if (target) {
        store.setFileDirty(target.projectId, target.path, false);
        store.dropOverride(target.projectId, target.path);
      }
      saverRef.current = null;
      checkRef.current = null;
    };
  }, [fileKey, markSaved, setSaveState, store]);

  // Every new text, typed or taken from the server, is saved and checked.
  useEffect(() => {
    saverRef.current?.change(tab.text);
    checkRef.current?.change(tab.text);
  }, [tab.text]);

  const path = file?.path ?? null;
  useEffect(() => {
    if (projectId !== null && path !== null) store.setFileDirty(projectId, path, tab.dirty);
  }, [projectId, path, tab.dirty, store, contents?.status]);

  // The markers follow the project's diagnostics, not each keystroke: Monaco moves them with
  // the text it edits until the next check answers.
  const diagnostics = contents?.diagnostics;
  const textRef = useRef(tab.text);
  const fileMarkers = useMemo(() => {
    if (path === null || !diagnostics) return null;
    return markersFor(diagnostics, path, textRef.current, message);
  }, [diagnostics, path, message]);
  textRef.current = tab.text;

  const flush = useCallback(() => {
    void saverRef.current?.flush();
  }, []);

  const overwrite = useCallback(() => {
    void saverRef.current?.overwrite();
  }, []);

  const reload = useCallback(async () => {
    const target = tabRef.current.file;
    if (!target) return;
    setReloadError(null);
    try {
      const theirs = await getFile(target.projectId, target.path);
      saverRef.current?.reloaded(theirs.text, theirs.version);
      replaceText(tabRef.current.id, theirs.text, theirs.version);
      const { name, language, size, version, created_at, updated_at } = theirs;
      store.putFile(target.projectId, { name, language, size, version, created_at, updated_at });
    } catch (caught) {
      setReloadError(asApiError(caught));
    }
  }, [replaceText, store]);

  return { markers: fileMarkers ?? tab.markers, flush, overwrite, reload, reloadError };
}
