/**
 * What the LAD/FBD editors can insert: TIA Portal's favourites and the full instruction
 * catalogue, each entry with the element it makes. New elements carry TIA's placeholders
 * (`<??.?>` for a bit, `<???>` for anything else) where an operand is still to be typed; the
 * compiler reports them (LAD212) until they are filled in, and the editor asks for them at once.
 */
import { CATALOGUE, type BoxSpec } from './boxes';
import { BIT_PLACEHOLDER, PLACEHOLDER } from './edits';
import type { Element, Final } from './tree';

export type CatalogueGroup =
  | 'bits'
  | 'coils'
  | 'program'
  | 'timers'
  | 'counters'
  | 'compare'
  | 'move'
  | 'math'
  | 'convert'
  | 'word'
  | 'shift'
  | 'flipflops'
  | 'calls';

export const GROUPS: readonly CatalogueGroup[] = ['bits', 'coils', 'timers', 'counters', 'compare', 'move', 'math', 'convert', 'word', 'shift', 'flipflops', 'program', 'calls'];

export interface CatalogueItem {
  /** Stable key: `contact`, `coil:S`, `box:S_ODT`, `call:FC 10`. */
  key: string;
  group: CatalogueGroup;
  /** What the palette shows: the LAD symbol or the box's name (the same in every language). */
  symbol: string;
  /** i18n key of the element's name, or null for a box (its name says it). */
  nameKey: string | null;
  /** Ends a rung: a coil, jump, RET or OPN (inserted as an output, not on the wire). */
  final: boolean;
  make: () => Element | Final;
  /** TIA Portal's favourites shortcut. */
  shortcut?: string;
}

const STATUS_BITS = ['OV', 'OS', 'BR', 'UO', '==0', '<>0', '>0', '<0', '>=0', '<=0'] as const;

function item(key: string, group: CatalogueGroup, symbol: string, make: () => Element | Final, final = false, shortcut?: string): CatalogueItem {
  return { key, group, symbol, nameKey: `lad.items.${key.replace(/[:=<>]/g, (c) => ({ ':': '_', '=': 'eq', '<': 'lt', '>': 'gt' })[c] ?? c)}`, final, make, ...(shortcut ? { shortcut } : {}) };
}

/** A new box of the catalogue, its required operands as placeholders. */
export function newBox(spec: BoxSpec): Element {
  const inputs: Record<string, string> = {};
  const outputs: Record<string, string> = {};
  for (const pin of spec.pins) {
    if (pin.type === 'BOOL') continue;
    if (pin.direction === 'in') inputs[pin.name] = PLACEHOLDER;
    else if (spec.enEno && pin.name === 'OUT') outputs[pin.name] = PLACEHOLDER;
  }
  if (spec.family === 'counter') delete inputs.PV; // PV is needed only with S
  if (spec.family === 'edge') inputs.M_BIT = BIT_PLACEHOLDER;
  const instance = spec.address === null ? null : spec.address === 'bit' ? BIT_PLACEHOLDER : PLACEHOLDER;
  return { kind: 'box', id: '', name: spec.name, instance, inputs, outputs };
}

function coil(kind: string, value = false): Final {
  return { kind: 'coil', id: '', coil: kind as Extract<Final, { kind: 'coil' }>['coil'], operand: kind === 'SAVE' ? '' : PLACEHOLDER_FOR(kind), value: value ? PLACEHOLDER : null };
}

function PLACEHOLDER_FOR(kind: string): string {
  return kind === '=' || kind === 'S' || kind === 'R' ? BIT_PLACEHOLDER : PLACEHOLDER;
}

const FIXED: CatalogueItem[] = [
  item('contact', 'bits', '-| |-', () => ({ kind: 'contact', id: '', operand: BIT_PLACEHOLDER, negated: false }), false, 'Shift+F2'),
  item('contactNC', 'bits', '-|/|-', () => ({ kind: 'contact', id: '', operand: BIT_PLACEHOLDER, negated: true }), false, 'Shift+F3'),
  item('not', 'bits', '-|NOT|-', () => ({ kind: 'not', id: '' })),
  item('edgeP', 'bits', '-(P)-', () => ({ kind: 'edge', id: '', edge: 'P', memory: BIT_PLACEHOLDER })),
  item('edgeN', 'bits', '-(N)-', () => ({ kind: 'edge', id: '', edge: 'N', memory: BIT_PLACEHOLDER })),
  item('midline', 'bits', '-(#)-', () => ({ kind: 'midline', id: '', operand: BIT_PLACEHOLDER })),
  ...STATUS_BITS.map((bit) => item(`status:${bit}`, 'bits', `-|${bit}|-`, () => ({ kind: 'status', id: '', bit, negated: false }))),
  item('coil:=', 'coils', '-( )', () => coil('='), true, 'Shift+F7'),
  item('coil:S', 'coils', '-(S)', () => coil('S'), true),
  item('coil:R', 'coils', '-(R)', () => coil('R'), true),
  item('coil:SAVE', 'coils', '-(SAVE)', () => coil('SAVE'), true),
  ...['SP', 'SE', 'SD', 'SS', 'SF'].map((kind) => item(`coil:${kind}`, 'timers', `-(${kind})`, () => coil(kind, true), true)),
  item('coil:CU', 'counters', '-(CU)', () => coil('CU'), true),
  item('coil:CD', 'counters', '-(CD)', () => coil('CD'), true),
  item('coil:SC', 'counters', '-(SC)', () => coil('SC', true), true),
  item('jump', 'program', '-(JMP)', () => ({ kind: 'jump', id: '', negated: false, label: 'M001' }), true),
  item('jumpN', 'program', '-(JMPN)', () => ({ kind: 'jump', id: '', negated: true, label: 'M001' }), true),
  item('ret', 'program', '-(RET)', () => ({ kind: 'ret', id: '' }), true),
  item('opn', 'program', '-(OPN)', () => ({ kind: 'opn', id: '', block: PLACEHOLDER }), true),
];

const FAMILY_GROUP: Record<BoxSpec['family'], CatalogueGroup> = {
  compare: 'compare',
  move: 'move',
  math: 'math',
  convert: 'convert',
  word: 'word',
  shift: 'shift',
  timer: 'timers',
  counter: 'counters',
  flipflop: 'flipflops',
  edge: 'flipflops',
};

/** The empty box of Shift+F5: its type is typed in afterwards. */
export function emptyBox(): Element {
  return { kind: 'box', id: '', name: PLACEHOLDER, instance: null, inputs: {}, outputs: {} };
}

const BOXES: CatalogueItem[] = Object.values(CATALOGUE).map((spec) => ({
  key: `box:${spec.name}`,
  group: FAMILY_GROUP[spec.family],
  symbol: spec.name,
  nameKey: null,
  final: false,
  make: () => newBox(spec),
}));

/** Every element of the catalogue (calls of the project's blocks are added by the editor). */
export const CATALOGUE_ITEMS: readonly CatalogueItem[] = [...FIXED, ...BOXES];

export function catalogueItem(key: string): CatalogueItem | undefined {
  return CATALOGUE_ITEMS.find((entry) => entry.key === key);
}

/** Entries whose symbol or translated name contains the search text (case and spacing ignored). */
export function searchCatalogue(items: readonly CatalogueItem[], search: string, nameOf: (item: CatalogueItem) => string): CatalogueItem[] {
  const wanted = search.replace(/\s+/g, '').toLowerCase();
  if (!wanted) return [...items];
  return items.filter((entry) => `${entry.symbol} ${nameOf(entry)} ${entry.key}`.replace(/\s+/g, '').toLowerCase().includes(wanted));
}
