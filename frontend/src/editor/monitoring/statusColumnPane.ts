/**
 * Draws the STL status rows beside the editor's lines. Only the lines in view get a row, and the
 * row elements are reused from frame to frame (a cell's text is written only when it changed),
 * so a 500-network block costs what its visible lines cost, at 30 frames a second.
 */
import { STATUS_COLUMNS, type StatusRow } from './statusColumns';

/** What the pane needs to know of the editor (Monaco's editor has these methods). */
export interface LineGeometry {
  getScrollTop(): number;
  getTopForLineNumber(line: number): number;
  getVisibleRanges(): ReadonlyArray<{ startLineNumber: number; endLineNumber: number }>;
}

/** The lines in view, first to last (several ranges when code is folded). */
export function visibleLines(geometry: LineGeometry): { first: number; last: number } | null {
  const ranges = geometry.getVisibleRanges();
  if (ranges.length === 0) return null;
  let first = Infinity;
  let last = -Infinity;
  for (const range of ranges) {
    first = Math.min(first, range.startLineNumber);
    last = Math.max(last, range.endLineNumber);
  }
  return { first, last };
}

export class StatusColumnPane {
  private readonly pool: HTMLDivElement[] = [];

  constructor(
    private readonly body: HTMLElement,
    private readonly lineHeight: number,
  ) {}

  private rowElement(index: number): HTMLDivElement {
    let element = this.pool[index];
    if (!element) {
      element = document.createElement('div');
      element.className = 'stl-status__row';
      element.style.height = `${this.lineHeight}px`;
      for (const column of STATUS_COLUMNS) {
        const cell = document.createElement('span');
        cell.className = `stl-status__cell stl-status__cell--${column.id}`;
        cell.dataset.column = column.id;
        element.appendChild(cell);
      }
      this.body.appendChild(element);
      this.pool[index] = element;
    }
    return element;
  }

  /** Shows the rows of the visible lines at their lines' heights; hides the rest. */
  render(rows: ReadonlyMap<number, StatusRow>, geometry: LineGeometry): number {
    const shown = visibleLines(geometry);
    let used = 0;
    if (shown && rows.size > 0) {
      const scrollTop = geometry.getScrollTop();
      for (let line = shown.first; line <= shown.last; line += 1) {
        const row = rows.get(line);
        if (!row) continue;
        const element = this.rowElement(used);
        used += 1;
        element.hidden = false;
        element.dataset.line = String(line);
        element.style.transform = `translateY(${geometry.getTopForLineNumber(line) - scrollTop}px)`;
        STATUS_COLUMNS.forEach((column, i) => {
          const cell = element.children[i] as HTMLElement;
          const text = row[column.id];
          if (cell.textContent !== text) cell.textContent = text;
        });
      }
    }
    for (let i = used; i < this.pool.length; i += 1) {
      const element = this.pool[i]!;
      if (!element.hidden) element.hidden = true;
    }
    return used;
  }

  /** Removes every row (the pane closes). */
  clear(): void {
    for (const element of this.pool) element.remove();
    this.pool.length = 0;
  }
}
