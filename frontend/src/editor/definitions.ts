import type { OutlineSymbol } from '../api/outline';
import type { BlockKind, TreeBlock } from '../api/types';

/** What names a block at a place in a line of STL or SCL. */
export type BlockReference = { kind: BlockKind; number: number } | { name: string };

const ABSOLUTE = /\b(OB|FB|FC|DB|DI|UDT)[ \t]*(\d+)\b/gi;
const QUOTED = /"([^"\n]*)"/g;
const WORD = /[A-Za-z_][A-Za-z0-9_]*/g;

/** Where a comment starts in the line (`//`, outside a quoted name), or the line's length. */
function commentStart(line: string): number {
  let quoted = false;
  for (let i = 0; i < line.length; i += 1) {
    const char = line[i];
    if (char === '"' || char === "'") quoted = !quoted;
    else if (!quoted && char === '/' && line[i + 1] === '/') return i;
  }
  return line.length;
}

function around(pattern: RegExp, line: string, index: number): RegExpExecArray | null {
  pattern.lastIndex = 0;
  for (let match = pattern.exec(line); match; match = pattern.exec(line)) {
    if (match.index <= index && index <= match.index + match[0].length) return match;
  }
  return null;
}

/**
 * The block a line names at `column` (1-based): `FC1`, `FC 1`, `DB5.DBW 2`, a quoted symbol
 * (`"Motor"`, `"TankSettings".Low`) or, in SCL, a plain name (`Scale(...)`). Comments name
 * nothing.
 */
export function referenceAt(line: string, column: number): BlockReference | null {
  const index = column - 1;
  if (index >= commentStart(line)) return null;
  const quoted = around(QUOTED, line, index);
  if (quoted && index > quoted.index && index < quoted.index + quoted[0].length) return { name: quoted[1] ?? '' };
  const absolute = around(ABSOLUTE, line, index);
  if (absolute) {
    const kind = (absolute[1] ?? '').toUpperCase();
    return { kind: (kind === 'DI' ? 'DB' : kind) as BlockKind, number: Number(absolute[2]) };
  }
  const word = around(WORD, line, index);
  return word ? { name: word[0] } : null;
}

/** The block of the project a reference names, by number or (letter case aside) by symbol. */
export function findBlock(blocks: readonly TreeBlock[], reference: BlockReference): TreeBlock | null {
  if ('kind' in reference) {
    return blocks.find((block) => block.kind === reference.kind && block.number === reference.number) ?? null;
  }
  const name = reference.name.toLowerCase();
  if (!name) return null;
  return blocks.find((block) => block.name.toLowerCase() === name) ?? null;
}

/** A place to open: a file and, when known, its line. */
export interface DefinitionTarget {
  file: string;
  line: number | null;
  /** A symbol table's row: the symbol's name (the table view selects its row). */
  symbol?: string;
}

/**
 * Where what is named at `column` of `line` is defined: a block of the project (its header), else
 * a symbol of its symbol table (the table's line: `"Pump"` -> `symbols.sdf`, line 3). A symbol
 * that names a block goes to the block.
 */
export function findDefinition(
  blocks: readonly TreeBlock[],
  line: string,
  column: number,
  symbols: readonly OutlineSymbol[] = [],
): DefinitionTarget | null {
  const reference = referenceAt(line, column);
  if (!reference) return null;
  const block = findBlock(blocks, reference);
  if (block) return block;
  if (!('name' in reference) || !reference.name) return null;
  const name = reference.name.toLowerCase();
  const symbol = symbols.find((item) => item.name.toLowerCase() === name);
  return symbol ? { file: symbol.file, line: symbol.line, symbol: symbol.name } : null;
}
