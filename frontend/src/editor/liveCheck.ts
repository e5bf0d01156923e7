import type { ProjectBuild } from '../api/types';

/** Quiet time after the last keystroke before the text is compiled for its diagnostics. */
export const CHECK_DELAY_MS = 400;

export interface LiveCheckOptions {
  /** POSTs the text to `/check`; throws on failure (an AbortError when cancelled). */
  check: (text: string, signal: AbortSignal) => Promise<ProjectBuild>;
  onResult: (build: ProjectBuild, text: string) => void;
  delayMs?: number;
}

/**
 * Diagnostics while typing: compiles the newest text `delayMs` after the last change. A newer
 * text cancels the check of an older one, so a slow answer never replaces a newer one. A failed
 * check keeps the markers there are (the autosave reports an unreachable server).
 */
export class LiveCheck {
  private readonly options: LiveCheckOptions;
  private readonly delay: number;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private request: AbortController | null = null;
  private lastChecked: string | null = null;
  /** The text of the check on its way (a change back to it need not check again). */
  private checking: string | null = null;

  constructor(options: LiveCheckOptions) {
    this.options = options;
    this.delay = options.delayMs ?? CHECK_DELAY_MS;
  }

  /** The text changed (or was opened: `immediately`). */
  change(text: string, immediately = false): void {
    this.clearTimer();
    if (!immediately && (this.request ? text === this.checking : text === this.lastChecked)) return;
    this.request?.abort();
    this.request = null;
    if (immediately) this.run(text);
    else this.timer = setTimeout(() => this.run(text), this.delay);
  }

  dispose(): void {
    this.clearTimer();
    this.request?.abort();
    this.request = null;
  }

  private clearTimer(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
  }

  private run(text: string): void {
    this.timer = null;
    const request = new AbortController();
    this.request = request;
    this.checking = text;
    this.options.check(text, request.signal).then(
      (build) => {
        if (request.signal.aborted) return;
        this.request = null;
        this.lastChecked = text;
        this.options.onResult(build, text);
      },
      () => {
        if (this.request === request) this.request = null;
      },
    );
  }
}
