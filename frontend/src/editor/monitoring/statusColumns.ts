/**
 * STEP 7's STL block status as rows beside the source lines: per line that ran in the sampled
 * scan, the RLO, STA, ACCU1 (STANDARD), ACCU2 and the status word. Pure, so the pane that draws
 * the rows (statusColumnPane.ts) only places text.
 */
import type { BlockStatus, InstructionStatus } from '../../api/monitor';

export type AccuFormat = 'dec' | 'hex';

export interface StatusRow {
  line: number;
  rlo: string;
  sta: string;
  accu1: string;
  accu2: string;
  stw: string;
}

/** Signed 32-bit decimal (`-1`), or `16#FFFF_FFFF` as STEP 7 writes hexadecimal. */
export function formatAccu(value: number, format: AccuFormat): string {
  const unsigned = value >>> 0;
  if (format === 'dec') return String(unsigned | 0);
  const hex = unsigned.toString(16).toUpperCase().padStart(8, '0');
  return `16#${hex.slice(0, 4)}_${hex.slice(4)}`;
}

/** The status word's 9 bits, BR (bit 8) first, as STEP 7 shows them. */
export function formatStatusWord(stw: number): string {
  return (stw & 0x1ff).toString(2).padStart(9, '0');
}

function row(line: number, status: InstructionStatus, format: AccuFormat): StatusRow {
  return {
    line,
    rlo: String(status.rlo ? 1 : 0),
    sta: String(status.sta ? 1 : 0),
    accu1: formatAccu(status.accu1, format),
    accu2: formatAccu(status.accu2, format),
    stw: formatStatusWord(status.stw),
  };
}

/**
 * The rows of a block status, by source line. A line with several instructions shows the
 * registers after its last one; lines whose instructions did not run have no row.
 */
export function statusRows(block: BlockStatus | null, format: AccuFormat): Map<number, StatusRow> {
  const rows = new Map<number, StatusRow>();
  if (!block || block.language !== 'stl') return rows;
  const last = new Map<number, InstructionStatus>();
  for (const status of block.instructions) {
    if (status.line == null) continue;
    const known = last.get(status.line);
    if (!known || known.index <= status.index) last.set(status.line, status);
  }
  for (const [line, status] of last) rows.set(line, row(line, status, format));
  return rows;
}

/** The columns, in order: their translation keys (`debug.columns.<id>`) and widths in ch. */
export const STATUS_COLUMNS = [
  { id: 'rlo', width: 4 },
  { id: 'sta', width: 4 },
  { id: 'accu1', width: 13 },
  { id: 'accu2', width: 13 },
  { id: 'stw', width: 10 },
] as const satisfies ReadonlyArray<{ id: keyof Omit<StatusRow, 'line'>; width: number }>;
