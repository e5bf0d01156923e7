/**
 * The watch table file (`<name>.vat`), as `backend/nasaq/workbench/watch_table.py` defines and
 * documents it: one row per line, `operand | format | modify value | force value // comment`,
 * header comments on top, `//` lines between rows as comment rows. Reading recovers: a broken
 * line becomes one problem (line, column, WAT8xx code) and stays in the table verbatim, so a
 * save writes back everything the user wrote. Both ends read and print alike (tested on both).
 */
import type { DisplayFormat } from '../panels/watchFormat';

export const WATCH_TABLE_SUFFIX = '.vat';
export const HEADER = '// Nasaq watch table: operand | format | modify value | force value // comment';
const MAX_COLUMNS = 4;
const WIDTHS = [12, 7, 8, 8];

/** The file's format names (STEP 7's display formats) and the table's own. */
const FORMAT_BY_NAME: Record<string, DisplayFormat> = {
  BOOL: 'bool',
  BIN: 'bin',
  HEX: 'hex',
  DEC: 'dec',
  REAL: 'real',
  CHAR: 'char',
  TIME: 'time',
  S5TIME: 's5time',
  COUNTER: 'counter',
  SIMATIC_TIME: 's5time',
  FLOATING_POINT: 'real',
  CHARACTER: 'char',
  'C#': 'counter',
};
const NAME_OF_FORMAT: Record<DisplayFormat, string> = {
  bool: 'BOOL',
  bin: 'BIN',
  hex: 'HEX',
  dec: 'DEC',
  real: 'REAL',
  char: 'CHAR',
  time: 'TIME',
  s5time: 'S5TIME',
  counter: 'COUNTER',
};

export interface WatchRow {
  /** Empty for a comment row. */
  operand: string;
  /** null: the default for the operand's type. */
  format: DisplayFormat | null;
  modify: string;
  force: string;
  comment: string;
}

export interface WatchProblem {
  code: string;
  key: string;
  params: Record<string, string | number>;
  line: number;
  column: number;
}

/** A line of the table: a row, or a broken line kept as written with its problem. */
export type WatchLine = { kind: 'row'; row: WatchRow } | { kind: 'broken'; text: string; problem: WatchProblem };

export interface WatchTableFile {
  header: string[];
  lines: WatchLine[];
}

const IDENT = '[A-Za-z_][A-Za-z0-9_]*';
const QUOTED = '"[^"]+"';
const INDEX = '\\[\\s*-?\\d+(?:\\s*,\\s*-?\\d+)*\\s*\\]';
const OPERANDS = [
  /^(?:P?[IQEA][BWD]?|[IQEAM][BWDX]?|[TCZ]|L[BWDX]?)\s?\d+(?:\.\d+)?$/i,
  /^DB\d+\.DB[XBWD]\s?\d+(?:\.\d+)?$/i,
  new RegExp(`^(?:${QUOTED}|${IDENT})(?:\\.(?:${IDENT}|${QUOTED})|${INDEX})*$`),
];

/** Whether `text` has the shape of something a row can watch (not whether it exists). */
export function isOperand(text: string): boolean {
  return OPERANDS.some((pattern) => pattern.test(text));
}

export function formatOf(text: string): DisplayFormat | null {
  return FORMAT_BY_NAME[text.trim().toUpperCase()] ?? null;
}

export function formatName(format: DisplayFormat): string {
  return NAME_OF_FORMAT[format];
}

class LineError extends Error {
  constructor(
    readonly code: string,
    readonly key: string,
    readonly column: number,
    readonly params: Record<string, string | number> = {},
  ) {
    super(code);
  }
}

/** The `|` columns of a line (with their 1-based start) and its `//` comment; quotes hide both. */
function split(text: string): { columns: [number, string][]; comment: string | null } {
  const columns: [number, string][] = [];
  let start = 0;
  let quote: string | null = null;
  let quoteAt = 0;
  for (let index = 0; index < text.length; index += 1) {
    const char = text[index]!;
    if (quote !== null) {
      if (char === quote) quote = null;
    } else if (char === '"' || char === "'") {
      quote = char;
      quoteAt = index;
    } else if (char === '|') {
      columns.push([start + 1, text.slice(start, index)]);
      start = index + 1;
    } else if (text.startsWith('//', index)) {
      columns.push([start + 1, text.slice(start, index)]);
      return { columns, comment: text.slice(index + 2).trim() };
    }
  }
  if (quote !== null) throw new LineError('WAT803', 'watch_open_quote', quoteAt + 1);
  columns.push([start + 1, text.slice(start)]);
  return { columns, comment: null };
}

function columnOf(columns: [number, string][], index: number): number {
  const [start, cell] = columns[index]!;
  return start + cell.length - cell.trimStart().length;
}

function readRow(text: string): WatchRow | null {
  const { columns, comment } = split(text);
  const cells = columns.map(([, cell]) => cell.trim());
  if (!cells.some((cell) => cell !== '')) {
    return comment === null ? null : { operand: '', format: null, modify: '', force: '', comment };
  }
  if (cells.length > MAX_COLUMNS) {
    throw new LineError('WAT804', 'watch_too_many_columns', columns[MAX_COLUMNS]![0], {
      count: cells.length,
      limit: MAX_COLUMNS,
    });
  }
  const [operand = '', formatText = '', modify = '', force = ''] = cells;
  if (!operand) throw new LineError('WAT805', 'watch_missing_operand', 1);
  if (!isOperand(operand)) throw new LineError('WAT801', 'watch_bad_operand', columnOf(columns, 0), { operand });
  const format = formatText ? formatOf(formatText) : null;
  if (formatText && format === null) {
    throw new LineError('WAT802', 'watch_unknown_format', columnOf(columns, 1), { format: formatText });
  }
  return { operand, format, modify, force, comment: comment ?? '' };
}

/** Reads a table file, recovering at every line. */
export function parseWatchTable(text: string): WatchTableFile {
  const header: string[] = [];
  const lines: WatchLine[] = [];
  let inHeader = true;
  text.split(/\r?\n/).forEach((raw, index) => {
    const line = raw.trimEnd();
    if (inHeader && line.trimStart().startsWith('//')) {
      header.push(line);
      return;
    }
    inHeader = false;
    try {
      const row = readRow(line);
      if (row) lines.push({ kind: 'row', row });
    } catch (error) {
      if (!(error instanceof LineError)) throw error;
      const problem = { code: error.code, key: error.key, params: error.params, line: index + 1, column: error.column };
      lines.push({ kind: 'broken', text: line, problem });
    }
  });
  return { header: header.length > 0 ? header : [HEADER], lines };
}

export function printRow(row: WatchRow): string {
  if (!row.operand) return `// ${row.comment}`.trimEnd();
  const cells = [row.operand, row.format ? NAME_OF_FORMAT[row.format] : '', row.modify, row.force];
  while (cells.length > 1 && cells[cells.length - 1] === '') cells.pop();
  const text = cells
    .map((cell, index) => cell.padEnd(WIDTHS[index]!))
    .join(' | ')
    .trimEnd();
  return row.comment ? `${text}  // ${row.comment}` : text;
}

export function printWatchTable(table: WatchTableFile): string {
  const lines = [...(table.header.length > 0 ? table.header : [HEADER])];
  for (const line of table.lines) lines.push(line.kind === 'broken' ? line.text : printRow(line.row));
  return `${lines.join('\n')}\n`;
}

export function isWatchTableName(name: string): boolean {
  return name.toLowerCase().endsWith(WATCH_TABLE_SUFFIX);
}

/** `VAT_1` for `VAT_1.vat`: how a table is named in the interface. */
export function tableTitle(fileName: string): string {
  return isWatchTableName(fileName) ? fileName.slice(0, -WATCH_TABLE_SUFFIX.length) : fileName;
}
