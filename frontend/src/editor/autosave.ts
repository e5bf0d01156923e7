import { asApiError, type ApiError } from '../api/client';
import type { FileInfo } from '../api/types';
import type { SaveState } from './EditorTabsContext';

/** Quiet time after the last keystroke before a file tab saves itself. */
export const AUTOSAVE_DELAY_MS = 1000;
/** A save that failed for a passing reason (server away) is tried again after this long. */
export const AUTOSAVE_RETRY_MS = 5000;

/** The server refused the save because the file changed since this copy was loaded. */
export function isStaleSave(error: ApiError): boolean {
  return error.status === 409 && error.code === 'API111';
}

/** `current_version` of an API111 answer: the version to overwrite. */
export function currentVersionOf(error: ApiError): number | null {
  const value = error.params.current_version;
  return typeof value === 'number' ? value : null;
}

export interface AutosaverOptions {
  /** The editor's text, and the version of the file it derives from (null: unknown, the first
   * save is then unconditional). */
  text: string;
  version: number | null;
  /** False when `text` is not what the server has (a text opened with changes): it is saved soon. */
  saved?: boolean;
  /** PUTs the text with the version check; throws an ApiError. */
  save: (text: string, baseVersion: number | null, options: { keepalive: boolean }) => Promise<FileInfo>;
  onState: (state: SaveState) => void;
  /** A save went through: the server has `text` at `info.version`. */
  onSaved: (info: FileInfo, text: string) => void;
  delayMs?: number;
  retryMs?: number;
}

/**
 * The autosave of one file tab: saves the newest text `delayMs` after the last change, at
 * once on `flush()` (blur, tab closed, page hidden), one save at a time, with the version the
 * text derives from. A stale version stops the autosave in the `conflict` state until the user
 * chooses: `overwrite()` saves over the newer version, `reloaded()` takes the server's text.
 */
export class Autosaver {
  private readonly options: AutosaverOptions;
  private readonly delay: number;
  private readonly retry: number;
  /** What the server has (as far as this tab knows; null: not known). */
  private savedText: string | null;
  private version: number | null;
  /** The newest text of the editor. */
  private text: string;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private running: Promise<void> | null = null;
  private state: SaveState = { status: 'saved', error: null };
  private disposed = false;

  constructor(options: AutosaverOptions) {
    this.options = options;
    this.delay = options.delayMs ?? AUTOSAVE_DELAY_MS;
    this.retry = options.retryMs ?? AUTOSAVE_RETRY_MS;
    this.savedText = options.saved === false ? null : options.text;
    this.text = options.text;
    this.version = options.version;
    if (this.savedText === null) {
      this.state = { status: 'dirty', error: null };
      this.schedule(this.delay);
    }
  }

  get status(): SaveState['status'] {
    return this.state.status;
  }

  get baseVersion(): number | null {
    return this.version;
  }

  /** The editor's text changed. */
  change(text: string): void {
    if (this.disposed) return;
    this.text = text;
    if (this.state.status === 'conflict') return; // waits for the user's choice
    if (text === this.savedText && !this.running) {
      this.clearTimer();
      this.setState({ status: 'saved', error: null });
      return;
    }
    if (!this.running) this.setState({ status: 'dirty', error: null });
    this.schedule(this.delay);
  }

  /** Saves now if anything is unsaved; resolves when the server has answered. */
  flush(options: { keepalive?: boolean } = {}): Promise<void> {
    this.clearTimer();
    if (this.state.status === 'conflict') return Promise.resolve();
    return this.run(options.keepalive ?? false);
  }

  /** The user chose to keep this text over the newer one on the server. */
  overwrite(): Promise<void> {
    if (this.state.status !== 'conflict') return Promise.resolve();
    const current = this.state.error ? currentVersionOf(this.state.error) : null;
    this.version = current;
    this.setState({ status: 'dirty', error: null });
    return this.run(false);
  }

  /** The user took the server's text (now in the editor), at `version`. */
  reloaded(text: string, version: number): void {
    this.clearTimer();
    this.savedText = text;
    this.text = text;
    this.version = version;
    this.setState({ status: 'saved', error: null });
  }

  /** The server gave the file a new version without changing its text (a rename). */
  rebase(version: number): void {
    this.version = version;
  }

  /** Forgets the unsaved text and stops: the file is gone (deleted). */
  discard(): void {
    this.clearTimer();
    this.savedText = this.text;
    this.disposed = true;
  }

  /** Stops the timers; a pending change is saved once more (the tab closed). */
  dispose(): Promise<void> {
    const done = this.flush({ keepalive: true });
    this.disposed = true;
    this.clearTimer();
    return done;
  }

  private clearTimer(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
  }

  private schedule(delay: number): void {
    this.clearTimer();
    this.timer = setTimeout(() => {
      this.timer = null;
      void this.run(false);
    }, delay);
  }

  private setState(state: SaveState): void {
    if (this.state.status === state.status && this.state.error === state.error) return;
    this.state = state;
    if (!this.disposed) this.options.onState(state);
  }

  private async run(keepalive: boolean): Promise<void> {
    while (this.running) await this.running;
    if (this.text === this.savedText || this.state.status === 'conflict') return;
    const text = this.text;
    this.setState({ status: 'saving', error: null });
    const attempt = this.options.save(text, this.version, { keepalive }).then(
      (info) => {
        this.savedText = text;
        this.version = info.version;
        this.options.onSaved(info, text);
        if (this.text === text) this.setState({ status: 'saved', error: null });
        else {
          this.setState({ status: 'dirty', error: null });
          if (!this.disposed) this.schedule(this.delay);
        }
      },
      (caught: unknown) => {
        const error = asApiError(caught);
        if (isStaleSave(error)) {
          this.clearTimer();
          this.setState({ status: 'conflict', error });
          return;
        }
        this.setState({ status: 'failed', error });
        // The server away or busy: try again later. A refusal (too large, bad name) waits for
        // the next change.
        if (!this.disposed && (error.unreachable || error.status >= 500)) this.schedule(this.retry);
      },
    );
    this.running = attempt;
    try {
      await attempt;
    } finally {
      this.running = null;
    }
  }
}

/** The autosave of every open file tab, by tab id: flushed before a rename and when the page goes. */
const running = new Map<string, { file: () => { projectId: number; path: string } | null; saver: Autosaver }>();

export function registerAutosaver(
  tabId: string,
  file: () => { projectId: number; path: string } | null,
  saver: Autosaver,
): () => void {
  running.set(tabId, { file, saver });
  return () => {
    if (running.get(tabId)?.saver === saver) running.delete(tabId);
  };
}

/** Saves what is unsaved of one file (or of every file of a project) before it is renamed or deleted. */
export async function flushFile(projectId: number, path?: string): Promise<void> {
  const waits = [...running.values()]
    .filter(({ file }) => {
      const ref = file();
      return !!ref && ref.projectId === projectId && (path === undefined || ref.path === path);
    })
    .map(({ saver }) => saver.flush());
  await Promise.all(waits);
}

/** Saves every tab now; `keepalive` lets the requests outlive a page that is being closed. */
export function flushAll(options: { keepalive?: boolean } = {}): Promise<void> {
  return Promise.all([...running.values()].map(({ saver }) => saver.flush(options))).then(() => undefined);
}

/** The file (or every file of a project) was deleted: its tabs stop saving, without a last save. */
export function discardFile(projectId: number, path?: string): void {
  for (const { file, saver } of running.values()) {
    const ref = file();
    if (ref && ref.projectId === projectId && (path === undefined || ref.path === path)) saver.discard();
  }
}

/** The server changed a file's text (a project-wide rename or its undo): its tabs take it. */
export function reloadedFile(projectId: number, path: string, text: string, version: number): void {
  for (const { file, saver } of running.values()) {
    const ref = file();
    if (ref && ref.projectId === projectId && ref.path === path) saver.reloaded(text, version);
  }
}

/** A file was renamed on the server, which counts as a new version of it. */
export function rebaseFile(projectId: number, path: string, version: number): void {
  for (const { file, saver } of running.values()) {
    const ref = file();
    if (ref && ref.projectId === projectId && ref.path === path) saver.rebase(version);
  }
}
