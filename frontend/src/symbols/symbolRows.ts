/**
 * The symbol table editor's rows in the browser: each with an id that outlives sorting and
 * deleting, so problems and the keyboard focus stay on their row. Sorting reorders the table
 * itself (it is saved in that order, as STEP 7's symbol editor does); filtering only hides rows.
 */
import type { RowProblem, SymbolField, SymbolRow } from '../api/symbols';

export interface GridRow extends SymbolRow {
  id: number;
}

export type SortDirection = 'asc' | 'desc';

let nextRowId = 1;

export function withIds(rows: readonly SymbolRow[]): GridRow[] {
  return rows.map((row) => ({ id: nextRowId++, name: row.name, address: row.address, type: row.type, comment: row.comment }));
}

export function emptyRow(): GridRow {
  return { id: nextRowId++, name: '', address: '', type: '', comment: '' };
}

/** What is saved: the four fields, in order (the ids stay in the browser). */
export function plainRows(rows: readonly GridRow[]): SymbolRow[] {
  return rows.map(({ name, address, type, comment }) => ({ name, address, type, comment }));
}

/** The rows' text for the autosave: it saves when this changes. */
export function rowsText(rows: readonly GridRow[]): string {
  return JSON.stringify(plainRows(rows));
}

export function updateCell(rows: readonly GridRow[], id: number, field: SymbolField, value: string): GridRow[] {
  return rows.map((row) => (row.id === id ? { ...row, [field]: value } : row));
}

const collator = new Intl.Collator('en', { numeric: true, sensitivity: 'base' });

/** Addresses sort by area, then numerically (`I 0.1` before `I 1.0` before `Q 0.0`). */
function addressKey(address: string): string {
  const compact = address.replace(/\s+/g, ' ').trim().toUpperCase();
  return compact.replace(/\d+/g, (digits) => digits.padStart(6, '0'));
}

export function sortRows(rows: readonly GridRow[], field: SymbolField, direction: SortDirection): GridRow[] {
  const sign = direction === 'asc' ? 1 : -1;
  const key = field === 'address' ? (row: GridRow) => addressKey(row.address) : (row: GridRow) => row[field];
  return [...rows].sort((a, b) => sign * collator.compare(key(a), key(b)));
}

/** The rows whose name, address, type or comment contains `filter` (any case). */
export function filterRows(rows: readonly GridRow[], filter: string): GridRow[] {
  const wanted = filter.trim().toLowerCase();
  if (!wanted) return [...rows];
  return rows.filter((row) =>
    [row.name, row.address, row.type, row.comment].some((value) => value.toLowerCase().includes(wanted)),
  );
}

export type ProblemsById = Map<number, RowProblem[]>;

/** The server's problems (by row index of the rows it checked) by row id. */
export function problemsById(problems: readonly RowProblem[], checked: readonly GridRow[]): ProblemsById {
  const found: ProblemsById = new Map();
  for (const problem of problems) {
    const row = checked[problem.row];
    if (!row) continue;
    const list = found.get(row.id) ?? [];
    list.push(problem);
    found.set(row.id, list);
  }
  return found;
}
