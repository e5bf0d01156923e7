/**
 * What the monitoring panels learn from the downloaded sources without asking the compiler:
 * the symbol table (to name addresses) and which input and output bytes the program uses (to
 * show them in the I/O panel). The compiler remains the authority; this is for display only.
 *
 * Symbol table formats as in backend/nasaq/lang/stl/symbols.py: `.sdf` (quoted fields), `.csv`
 * (`,` or `;`), `.seq` (tab-separated, optionally led by `126`), `.asc` (`126,` then columns of
 * 24, 12, 10 and 80 characters). Addresses in either mnemonic set (`E 0.0` or `I 0.0`).
 */
import type { SourceText } from '../api/sessions';

export interface SymbolEntry {
  name: string;
  /** Normalised: no spaces, international mnemonics (`I0.0`, `QB4`, `MW10`). */
  address: string;
  type: string;
  comment: string;
}

/** `E 0.0` → `I0.0`, `A 4.0` → `Q4.0`, `PEW 256` → `PIW256`, `mw 10` → `MW10`. */
export function normaliseAddress(text: string): string {
  const compact = text.replace(/\s+/g, '').toUpperCase();
  const match = /^(P?)([EAIQ])([BWDX]?)(\d+(?:\.\d+)?)$/.exec(compact);
  if (!match) return compact;
  const [, peripheral, area, size, rest] = match;
  const international = area === 'E' ? 'I' : area === 'A' ? 'Q' : area;
  return `${peripheral}${international}${size === 'X' ? '' : size}${rest}`;
}

function splitQuoted(line: string, separator: string): string[] {
  const fields: string[] = [];
  let field = '';
  let quoted = false;
  for (let i = 0; i < line.length; i++) {
    const ch = line[i]!;
    if (quoted) {
      if (ch === '"' && line[i + 1] === '"') {
        field += '"';
        i++;
      } else if (ch === '"') quoted = false;
      else field += ch;
    } else if (ch === '"') quoted = true;
    else if (ch === separator) {
      fields.push(field);
      field = '';
    } else field += ch;
  }
  fields.push(field);
  return fields.map((item) => item.trim());
}

function entry(fields: string[]): SymbolEntry | null {
  const [name, address, type = '', comment = ''] = fields;
  if (!name || !address) return null;
  return { name, address: normaliseAddress(address), type: type.toUpperCase(), comment };
}

/** The symbols of one symbol table file; other files give none. */
export function parseSymbolTable(name: string, text: string): SymbolEntry[] {
  const suffix = name.toLowerCase().slice(name.lastIndexOf('.'));
  const lines = text.split(/\r?\n/).filter((line) => line.trim() !== '');
  const found: Array<SymbolEntry | null> = [];
  for (const line of lines) {
    if (suffix === '.sdf') found.push(entry(splitQuoted(line, ',')));
    else if (suffix === '.csv') {
      const fields = splitQuoted(line, line.includes(';') && !line.includes(',') ? ';' : ',');
      if (/^(name|symbol)$/i.test(fields[0] ?? '')) continue;
      found.push(entry(fields));
    } else if (suffix === '.seq') {
      const fields = line.split('\t').map((item) => item.trim());
      found.push(entry(fields[0] === '126' ? fields.slice(1) : fields));
    } else if (suffix === '.asc') {
      const body = line.startsWith('126,') ? line.slice(4) : line;
      found.push(entry([body.slice(0, 24), body.slice(24, 36), body.slice(36, 46), body.slice(46)].map((f) => f.trim())));
    }
  }
  return found.filter((item): item is SymbolEntry => item !== null);
}

/** Every symbol of the sources' symbol tables. */
export function symbolsOf(sources: readonly SourceText[]): SymbolEntry[] {
  return sources.flatMap((source) => parseSymbolTable(source.name, source.text));
}

/** The symbol of each normalised address (the first one when several name it). */
export function symbolsByAddress(symbols: readonly SymbolEntry[]): Map<string, SymbolEntry> {
  const map = new Map<string, SymbolEntry>();
  for (const symbol of symbols) if (!map.has(symbol.address)) map.set(symbol.address, symbol);
  return map;
}

const SIZE_BYTES: Record<string, number> = { '': 1, X: 1, B: 1, W: 2, D: 4 };

// An I/O address in code: `I 0.0`, `E0.1`, `QB 4`, `AW4`, `%Q4.0`, `PIW 256`. A bit needs its
// `.n`, a byte/word/double word its size letter, so words like `E001:` or `A` (AND) never count.
const IN_CODE = /(?<![\w#.%"'])%?(P?)([IEQA])(?:([BWD])[ \t]*(\d+)|[ \t]*(\d+)\.[0-7])(?![\w.])/gi;

export interface IoBytes {
  inputs: number[];
  outputs: number[];
}

/**
 * The input and output bytes the sources name (in code or in the symbol table), below
 * `limit`: the digital I/O of a small PLC; analog values (PIW256 …) are not switches or lamps.
 */
export function usedIoBytes(sources: readonly SourceText[], limit = 16): IoBytes {
  const inputs = new Set<number>();
  const outputs = new Set<number>();
  const add = (area: string, size: string, byte: number) => {
    const target = area === 'I' || area === 'E' ? inputs : outputs;
    for (let k = 0; k < (SIZE_BYTES[size] ?? 1); k++) if (byte + k < limit) target.add(byte + k);
  };
  for (const source of sources) {
    const lower = source.name.toLowerCase();
    if (/\.(?:awl|stl|scl|lad|fbd)$/.test(lower)) {
      for (const match of source.text.matchAll(IN_CODE)) {
        const size = (match[3] ?? '').toUpperCase();
        const byte = Number(match[4] ?? match[5]);
        add((match[2] ?? '').toUpperCase(), size, byte);
      }
    }
    for (const symbol of parseSymbolTable(source.name, source.text)) {
      const match = /^([IQ])([BWD]?)(\d+)/.exec(symbol.address);
      if (match) add(match[1]!, match[2]!, Number(match[3]));
    }
  }
  const sorted = (set: Set<number>) => [...set].sort((a, b) => a - b);
  return { inputs: sorted(inputs), outputs: sorted(outputs) };
}

/** The bytes the I/O panel shows: 0 to 3 always, and any other byte the program uses. */
export function shownIoBytes(used: IoBytes, always = 4): IoBytes {
  const base = Array.from({ length: always }, (_, i) => i);
  const join = (extra: number[]) => [...new Set([...base, ...extra])].sort((a, b) => a - b);
  return { inputs: join(used.inputs), outputs: join(used.outputs) };
}
