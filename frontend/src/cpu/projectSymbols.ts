/**
 * What the monitoring panels learn from the downloaded sources without asking the compiler:
 * the symbol table (to name addresses; which I/O the program uses is `io/ioUsage.ts`). The
 * compiler remains the authority; this is for display only.
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
