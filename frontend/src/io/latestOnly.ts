/**
 * Sends the values of a control that changes faster than the server answers (a slider being
 * dragged): one command at a time, and of the values that came meanwhile only the last one, so the
 * socket is never flooded and the value that stays is the one the user let go at.
 */
export class LatestOnly<T> {
  private busy = false;
  private pending: { value: T } | null = null;

  constructor(private readonly send: (value: T) => Promise<unknown>) {}

  push(value: T): void {
    if (this.busy) {
      this.pending = { value };
      return;
    }
    this.busy = true;
    void this.run(value);
  }

  private async run(value: T): Promise<void> {
    try {
      await this.send(value);
    } catch {
      // The caller's send reports its own failures; the next value is still sent.
    }
    const next = this.pending;
    this.pending = null;
    if (next) void this.run(next.value);
    else this.busy = false;
  }
}
