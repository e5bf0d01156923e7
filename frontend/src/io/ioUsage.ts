/**
 * Which process I/O the downloaded program uses, for the I/O panel: the digital bytes (bits and
 * bytes: switches and lamps) and the analog words (IW/QW/PIW/PQW: sliders and meters).
 *
 * A word counts as analog unless one of its bytes is also used bit by bit or as a byte (then it is
 * digital I/O read as a word, e.g. `L IW 0` next to `A I 0.3`, and its bytes are shown as bits).
 * Double words (`ID 4`) are always digital: S7 analog modules deliver one word per channel.
 * The symbol table counts as use, as in PLCSIM where a symbol names the module's channel.
 */
import type { SourceText } from '../api/sessions';
import { parseSymbolTable } from '../cpu/projectSymbols';

export interface AnalogWord {
  /** The address as the panel names it: `IW64`, `PIW256`, `QW80`, `PQW272`. */
  address: string;
  byte: number;
  /** Only read or written directly at the module (`PIW`/`PQW`), never through the process image. */
  peripheral: boolean;
}

export interface IoUsage {
  inputs: number[];
  outputs: number[];
  analogInputs: AnalogWord[];
  analogOutputs: AnalogWord[];
}

// An I/O address in code: `I 0.0`, `E0.1`, `QB 4`, `AW4`, `%Q4.0`, `PIW 256`, `PEW256`. A bit
// needs its `.n`, a byte/word/double word its size letter, so `E001:` or `A` (AND) never count.
const IN_CODE = /(?<![\w#.%"'])%?(P?)([IEQA])(?:([BWD])[ \t]*(\d+)|[ \t]*(\d+)\.[0-7])(?![\w.])/gi;
const CODE_FILE = /\.(?:awl|stl|scl|db|udt|lad|fbd|graph)$/i;

interface Access {
  input: boolean;
  peripheral: boolean;
  size: '' | 'B' | 'W' | 'D';
  byte: number;
}

function accessesOf(sources: readonly SourceText[]): Access[] {
  const found: Access[] = [];
  const add = (peripheral: string, area: string, size: string, byte: number) => {
    const upper = area.toUpperCase();
    found.push({
      input: upper === 'I' || upper === 'E',
      peripheral: peripheral !== '',
      size: size.toUpperCase() as Access['size'],
      byte,
    });
  };
  for (const source of sources) {
    if (CODE_FILE.test(source.name)) {
      for (const match of source.text.matchAll(IN_CODE)) {
        add(match[1] ?? '', match[2] ?? '', match[3] ?? '', Number(match[4] ?? match[5]));
      }
    }
    for (const symbol of parseSymbolTable(source.name, source.text)) {
      const match = /^(P?)([IQ])([BWD]?)(\d+)(\.[0-7])?$/.exec(symbol.address);
      if (match) add(match[1]!, match[2]!, match[3]!, Number(match[4]));
    }
  }
  return found;
}

const sorted = (set: Set<number>) => [...set].sort((a, b) => a - b);

/** The digital bytes and analog words of the sources (see the module's rules). */
export function ioUsage(sources: readonly SourceText[]): IoUsage {
  const accesses = accessesOf(sources);
  const digital = { in: new Set<number>(), out: new Set<number>() };
  const words = { in: new Map<number, AnalogWord>(), out: new Map<number, AnalogWord>() };
  for (const access of accesses) {
    const bytes = digital[access.input ? 'in' : 'out'];
    if (access.size === '' || access.size === 'B') bytes.add(access.byte);
    else if (access.size === 'D') for (let k = 0; k < 4; k++) bytes.add(access.byte + k);
  }
  for (const access of accesses) {
    if (access.size !== 'W') continue;
    const side = access.input ? 'in' : 'out';
    const bytes = digital[side];
    if (bytes.has(access.byte) || bytes.has(access.byte + 1)) {
      bytes.add(access.byte).add(access.byte + 1);
      continue;
    }
    const known = words[side].get(access.byte);
    // Used through the process image anywhere: named as such (`IW64`, not `PIW64`).
    const peripheral = access.peripheral && (known?.peripheral ?? true);
    const area = access.input ? 'I' : 'Q';
    words[side].set(access.byte, { address: `${peripheral ? 'P' : ''}${area}W${access.byte}`, byte: access.byte, peripheral });
  }
  // A word that overlaps a digital byte found after it was listed goes back to the bytes.
  const analog = (side: 'in' | 'out') =>
    [...words[side].values()]
      .filter((word) => !digital[side].has(word.byte) && !digital[side].has(word.byte + 1))
      .sort((a, b) => a.byte - b.byte);
  return {
    inputs: sorted(digital.in),
    outputs: sorted(digital.out),
    analogInputs: analog('in'),
    analogOutputs: analog('out'),
  };
}

/**
 * The digital bytes the panel shows: by default those the program uses; on request every byte
 * from 0 to the highest one used (at least IB0..IB3 / QB0..QB3), as PLCSIM's input and output
 * windows would show them side by side.
 */
export function shownBytes(used: readonly number[], all: boolean, atLeast = 4): number[] {
  if (!all) return [...used];
  const last = Math.max(atLeast - 1, ...used);
  return Array.from({ length: last + 1 }, (_, i) => i);
}
