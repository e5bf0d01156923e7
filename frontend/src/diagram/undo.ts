/**
 * The undo/redo history of a diagram editor: whole snapshots of its (immutable) model, so an
 * undo is exact whatever the edit was and costs only what the edit changed (the snapshots share
 * every untouched subtree). Every graphical editor (LAD, FBD, Graph) keeps one of these; none
 * keeps its own stack.
 *
 * The history belongs to the open editor, not to the file: an autosave does not clear it, so
 * Ctrl+Z after a save still undoes (the undone model is then saved again).
 */

/** How many steps back the history reaches; older ones are dropped. */
export const UNDO_DEPTH = 200;

export interface UndoEntry<T> {
  state: T;
  /** What the edit that led to `state` was ("Insert contact"), for the menu's tooltip. */
  label: string;
}

export class UndoHistory<T> {
  private past: UndoEntry<T>[] = [];
  private future: UndoEntry<T>[] = [];
  private current: UndoEntry<T>;
  private readonly depth: number;

  constructor(initial: T, depth = UNDO_DEPTH) {
    this.current = { state: initial, label: '' };
    this.depth = depth;
  }

  get state(): T {
    return this.current.state;
  }

  get canUndo(): boolean {
    return this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** The label of the edit an undo would take back. */
  get undoLabel(): string | null {
    return this.past.length > 0 ? this.current.label : null;
  }

  /** The label of the edit a redo would make again. */
  get redoLabel(): string | null {
    return this.future[this.future.length - 1]?.label ?? null;
  }

  /** A new edit: it becomes the state, and what had been undone can no longer be redone. */
  push(state: T, label: string): void {
    if (Object.is(state, this.current.state)) return;
    this.past.push(this.current);
    if (this.past.length > this.depth) this.past.splice(0, this.past.length - this.depth);
    this.current = { state, label };
    this.future = [];
  }

  /** Steps back; the state before, or null when there is nothing to undo. */
  undo(): T | null {
    const previous = this.past.pop();
    if (!previous) return null;
    this.future.push(this.current);
    this.current = previous;
    return previous.state;
  }

  /** Steps forward again; null when nothing was undone. */
  redo(): T | null {
    const next = this.future.pop();
    if (!next) return null;
    this.past.push(this.current);
    this.current = next;
    return next.state;
  }

  /**
   * The state changed outside the editor (the text view, a reload after a conflict): it is a
   * step of its own, so it can be undone like an edit.
   */
  replace(state: T, label: string): void {
    this.push(state, label);
  }
}
