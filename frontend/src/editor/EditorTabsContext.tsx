import { createContext, useCallback, useContext, useMemo, useRef, useState, type ReactNode } from 'react';
import type { EditorMarker, SourceLanguage } from './CodeEditor';

/** What an editor tab shows. LAD/FBD and Graph editors join this list later. */
export type EditorTabKind = 'start' | 'source';

export interface StartTab {
  id: 'start';
  kind: 'start';
}

/** Where a source tab's text lives on the server; none while it exists only in the browser. */
export interface SourceFileRef {
  projectId: number;
  path: string;
}

/** An STL or SCL text in a Monaco editor. */
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
}

export type EditorTab = StartTab | SourceTab;

export interface NewSource {
  name: string;
  language: SourceLanguage;
  text: string;
  file?: SourceFileRef | null;
  /** A new text that exists nowhere else starts dirty; a text just read from a file does not. */
  dirty?: boolean;
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
  /** The text of a source tab changed in its editor: it becomes dirty. */
  updateSource: (id: string, text: string) => void;
  /** The text of a source tab was saved (as `file`, when given). */
  markSaved: (id: string, file?: SourceFileRef) => void;
  /** The problems the compiler found in a source tab's text. */
  setMarkers: (id: string, markers: readonly EditorMarker[]) => void;
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

  const openSource = useCallback((source: NewSource) => {
    const existing = tabsRef.current.find((tab) => tab.kind === 'source' && sameFile(tab.file, source.file));
    if (existing) {
      setActiveId(existing.id);
      return existing.id;
    }
    const id = `source-${nextId.current++}`;
    const tab: SourceTab = {
      id,
      kind: 'source',
      name: source.name,
      language: source.language,
      text: source.text,
      dirty: source.dirty ?? !source.file,
      file: source.file ?? null,
      markers: [],
    };
    setTabs((current) => [...current, tab]);
    setActiveId(id);
    return id;
  }, []);

  const updateSource = useCallback((id: string, text: string) => {
    setTabs((current) =>
      current.map((tab) => (tab.kind === 'source' && tab.id === id && tab.text !== text ? { ...tab, text, dirty: true } : tab)),
    );
  }, []);

  const markSaved = useCallback((id: string, file?: SourceFileRef) => {
    setTabs((current) =>
      current.map((tab) =>
        tab.kind === 'source' && tab.id === id ? { ...tab, dirty: false, file: file ?? tab.file } : tab,
      ),
    );
  }, []);

  const setMarkers = useCallback((id: string, markers: readonly EditorMarker[]) => {
    setTabs((current) => current.map((tab) => (tab.kind === 'source' && tab.id === id ? { ...tab, markers } : tab)));
  }, []);

  const value = useMemo(
    () => ({ tabs, activeId, activate, close, openStart, openSource, updateSource, markSaved, setMarkers }),
    [tabs, activeId, activate, close, openStart, openSource, updateSource, markSaved, setMarkers],
  );
  return <EditorTabsContext.Provider value={value}>{children}</EditorTabsContext.Provider>;
}

export function useEditorTabs(): EditorTabsValue {
  const value = useContext(EditorTabsContext);
  if (!value) throw new Error('useEditorTabs needs an <EditorTabsProvider> above it');
  return value;
}
