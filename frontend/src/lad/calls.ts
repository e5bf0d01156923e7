/**
 * Calls of FCs, FBs, SFCs and SFBs in LAD/FBD: a box whose pins are the called block's
 * parameters. The project's blocks come with their interface in the outline; the system blocks
 * the CPU runs are in `SYSTEM_BLOCKS` (generated from the backend's `lang/system_blocks.py`).
 * As STEP 7 requires, a new FC call has every parameter to fill in; an FB or SFB call starts with
 * its instance DB to name and its parameters open (they keep their instance values), each one
 * connected from the box's menu.
 */
import type { OutlineBlock, ProjectOutline } from '../api/outline';
import { callTarget } from './boxes';
import { BIT_PLACEHOLDER, PLACEHOLDER } from './edits';
import type { CatalogueItem } from './elements';
import { SYSTEM_BLOCKS, type Box } from './model';

export interface CallPin {
  section: 'IN' | 'OUT' | 'IN_OUT';
  name: string;
  type: string;
}

function placeholderOf(type: string): string {
  return type.toUpperCase() === 'BOOL' ? BIT_PLACEHOLDER : PLACEHOLDER;
}

function blockPins(block: OutlineBlock): CallPin[] {
  const pins: CallPin[] = [];
  for (const member of block.members) {
    if (member.depth !== 0) continue;
    if (member.section === 'IN' || member.section === 'OUT' || member.section === 'IN_OUT') pins.push({ section: member.section, name: member.name, type: member.type });
  }
  if (block.kind === 'FC' && block.return_type && block.return_type.toUpperCase() !== 'VOID') pins.push({ section: 'OUT', name: 'RET_VAL', type: block.return_type });
  return pins;
}

/** The parameters of the block a call box calls (`FC 10`, `"Motor"`, `SFB 4`), if known. */
export function callInterface(name: string, outline: ProjectOutline | null): CallPin[] | null {
  const target = callTarget(name);
  if (!target) return null;
  const absolute = /^(FC|FB|SFC|SFB)\s*(\d+)$/i.exec(target[0]);
  if (absolute) {
    const kind = (absolute[1] ?? '').toUpperCase();
    const number = Number(absolute[2]);
    const system = SYSTEM_BLOCKS.find((block) => block.kind === kind && block.number === number);
    if (system) return system.pins;
    const block = outline?.blocks.find((b) => b.kind === kind && b.number === number);
    return block ? blockPins(block) : null;
  }
  const symbol = target[0].replace(/^"|"$/g, '').toLowerCase();
  const block = outline?.blocks.find((b) => b.name.toLowerCase() === symbol);
  return block ? blockPins(block) : null;
}

/** A new call box; an FC's parameters all to fill in, an FB's instance DB to name. */
export function newCallBox(name: string, kind: string, pins: readonly CallPin[]): Box {
  const fc = kind === 'FC' || kind === 'SFC';
  const inputs: Record<string, string> = {};
  const outputs: Record<string, string> = {};
  if (fc) {
    for (const pin of pins) {
      if (pin.section === 'OUT') outputs[pin.name] = placeholderOf(pin.type);
      else inputs[pin.name] = placeholderOf(pin.type);
    }
  }
  return { kind: 'box', id: '', name, instance: fc ? null : PLACEHOLDER, inputs, outputs };
}

/** The box with one more parameter connected (to a placeholder to fill in). */
export function connectPin(box: Box, pin: CallPin): Box {
  if (pin.section === 'OUT') return { ...box, outputs: { ...box.outputs, [pin.name]: placeholderOf(pin.type) } };
  return { ...box, inputs: { ...box.inputs, [pin.name]: placeholderOf(pin.type) } };
}

/** The catalogue's call entries: the project's FCs and FBs, and the system blocks. */
export function callItems(outline: ProjectOutline | null): CatalogueItem[] {
  const project = (outline?.blocks ?? [])
    .filter((block) => block.kind === 'FC' || block.kind === 'FB')
    .map((block): CatalogueItem => {
      const name = `${block.kind} ${block.number}`;
      const pins = blockPins(block);
      return {
        key: `call:${name}`,
        group: 'calls',
        symbol: block.name && block.name !== name ? `${name} "${block.name}"` : name,
        nameKey: null,
        final: false,
        make: () => newCallBox(name, block.kind, pins),
      };
    });
  const system = SYSTEM_BLOCKS.map(
    (block): CatalogueItem => ({
      key: `call:${block.kind} ${block.number}`,
      group: 'calls',
      symbol: `${block.kind} ${block.number} ${block.name}`,
      nameKey: null,
      final: false,
      make: () => newCallBox(`${block.kind} ${block.number}`, block.kind, block.pins),
    }),
  );
  return [...project, ...system];
}
