/**
 * How operands are shown on the diagram (TIA Portal's "symbolic", "absolute", "symbolic and
 * absolute"), from the project's symbol table: the file keeps what the user wrote, the display
 * shows the other form too. Also the completions an operand field offers.
 */
import type { OutlineBlock, ProjectOutline } from '../api/outline';
import { completeOperand } from '../editor/intellisense/completion';
import { blockNamed } from '../editor/intellisense/scope';
import type { OperandLabel } from './LadRung';
import type { Complete, OperandOption } from './OperandEditor';

export type OperandDisplay = 'both' | 'symbolic' | 'absolute';

/** An address written without spaces and in capitals (`Q 4.0` and `q4.0` are the same). */
export function addressKey(text: string): string {
  return text.replace(/\s+/g, '').toUpperCase();
}

export interface SymbolIndex {
  byAddress: ReadonlyMap<string, string>;
  byName: ReadonlyMap<string, string>;
}

export function symbolIndex(outline: ProjectOutline | null): SymbolIndex {
  const byAddress = new Map<string, string>();
  const byName = new Map<string, string>();
  for (const symbol of outline?.symbols ?? []) {
    byAddress.set(addressKey(symbol.address), symbol.name);
    byName.set(symbol.name.toLowerCase(), symbol.address);
  }
  return { byAddress, byName };
}

/** The operand as the display wants it: the symbol, the address, or the symbol over the address. */
export function operandLabel(operand: string, display: OperandDisplay, symbols: SymbolIndex): OperandLabel {
  const quoted = /^"([^"]*)"$/.exec(operand.trim());
  const symbol = quoted ? `"${quoted[1]}"` : (() => {
    const name = symbols.byAddress.get(addressKey(operand));
    return name === undefined ? null : `"${name}"`;
  })();
  const address = quoted ? symbols.byName.get((quoted[1] ?? '').toLowerCase()) ?? null : operand.trim();
  if (!symbol || !address) return { main: operand };
  if (display === 'symbolic') return { main: symbol };
  if (display === 'absolute') return { main: address };
  return { main: symbol, second: address };
}

/** The outline's block a LAD block is (`OB 1`, `"Motor"`), for its members. */
export function outlineBlock(outline: ProjectOutline | null, name: string): OutlineBlock | null {
  const quoted = /^"([^"]*)"$/.exec(name.trim());
  return blockNamed(outline, quoted ? (quoted[1] ?? '') : name);
}

/** Completions of an operand typed on an element of `block`. */
export function operandCompleter(outline: ProjectOutline | null, block: OutlineBlock | null, uiLanguage: string): Complete {
  return (typed) => {
    const found = completeOperand(typed, outline, block, uiLanguage);
    return {
      from: found.from,
      to: found.to,
      options: found.suggestions.map((s): OperandOption => ({ label: s.label, insert: s.insertText, ...(s.detail ? { detail: s.detail } : {}) })),
    };
  };
}

/** Completions from a fixed list (box types, status bits), matched anywhere in the name. */
export function listCompleter(options: readonly OperandOption[]): Complete {
  return (typed) => ({ from: 1, to: typed.length + 1, options: options.filter((o) => o.label.toLowerCase().includes(typed.trim().toLowerCase())) });
}

/** Whether an operand (an address or a symbol) is a process input (`I`/`E`): it is driven, not written. */
export function isInput(operand: string, byName: ReadonlyMap<string, string>): boolean {
  const quoted = /^"([^"]*)"$/.exec(operand.trim());
  const address = quoted ? (byName.get((quoted[1] ?? '').toLowerCase()) ?? '') : operand;
  return /^\s*[IE]\s*\d/i.test(address);
}
