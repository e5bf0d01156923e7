import { useEffect, useSyncExternalStore } from 'react';
import { asApiError, getBlocks, listFiles, type ApiError } from '../api/client';
import type { Diagnostic, FileInfo, ProjectBuild, TreeBlock } from '../api/types';

/**
 * What the server says a project holds: its files, the blocks they compile to and the
 * compiler's diagnostics. One entry per project, shared by the project tree, the editor (go to
 * definition, markers) and the Diagnostics panel.
 *
 * The build comes from `/blocks` when the project is first shown and from `/check` while a file
 * is edited. A file with unsaved changes keeps the diagnostics of its own newest check
 * (`overrides`): a check of another tab's text compiles this file's saved text, which is older
 * than what its editor shows. Once the file is saved, the next build of any file is right for it.
 */
export interface ProjectContents {
  status: 'loading' | 'ready' | 'error';
  files: readonly FileInfo[];
  blocks: readonly TreeBlock[];
  /** Every diagnostic of the project, each file's from its newest check. */
  diagnostics: readonly Diagnostic[];
  error: ApiError | null;
}

interface Entry {
  contents: ProjectContents;
  build: ProjectBuild | null;
  overrides: ReadonlyMap<string, readonly Diagnostic[]>;
  /** Files an editor tab holds with unsaved changes. */
  dirty: ReadonlySet<string>;
  request: AbortController | null;
}

type Listener = () => void;

const EMPTY: readonly never[] = [];

/** How long after a change the contents are read again (see `reloadSoon`). */
export const RELOAD_DELAY_MS = 300;

function byName(a: FileInfo, b: FileInfo): number {
  return a.name.localeCompare(b.name, undefined, { sensitivity: 'base', numeric: true });
}

function merged(build: ProjectBuild | null, overrides: ReadonlyMap<string, readonly Diagnostic[]>): Diagnostic[] {
  const base = (build?.diagnostics ?? []).filter((d) => !d.span?.file || !overrides.has(d.span.file));
  return [...base, ...[...overrides.values()].flat()];
}

/** The overrides of files an editor still holds unsaved (the same map when none went). */
function unsavedOnly(entry: Entry): ReadonlyMap<string, readonly Diagnostic[]> {
  const kept = [...entry.overrides].filter(([name]) => entry.dirty.has(name));
  return kept.length === entry.overrides.size ? entry.overrides : new Map(kept);
}

export interface ProjectContentsStore {
  get: (projectId: number) => ProjectContents | undefined;
  /** Loads the project's files and blocks unless they are loaded or loading. */
  ensure: (projectId: number) => void;
  /** Loads them again (the old contents stay shown meanwhile). */
  reload: (projectId: number) => Promise<void>;
  /**
   * Loads them again shortly after a change was made (create, rename, delete). The server answers
   * such a request before its transaction is committed (the session dependency closes after the
   * response), so a list read at once may not show the change yet; the local update shows it
   * meanwhile.
   */
  reloadSoon: (projectId: number) => void;
  /** A build from `/check` of `file`'s unsaved text (or from `/blocks` when `file` is null). */
  applyBuild: (projectId: number, build: ProjectBuild, file?: string | null) => void;
  /** Whether an editor tab holds the file with unsaved changes. */
  setFileDirty: (projectId: number, file: string, dirty: boolean) => void;
  /** The file's own check no longer applies (its tab closed): the project's build counts again. */
  dropOverride: (projectId: number, file: string) => void;
  /** A file was saved, created or renamed: its row in the list, without asking the server. */
  putFile: (projectId: number, info: FileInfo, previousName?: string) => void;
  removeFile: (projectId: number, name: string) => void;
  forget: (projectId: number) => void;
  /** Forgets every project (tests start from an empty store). */
  clear: () => void;
  subscribe: (listener: Listener) => () => void;
  /** Grows with every change: a snapshot for views that read several projects. */
  version: () => number;
}

export function createProjectContentsStore(
  api: { listFiles: typeof listFiles; getBlocks: typeof getBlocks } = { listFiles, getBlocks },
): ProjectContentsStore {
  const entries = new Map<number, Entry>();
  const soon = new Map<number, ReturnType<typeof setTimeout>>();
  const listeners = new Set<Listener>();
  let version = 0;
  const notify = () => {
    version += 1;
    listeners.forEach((listener) => listener());
  };

  function update(projectId: number, change: (entry: Entry) => Partial<Entry>, contents?: Partial<ProjectContents>) {
    const entry = entries.get(projectId);
    if (!entry) return;
    const next = { ...entry, ...change(entry) };
    next.contents = {
      ...entry.contents,
      blocks: next.build?.blocks ?? entry.contents.blocks,
      diagnostics: next.build === entry.build && next.overrides === entry.overrides ? entry.contents.diagnostics : merged(next.build, next.overrides),
      ...contents,
    };
    entries.set(projectId, next);
    notify();
  }

  function load(projectId: number): Promise<void> {
    const previous = entries.get(projectId);
    previous?.request?.abort();
    const request = new AbortController();
    const contents: ProjectContents = previous
      ? { ...previous.contents, status: previous.contents.status === 'error' ? 'loading' : previous.contents.status }
      : { status: 'loading', files: EMPTY, blocks: EMPTY, diagnostics: EMPTY, error: null };
    entries.set(projectId, {
      contents,
      build: previous?.build ?? null,
      overrides: previous?.overrides ?? new Map(),
      dirty: previous?.dirty ?? new Set(),
      request,
    });
    notify();
    return Promise.all([api.listFiles(projectId, request.signal), api.getBlocks(projectId, request.signal)]).then(
      ([files, build]) => {
        if (request.signal.aborted) return;
        // The build compiled the saved texts: it replaces the own checks of files saved since.
        update(projectId, (entry) => ({ build, request: null, overrides: unsavedOnly(entry) }), {
          status: 'ready',
          files: [...files].sort(byName),
          error: null,
        });
      },
      (error: unknown) => {
        if (request.signal.aborted) return;
        update(projectId, () => ({ request: null }), { status: 'error', error: asApiError(error) });
      },
    );
  }

  return {
    get: (projectId) => entries.get(projectId)?.contents,
    ensure: (projectId) => {
      if (!entries.has(projectId)) void load(projectId);
    },
    reload: load,
    reloadSoon: (projectId) => {
      clearTimeout(soon.get(projectId));
      soon.set(
        projectId,
        setTimeout(() => {
          soon.delete(projectId);
          if (entries.has(projectId)) void load(projectId);
        }, RELOAD_DELAY_MS),
      );
    },
    applyBuild: (projectId, build, file = null) =>
      update(projectId, (entry) => {
        // The build compiled every other file's saved text: right for those without changes.
        const overrides = new Map([...entry.overrides].filter(([name]) => name !== file && entry.dirty.has(name)));
        if (file && entry.dirty.has(file)) {
          overrides.set(
            file,
            build.diagnostics.filter((d) => d.span?.file === file),
          );
        }
        return { build, overrides };
      }),
    setFileDirty: (projectId, file, dirty) => {
      const entry = entries.get(projectId);
      if (!entry || entry.dirty.has(file) === dirty) return;
      const next = new Set(entry.dirty);
      if (dirty) next.add(file);
      else next.delete(file);
      entries.set(projectId, { ...entry, dirty: next });
    },
    dropOverride: (projectId, file) =>
      update(projectId, (entry) => {
        if (!entry.overrides.has(file)) return {};
        const overrides = new Map(entry.overrides);
        overrides.delete(file);
        return { overrides };
      }),
    putFile: (projectId, info, previousName) =>
      update(
        projectId,
        (entry) => {
          if (!previousName || previousName === info.name || !entry.build) return {};
          // A rename: the blocks and diagnostics of the file move with it.
          const moved = <T extends { file?: string | null }>(item: T): T =>
            item.file === previousName ? { ...item, file: info.name } : item;
          return {
            build: {
              blocks: entry.build.blocks.map(moved),
              diagnostics: entry.build.diagnostics.map((d) => (d.span ? { ...d, span: moved(d.span) } : d)),
            },
          };
        },
        (() => {
          const files = entries.get(projectId)?.contents.files ?? [];
          const others = files.filter((file) => file.name !== info.name && file.name !== previousName);
          return { files: [...others, info].sort(byName) };
        })(),
      ),
    removeFile: (projectId, name) =>
      update(
        projectId,
        (entry) => {
          const overrides = new Map(entry.overrides);
          overrides.delete(name);
          const build = entry.build && {
            blocks: entry.build.blocks.filter((block) => block.file !== name),
            diagnostics: entry.build.diagnostics.filter((d) => d.span?.file !== name),
          };
          return { overrides, build };
        },
        { files: (entries.get(projectId)?.contents.files ?? []).filter((file) => file.name !== name) },
      ),
    forget: (projectId) => {
      clearTimeout(soon.get(projectId));
      soon.delete(projectId);
      entries.get(projectId)?.request?.abort();
      if (entries.delete(projectId)) notify();
    },
    clear: () => {
      for (const timer of soon.values()) clearTimeout(timer);
      soon.clear();
      for (const entry of entries.values()) entry.request?.abort();
      entries.clear();
      notify();
    },
    subscribe: (listener) => {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    version: () => version,
  };
}

/** The application's one store of project contents. */
export const projectContents = createProjectContentsStore();

/**
 * The contents of a project, loaded on first use; undefined for no project (or before the
 * first render's effect has started the load).
 */
export function useProjectContents(
  projectId: number | null,
  store: ProjectContentsStore = projectContents,
): ProjectContents | undefined {
  useEffect(() => {
    if (projectId !== null) store.ensure(projectId);
  }, [projectId, store]);
  return useSyncExternalStore(
    store.subscribe,
    () => (projectId === null ? undefined : store.get(projectId)),
    () => undefined,
  );
}
