import { useEffect, useLayoutEffect, useRef, useState, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { SYMBOL_FIELDS, type SymbolField } from '../api/symbols';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import type { GridRow, ProblemsById, SortDirection } from './symbolRows';

/** Height of one grid row in pixels: the grid renders only the rows in view (and a few more). */
export const ROW_HEIGHT = 28;
const OVERSCAN = 10;
/** What the grid assumes before it is laid out (and in tests, where nothing is). */
const FALLBACK_HEIGHT = 560;

export interface Cell {
  /** Index in the shown rows; `rows.length` is the empty row that adds a symbol. */
  row: number;
  col: number;
}

export interface SymbolGridProps {
  rows: readonly GridRow[];
  problems: ProblemsById;
  sort: { field: SymbolField; direction: SortDirection } | null;
  selected: ReadonlySet<number>;
  onChange: (id: number, field: SymbolField, value: string) => void;
  /** Typing into the empty last row: a new row with that value; its id. */
  onAdd: (field: SymbolField, value: string) => number;
  onDelete: (ids: number[]) => void;
  onSort: (field: SymbolField) => void;
  onSelect: (id: number, selected: boolean) => void;
  onActiveRow: (id: number | null) => void;
  /** A row to make active (its name cell), once per `seq`: F12 on a symbol. */
  focusRow?: { id: number; seq: number } | null;
  /** Whether the grid is on screen (a hidden grid cannot take the focus yet). */
  visible?: boolean;
}

/**
 * Where Tab (or Shift+Tab) goes from `cell`, as in a spreadsheet: the next (previous) column, from
 * the last column to the first of the next row (from the first to the last of the row before).
 * Null past the grid's first or last cell: the focus then leaves the grid as usual.
 */
export function tabTarget(cell: Cell, backwards: boolean, rowCount: number): Cell | null {
  const last = SYMBOL_FIELDS.length - 1;
  if (backwards) {
    if (cell.col > 0) return { row: cell.row, col: cell.col - 1 };
    return cell.row > 0 ? { row: cell.row - 1, col: last } : null;
  }
  if (cell.col < last) return { row: cell.row, col: cell.col + 1 };
  return cell.row < rowCount - 1 ? { row: cell.row + 1, col: 0 } : null;
}

/**
 * The symbol rows as a keyboard grid of text fields: arrows move between cells (left and right
 * at the text's ends), Tab and Shift+Tab to the next and previous cell, Enter moves down, Page Up/Down by a page, Ctrl+Home/End to the first or
 * last row, Escape undoes the cell's edit, Ctrl+Delete deletes the row. Addresses and names are
 * data: the grid is left-to-right in every interface language.
 */
export function SymbolGrid(props: SymbolGridProps) {
  const { rows, problems, sort, selected, onChange, onAdd, onDelete, onSort, onSelect, onActiveRow, focusRow, visible = true } = props;
  const { t } = useTranslation();
  const message = useDiagnosticMessage();
  const scroller = useRef<HTMLDivElement>(null);
  const [scrollTop, setScrollTop] = useState(0);
  const [height, setHeight] = useState(FALLBACK_HEIGHT);
  const [active, setActive] = useState<Cell | null>(null);
  const focusWanted = useRef(false);
  const before = useRef('');

  useLayoutEffect(() => {
    const element = scroller.current;
    if (!element) return;
    const measure = () => setHeight(element.clientHeight || FALLBACK_HEIGHT);
    measure();
    if (typeof ResizeObserver === 'undefined') return;
    const observer = new ResizeObserver(measure);
    observer.observe(element);
    return () => observer.disconnect();
  }, []);

  const total = rows.length + 1; // the empty row that adds
  const first = Math.max(0, Math.floor(scrollTop / ROW_HEIGHT) - OVERSCAN);
  const last = Math.min(total, Math.ceil((scrollTop + height) / ROW_HEIGHT) + OVERSCAN);

  const activeId = active && active.row < rows.length ? rows[active.row]!.id : null;
  useEffect(() => onActiveRow(activeId), [activeId, onActiveRow]);

  // Moves the focus to the active cell once it is rendered (after scrolling it into view).
  useEffect(() => {
    if (!focusWanted.current || !active) return;
    const input = scroller.current?.querySelector<HTMLInputElement>(
      `input[data-row="${active.row}"][data-col="${active.col}"]`,
    );
    if (input) {
      focusWanted.current = false;
      if (document.activeElement !== input) {
        input.focus();
        input.setSelectionRange(input.value.length, input.value.length);
      }
    }
  });

  const focusSeq = focusRow?.seq ?? 0;
  useEffect(() => {
    if (!focusRow || !visible) return;
    const index = rows.findIndex((row) => row.id === focusRow.id);
    if (index >= 0) moveTo({ row: index, col: 0 });
    // Once per request, when the grid is shown.
  }, [focusSeq, visible]);

  const moveTo = (cell: Cell) => {
    const row = Math.max(0, Math.min(total - 1, cell.row));
    const col = Math.max(0, Math.min(SYMBOL_FIELDS.length - 1, cell.col));
    setActive({ row, col });
    focusWanted.current = true;
    const element = scroller.current;
    if (element) {
      const top = row * ROW_HEIGHT;
      const bodyHeight = Math.max(ROW_HEIGHT, (element.clientHeight || height) - ROW_HEIGHT);
      if (top < element.scrollTop) element.scrollTop = top;
      else if (top + ROW_HEIGHT > element.scrollTop + bodyHeight) element.scrollTop = top + ROW_HEIGHT - bodyHeight;
      setScrollTop(element.scrollTop);
    }
  };

  const onKey = (event: KeyboardEvent<HTMLInputElement>, cell: Cell) => {
    const input = event.currentTarget;
    const page = Math.max(1, Math.floor(height / ROW_HEIGHT) - 1);
    const atStart = input.selectionStart === 0 && input.selectionEnd === 0;
    const atEnd = input.selectionStart === input.value.length && input.selectionEnd === input.value.length;
    const ctrl = event.ctrlKey || event.metaKey;
    let next: Cell | null = null;
    if (event.key === 'ArrowDown' || (event.key === 'Enter' && !event.shiftKey)) next = { row: cell.row + 1, col: cell.col };
    else if (event.key === 'ArrowUp' || (event.key === 'Enter' && event.shiftKey)) next = { row: cell.row - 1, col: cell.col };
    else if (event.key === 'ArrowLeft' && atStart && cell.col > 0) next = { row: cell.row, col: cell.col - 1 };
    else if (event.key === 'ArrowRight' && atEnd && cell.col < SYMBOL_FIELDS.length - 1) next = { row: cell.row, col: cell.col + 1 };
    else if (event.key === 'Tab' && !ctrl && !event.altKey) next = tabTarget(cell, event.shiftKey, total);
    else if (event.key === 'PageDown') next = { row: cell.row + page, col: cell.col };
    else if (event.key === 'PageUp') next = { row: cell.row - page, col: cell.col };
    else if (ctrl && event.key === 'Home') next = { row: 0, col: cell.col };
    else if (ctrl && event.key === 'End') next = { row: total - 1, col: cell.col };
    else if (event.key === 'Escape' && cell.row < rows.length) {
      const row = rows[cell.row]!;
      onChange(row.id, SYMBOL_FIELDS[cell.col]!, before.current);
      event.preventDefault();
      return;
    } else if (ctrl && event.key === 'Delete' && cell.row < rows.length) {
      onDelete([rows[cell.row]!.id]);
      event.preventDefault();
      moveTo({ row: Math.min(cell.row, rows.length - 1), col: cell.col });
      return;
    }
    if (next) {
      event.preventDefault();
      moveTo(next);
    }
  };

  const shown = [];
  for (let index = first; index < last; index++) {
    const row = index < rows.length ? rows[index]! : null;
    const rowProblems = row ? (problems.get(row.id) ?? []) : [];
    const worst = rowProblems.some((item) => item.problem.severity === 'error')
      ? 'error'
      : rowProblems.length > 0
        ? 'warning'
        : null;
    shown.push(
      <div
        key={row ? row.id : 'new'}
        role="row"
        aria-rowindex={index + 2}
        aria-selected={active?.row === index}
        className={`symbol-grid__row${row ? '' : ' symbol-grid__row--new'}${worst ? ` symbol-grid__row--${worst}` : ''}${active?.row === index ? ' symbol-grid__row--active' : ''}`}
        style={{ top: (index + 1) * ROW_HEIGHT, height: ROW_HEIGHT }}
        data-testid={row ? 'symbol-row' : 'symbol-row-new'}
        data-name={row?.name}
      >
        <div role="gridcell" className="symbol-grid__select">
          {row ? (
            <input
              type="checkbox"
              checked={selected.has(row.id)}
              aria-label={t('symbolTable.selectRow', { row: index + 1 })}
              onChange={(event) => onSelect(row.id, event.target.checked)}
              tabIndex={-1}
            />
          ) : null}
        </div>
        {SYMBOL_FIELDS.map((field, col) => {
          const cellProblems = rowProblems.filter((item) => item.field === field);
          const isActive = active?.row === index && active.col === col;
          const invalid = cellProblems.length > 0;
          const problemText = cellProblems.map((item) => `${item.problem.code} ${message(item.problem)}`).join('\n');
          return (
            <div
              key={field}
              role="gridcell"
              className={`symbol-grid__cell symbol-grid__cell--${field}${invalid ? ` symbol-grid__cell--${cellProblems.some((item) => item.problem.severity === 'error') ? 'error' : 'warning'}` : ''}`}
              title={problemText || undefined}
            >
              <input
                className="symbol-grid__input"
                dir="ltr"
                spellCheck={false}
                autoComplete="off"
                value={row ? row[field] : ''}
                placeholder={!row && col === 0 ? t('symbolTable.newRowHint') : undefined}
                aria-label={`${t(`symbolTable.columns.${field}`)} ${index + 1}`}
                aria-invalid={invalid || undefined}
                data-row={index}
                data-col={col}
                data-testid={`symbol-cell-${field}`}
                tabIndex={isActive || (!active && index === 0 && col === 0) ? 0 : -1}
                onFocus={(event) => {
                  before.current = event.currentTarget.value;
                  if (!isActive) setActive({ row: index, col });
                }}
                onKeyDown={(event) => onKey(event, { row: index, col })}
                onChange={(event) => {
                  const value = event.target.value;
                  if (row) onChange(row.id, field, value);
                  else if (value !== '') {
                    onAdd(field, value);
                    focusWanted.current = true;
                  }
                }}
              />
            </div>
          );
        })}
      </div>,
    );
  }

  return (
    <div
      className="symbol-grid"
      ref={scroller}
      dir="ltr"
      role="grid"
      aria-rowcount={total + 1}
      aria-colcount={SYMBOL_FIELDS.length + 1}
      aria-label={t('symbolTable.gridLabel')}
      data-testid="symbol-grid"
      onScroll={(event) => setScrollTop(event.currentTarget.scrollTop)}
    >
      <div className="symbol-grid__canvas" role="rowgroup" style={{ height: (total + 1) * ROW_HEIGHT }}>
        <div role="row" aria-rowindex={1} className="symbol-grid__row symbol-grid__row--head" style={{ top: 0, height: ROW_HEIGHT }}>
          <div role="columnheader" className="symbol-grid__select">
            <span className="visually-hidden">{t('symbolTable.columns.select')}</span>
          </div>
          {SYMBOL_FIELDS.map((field) => {
            const sorted = sort?.field === field ? sort.direction : null;
            return (
              <div
                key={field}
                role="columnheader"
                className={`symbol-grid__cell symbol-grid__cell--${field}`}
                aria-sort={sorted === 'asc' ? 'ascending' : sorted === 'desc' ? 'descending' : 'none'}
              >
                <button
                  type="button"
                  className="symbol-grid__sort"
                  data-testid={`symbol-sort-${field}`}
                  title={t('symbolTable.sortBy', { column: t(`symbolTable.columns.${field}`) })}
                  onClick={() => onSort(field)}
                >
                  {t(`symbolTable.columns.${field}`)}
                  <span aria-hidden="true">{sorted === 'asc' ? ' ▲' : sorted === 'desc' ? ' ▼' : ''}</span>
                </button>
              </div>
            );
          })}
        </div>
        {shown}
      </div>
    </div>
  );
}
