import { createContext, useCallback, useContext, useMemo, useRef, useState, type ReactNode } from 'react';
import type { ApiError } from '../api/client';
import type { EditorMarker, SourceLanguage } from './CodeEditor';
import { languageOfFile } from './fileLanguage';

/** What an editor tab shows. LAD/FBD and Graph editors join this list later. */
export type EditorTabKind = 'start' | 'source' | 'db';

export interface StartTab {
  id: 'start';
  kind: 'start';
}

/** Where a source tab's text lives on the server; none while it exists only in the browser. */
export interface SourceFileRef {
  projectId: number;
  path: string;
}

/**
 * Where a file tab's text stands against the server: saved, changed and waiting for the
 * autosave, being saved, refused because the file changed elsewhere (409, API111), or not
 * saved because of another error (kept, and tried again).
 */
export type SaveStatus = 'saved' | 'dirty' | 'saving' | 'conflict' | 'failed';

export interface SaveState {
  status: SaveStatus;
  /** The server's answer when the status is `conflict` or `failed`. */
  error: ApiError | null;
}

/** A place in the text to show: the editor scrolls there and puts the caret there. */
export interface RevealRequest {
  line: number;
  column: number;
  /** In a LAD/FBD file: the network (1-based in its block) and the element to select there. */
  network?: number | null;
  element?: string | null;
  /** Grows with every request, so the same place can be asked for twice. */
  seq: number;
}

/** An STL or SCL text (or a symbol table) in a Monaco editor. */
export interface SourceTab {
  id: string;
  kind: 'source';
  /** The file name the tab shows (`Motor.awl`). */
  name: string;
  language: SourceLanguage;
  text: string;
  /** True when `text` has changes that are not saved. */
  dirty: boolean;
  file: SourceFileRef | null;
  /** The compiler's problems in this text, shown as markers in the editor. */
  markers: readonly EditorMarker[];
  /** The file's version on the server that `text` derives from (null: no file, or unknown). */
  version: number | null;
  save: SaveState;
  reveal: RevealRequest | null;
}

/** The DB editor of a data block: its variables, offline values and (in a simulation) live ones. */
export interface DbTab {
  id: string;
  kind: 'db';
  projectId: number;
  /** How the server finds the DB: `DB10` or its symbol. */
  block: string;
  /** What the tab shows: `DB10 LevelData`. */
  name: string;
}

export type EditorTab = StartTab | SourceTab | DbTab;

/** A place to show: a line (and column); in a LAD/FBD file also its network and element. */
export type RevealAt = { line: number; column?: number; network?: number | null; element?: string | null };

export interface NewSource {
  name: string;
  language: SourceLanguage;
  text: string;
  file?: SourceFileRef | null;
  /** A new text that exists nowhere else starts dirty; a text just read from a file does not. */
  dirty?: boolean;
  /** The file's version on the server, for the autosave's version check. */
  version?: number | null;
  /** A line to show once the tab is open (a block's header, a diagnostic). */
  at?: RevealAt | null;
}

interface EditorTabsValue {
  tabs: readonly EditorTab[];
  activeId: string | null;
  activate: (id: string) => void;
  close: (id: string) => void;
  /** Opens the Start page, or brings it to the front if it is already open. */
  openStart: () => void;
  /** Opens a source in a new tab (or brings the tab of the same file to the front); its id. */
  openSource: (source: NewSource) => string;
  /** Opens the DB editor of a data block (or brings its tab to the front); its id. */
  openDb: (db: { projectId: number; block: string; name: string }) => string;
  /** The text of a source tab changed in its editor: it becomes dirty. */
  updateSource: (id: string, text: string) => void;
  /**
   * The text of a source tab was saved (as `file`, when given). With `saved`, the tab stays
   * dirty if its text changed while it was being saved.
   */
  markSaved: (id: string, file?: SourceFileRef, saved?: { version: number; text: string }) => void;
  /** The problems the compiler found in a source tab's text. */
  setMarkers: (id: string, markers: readonly EditorMarker[]) => void;
  /** The autosave's state of a file tab. */
  setSaveState: (id: string, save: SaveState) => void;
  /** Replaces a tab's text with the server's (after a conflict): saved, at `version`. */
  replaceText: (id: string, text: string, version: number) => void;
  /** Brings a tab to the front and shows `line` (and `column`) in its editor. */
  reveal: (id: string, at: RevealAt) => void;
  /** A file was renamed on the server: its tabs follow. */
  renameFileTabs: (projectId: number, from: string, to: string) => void;
  /** A file (or, without `path`, every file of a project) was deleted: its tabs close. */
  closeFileTabs: (projectId: number, path?: string) => void;
}

const START_TAB: StartTab = { id: 'start', kind: 'start' };

const EditorTabsContext = createContext<EditorTabsValue | null>(null);

function sameFile(a: SourceFileRef | null, b: SourceFileRef | null | undefined): boolean {
  return !!a && !!b && a.projectId === b.projectId && a.path === b.path;
}

/** The open editor tabs, shared by the editor area and the menus that open tabs. */
export function EditorTabsProvider({ children }: { children: ReactNode }) {
  const [tabs, setTabs] = useState<readonly EditorTab[]>([START_TAB]);
  const [activeId, setActiveId] = useState<string | null>(START_TAB.id);
  const nextId = useRef(1);
  // The latest tabs for callbacks that must answer at once (openSource returns an id).
  const tabsRef = useRef(tabs);
  tabsRef.current = tabs;

  const activate = useCallback((id: string) => setActiveId(id), []);

  const close = useCallback(
    (id: string) => {
      const index = tabs.findIndex((tab) => tab.id === id);
      if (index < 0) return;
      const remaining = tabs.filter((tab) => tab.id !== id);
      setTabs(remaining);
      if (activeId === id) {
        const neighbour = remaining[Math.min(index, remaining.length - 1)];
        setActiveId(neighbour ? neighbour.id : null);
      }
    },
    [tabs, activeId],
  );

  const openStart = useCallback(() => {
    setTabs((current) => (current.some((tab) => tab.id === START_TAB.id) ? current : [START_TAB, ...current]));
    setActiveId(START_TAB.id);
  }, []);

  const revealSeq = useRef(0);
  const revealAt = (at: RevealAt): RevealRequest => ({
    line: Math.max(1, at.line),
    column: Math.max(1, at.column ?? 1),
    ...(at.network != null ? { network: at.network } : {}),
    ...(at.element ? { element: at.element } : {}),
    seq: ++revealSeq.current,
  });

  const openSource = useCallback((source: NewSource) => {
    const existing = tabsRef.current.find((tab) => tab.kind === 'source' && sameFile(tab.file, source.file));
    if (existing) {
      if (source.at) {
        const reveal = revealAt(source.at);
        setTabs((current) => current.map((tab) => (tab.id === existing.id ? { ...tab, reveal } : tab)));
      }
      setActiveId(existing.id);
      return existing.id;
    }
    const id = `source-${nextId.current++}`;
    const dirty = source.dirty ?? !source.file;
    const tab: SourceTab = {
      id,
      kind: 'source',
      name: source.name,
      language: source.language,
      text: source.text,
      dirty,
      file: source.file ?? null,
      markers: [],
      version: source.version ?? null,
      save: { status: dirty ? 'dirty' : 'saved', error: null },
      reveal: source.at ? revealAt(source.at) : null,
    };
    setTabs((current) => [...current, tab]);
    setActiveId(id);
    return id;
  }, []);

  const openDb = useCallback((db: { projectId: number; block: string; name: string }) => {
    const existing = tabsRef.current.find(
      (tab) => tab.kind === 'db' && tab.projectId === db.projectId && tab.block === db.block,
    );
    if (existing) {
      setActiveId(existing.id);
      return existing.id;
    }
    const id = `db-${nextId.current++}`;
    const tab: DbTab = { id, kind: 'db', projectId: db.projectId, block: db.block, name: db.name };
    setTabs((current) => [...current, tab]);
    setActiveId(id);
    return id;
  }, []);

  const updateSource = useCallback((id: string, text: string) => {
    setTabs((current) =>
      current.map((tab) => (tab.kind === 'source' && tab.id === id && tab.text !== text ? { ...tab, text, dirty: true } : tab)),
    );
  }, []);

  const markSaved = useCallback((id: string, file?: SourceFileRef, saved?: { version: number; text: string }) => {
    setTabs((current) =>
      current.map((tab) =>
        tab.kind === 'source' && tab.id === id
          ? {
              ...tab,
              dirty: saved ? tab.text !== saved.text : false,
              file: file ?? tab.file,
              version: saved ? saved.version : tab.version,
            }
          : tab,
      ),
    );
  }, []);

  const setSaveState = useCallback((id: string, save: SaveState) => {
    setTabs((current) =>
      current.map((tab) =>
        tab.kind === 'source' && tab.id === id && (tab.save.status !== save.status || tab.save.error !== save.error)
          ? { ...tab, save }
          : tab,
      ),
    );
  }, []);

  const replaceText = useCallback((id: string, text: string, version: number) => {
    setTabs((current) =>
      current.map((tab) =>
        tab.kind === 'source' && tab.id === id
          ? { ...tab, text, version, dirty: false, save: { status: 'saved', error: null } }
          : tab,
      ),
    );
  }, []);

  const reveal = useCallback((id: string, at: RevealAt) => {
    const request = revealAt(at);
    setTabs((current) => current.map((tab) => (tab.kind === 'source' && tab.id === id ? { ...tab, reveal: request } : tab)));
    setActiveId(id);
  }, []);

  const renameFileTabs = useCallback((projectId: number, from: string, to: string) => {
    setTabs((current) =>
      current.map((tab) =>
        tab.kind === 'source' && sameFile(tab.file, { projectId, path: from })
          ? { ...tab, name: to, file: { projectId, path: to }, language: languageOfFile(to) ?? tab.language }
          : tab,
      ),
    );
  }, []);

  const closeFileTabs = useCallback((projectId: number, path?: string) => {
    const gone = (tab: EditorTab) =>
      (tab.kind === 'source' && !!tab.file && tab.file.projectId === projectId && (path === undefined || tab.file.path === path)) ||
      (tab.kind === 'db' && path === undefined && tab.projectId === projectId);
    const current = tabsRef.current;
    if (!current.some(gone)) return;
    const remaining = current.filter((tab) => !gone(tab));
    setTabs(remaining);
    setActiveId((active) => {
      if (active === null || remaining.some((tab) => tab.id === active)) return active;
      const index = current.findIndex((tab) => tab.id === active);
      const before = current.slice(0, index).filter((tab) => !gone(tab));
      return (before.at(-1) ?? remaining[0])?.id ?? null;
    });
  }, []);

  const setMarkers = useCallback((id: string, markers: readonly EditorMarker[]) => {
    setTabs((current) => current.map((tab) => (tab.kind === 'source' && tab.id === id ? { ...tab, markers } : tab)));
  }, []);

  const value = useMemo(
    () => ({
      tabs,
      activeId,
      activate,
      close,
      openStart,
      openSource,
      openDb,
      updateSource,
      markSaved,
      setMarkers,
      setSaveState,
      replaceText,
      reveal,
      renameFileTabs,
      closeFileTabs,
    }),
    [
      tabs,
      activeId,
      activate,
      close,
      openStart,
      openSource,
      openDb,
      updateSource,
      markSaved,
      setMarkers,
      setSaveState,
      replaceText,
      reveal,
      renameFileTabs,
      closeFileTabs,
    ],
  );
  return <EditorTabsContext.Provider value={value}>{children}</EditorTabsContext.Provider>;
}

export function useEditorTabs(): EditorTabsValue {
  const value = useContext(EditorTabsContext);
  if (!value) throw new Error('useEditorTabs needs an <EditorTabsProvider> above it');
  return value;
}
