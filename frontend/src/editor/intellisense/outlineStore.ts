/**
 * The outline of each project the editor has asked about (`GET /outline`): symbols, blocks and
 * members for completion, hover and go to definition. Providers read it synchronously (`get`);
 * the first read starts the load. It follows the project's saved files: `projectContents` tells of
 * every change, and when a project's list of files (names and save counts) differs from the one
 * the outline was loaded for, it is loaded again (shortly, so that a burst of saves loads once).
 */
import { getOutline, type ProjectOutline } from '../../api/outline';
import { projectContents, type ProjectContentsStore } from '../../projects/projectContents';

/** How long after a change of the files the outline is read again. */
export const OUTLINE_RELOAD_MS = 400;

interface Entry {
  outline: ProjectOutline | null;
  /** The files (name@version) the loaded or loading outline is for. */
  files: string;
  request: AbortController | null;
  /** The load under way. */
  pending: Promise<void> | null;
  timer: ReturnType<typeof setTimeout> | null;
}

export interface OutlineStore {
  /** The outline, if loaded; starts loading it the first time. */
  get: (projectId: number) => ProjectOutline | null;
  /** The outline once the load under way (or a first one) has ended; null if it failed. */
  ready: (projectId: number) => Promise<ProjectOutline | null>;
  /** Loads it now (again). */
  load: (projectId: number) => Promise<void>;
  subscribe: (listener: () => void) => () => void;
  /** Forgets everything (tests). */
  clear: () => void;
}

export function createOutlineStore(
  api: { getOutline: typeof getOutline } = { getOutline },
  contents: ProjectContentsStore = projectContents,
): OutlineStore {
  const entries = new Map<number, Entry>();
  const listeners = new Set<() => void>();
  const notify = () => listeners.forEach((listener) => listener());

  const filesOf = (projectId: number): string =>
    (contents.get(projectId)?.files ?? []).map((file) => `${file.name}@${file.version}`).join('\n');

  function load(projectId: number): Promise<void> {
    const entry = entries.get(projectId) ?? { outline: null, files: '', request: null, pending: null, timer: null };
    entry.request?.abort();
    if (entry.timer !== null) clearTimeout(entry.timer);
    const request = new AbortController();
    const pending = api.getOutline(projectId, request.signal).then(
      (outline) => {
        const current = entries.get(projectId);
        if (request.signal.aborted || !current) return;
        entries.set(projectId, { ...current, outline, request: null, pending: null });
        notify();
      },
      () => {
        const current = entries.get(projectId);
        if (current && current.request === request) entries.set(projectId, { ...current, request: null, pending: null });
      },
    );
    entries.set(projectId, { ...entry, files: filesOf(projectId), request, pending, timer: null });
    return pending;
  }

  contents.subscribe(() => {
    for (const [projectId, entry] of entries) {
      if (!contents.get(projectId)) continue;
      if (filesOf(projectId) === entry.files || entry.timer !== null) continue;
      const timer = setTimeout(() => void load(projectId), OUTLINE_RELOAD_MS);
      entries.set(projectId, { ...entry, timer });
    }
  });

  return {
    get: (projectId) => {
      const entry = entries.get(projectId);
      if (!entry) {
        void load(projectId);
        return null;
      }
      return entry.outline;
    },
    ready: async (projectId) => {
      const entry = entries.get(projectId);
      if (!entry) await load(projectId);
      else if (entry.pending && !entry.outline) await entry.pending;
      return entries.get(projectId)?.outline ?? null;
    },
    load,
    subscribe: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    clear: () => {
      for (const entry of entries.values()) {
        entry.request?.abort();
        if (entry.timer !== null) clearTimeout(entry.timer);
      }
      entries.clear();
    },
  };
}

/** The application's one outline store. */
export const outlines = createOutlineStore();
