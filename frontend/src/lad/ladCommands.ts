/**
 * The editor's commands on a block's networks, as pure functions of the blocks and the
 * selection: what a key, a toolbar button, a menu entry or a drop does. They return the new
 * blocks and the new selection; the editor applies them as one undo step each.
 */
import { closeBranch, emptyNetwork, endOfRung, finalAfterBox, insertElement, insertFinal, isPlaceholder, openBranch, pointAfter, removeAt, replaceElement, shiftAlong, moveTo, type Edited } from './edits';
import type { CatalogueItem } from './elements';
import { catalogueItem } from './elements';
import type { LadBlock, Network } from './model';
import { elementAt, placesById, type Element, type Final, type InsertPoint } from './tree';

export interface Selection {
  block: number;
  /** Index in the block's networks (network number - 1). */
  network: number;
  /** The selected element, or null: the network itself (its header) or a wire position. */
  id: string | null;
  /** A wire position chosen on the rung (the next element goes there). */
  point: InsertPoint | null;
}

export interface Outcome {
  blocks: readonly LadBlock[];
  selection: Selection;
  /** The field to edit at once (a new element's operand), if any. */
  edit?: { id: string; field: string } | null;
}

export function networkAt(blocks: readonly LadBlock[], selection: Selection): Network | null {
  return blocks[selection.block]?.networks[selection.network] ?? null;
}

function withNetwork(blocks: readonly LadBlock[], b: number, n: number, network: Network): LadBlock[] {
  return blocks.map((block, k) => (k === b ? { ...block, networks: block.networks.map((item, j) => (j === n ? network : item)) } : block));
}

function withNetworks(blocks: readonly LadBlock[], b: number, networks: readonly Network[]): LadBlock[] {
  return blocks.map((block, k) => (k === b ? { ...block, networks: [...networks] } : block));
}

/** Where the next element goes: the wire position chosen, else right of the selected element, else the rung's end. */
export function insertionPoint(network: Network, selection: Selection): InsertPoint {
  if (selection.point) return selection.point;
  if (selection.id) {
    const place = placesById(network).get(selection.id);
    if (place) return pointAfter(network, place);
  }
  return endOfRung(network);
}

/** The field a new element asks for first (its operand), or null when it has none to fill. */
export function firstField(element: Element | Final): string | null {
  switch (element.kind) {
    case 'contact':
    case 'midline':
    case 'coil':
      return element.kind === 'coil' && element.coil === 'SAVE' ? null : isPlaceholder(element.operand) ? 'operand' : null;
    case 'edge':
      return isPlaceholder(element.memory) ? 'operand' : null;
    case 'opn':
      return 'operand';
    case 'jump':
      return 'label';
    case 'box':
      if (isPlaceholder(element.name)) return 'name';
      if (element.instance && isPlaceholder(element.instance)) return 'instance';
      return null;
    default:
      return null;
  }
}

function applied(blocks: readonly LadBlock[], selection: Selection, edited: Edited, ask = true): Outcome {
  const network = edited.network;
  const next = withNetwork(blocks, selection.block, selection.network, network);
  const id = edited.select;
  let edit: Outcome['edit'] = null;
  if (ask && id) {
    const element = findById(network, id);
    const field = element ? firstField(element) : null;
    if (field) edit = { id, field };
  }
  return { blocks: next, selection: { ...selection, id, point: null }, edit };
}

/** The element with id `id`. */
export function findById(network: Network, id: string): Element | Final | null {
  const place = placesById(network).get(id);
  return place ? elementAt(network, place) : null;
}

/** Inserts a catalogue entry at the selection. */
export function insertItem(blocks: readonly LadBlock[], selection: Selection, item: CatalogueItem): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network || network.stl !== null) return null;
  const at = insertionPoint(network, selection);
  const element = item.make();
  const place = selection.id && !selection.point ? placesById(network).get(selection.id) : undefined;
  const afterBox = item.final && place?.kind === 'target' && network.outputs[place.output]?.target.kind === 'box';
  const edited = afterBox
    ? finalAfterBox(network, (place as { output: number }).output, element as Final)
    : item.final
      ? insertFinal(network, at, element as Final)
      : insertElement(network, at, element as Element);
  return applied(blocks, selection, edited);
}

/** Inserts at a wire position (a drop from the catalogue). */
export function insertItemAt(blocks: readonly LadBlock[], selection: Selection, item: CatalogueItem, at: InsertPoint): Outcome | null {
  return insertItem(blocks, { ...selection, id: null, point: at }, item);
}

export function branchCommand(blocks: readonly LadBlock[], selection: Selection, command: 'openBranch' | 'closeBranch'): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network || network.stl !== null || !selection.id) return null;
  const place = placesById(network).get(selection.id);
  if (!place) return null;
  if (command === 'closeBranch') return applied(blocks, selection, closeBranch(network, place), false);
  const contact = catalogueItem('contact')?.make() as Element;
  const coil = catalogueItem('coil:=')?.make() as Final;
  return applied(blocks, selection, openBranch(network, place, contact, coil));
}

export function deleteSelected(blocks: readonly LadBlock[], selection: Selection): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network) return null;
  if (selection.id) {
    const place = placesById(network).get(selection.id);
    if (!place) return null;
    return applied(blocks, selection, removeAt(network, place), false);
  }
  return deleteNetwork(blocks, selection);
}

export function shiftSelected(blocks: readonly LadBlock[], selection: Selection, delta: -1 | 1): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network || !selection.id) return null;
  const place = placesById(network).get(selection.id);
  if (!place) return null;
  return applied(blocks, selection, shiftAlong(network, place, delta), false);
}

export function moveElement(blocks: readonly LadBlock[], selection: Selection, id: string, to: InsertPoint): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network) return null;
  const place = placesById(network).get(id);
  if (!place) return null;
  return applied(blocks, selection, moveTo(network, place, to), false);
}

export function replaceSelected(blocks: readonly LadBlock[], selection: Selection, id: string, element: Element | Final): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network) return null;
  const place = placesById(network).get(id);
  if (!place) return null;
  return applied(blocks, { ...selection, id }, replaceElement(network, place, element), false);
}

// -- networks ----------------------------------------------------------------------------------

/** A new empty network after the selected one (or at the end of the block). */
export function insertNetwork(blocks: readonly LadBlock[], selection: Selection, networks: readonly Network[] = [emptyNetwork()]): Outcome | null {
  const block = blocks[selection.block];
  if (!block) return null;
  const at = Math.min(selection.network + 1, block.networks.length);
  const next = [...block.networks.slice(0, at), ...networks, ...block.networks.slice(at)];
  return { blocks: withNetworks(blocks, selection.block, next), selection: { block: selection.block, network: at, id: null, point: null } };
}

export function deleteNetwork(blocks: readonly LadBlock[], selection: Selection): Outcome | null {
  const block = blocks[selection.block];
  if (!block || !block.networks[selection.network]) return null;
  const next = block.networks.filter((_, k) => k !== selection.network);
  const network = Math.max(0, Math.min(selection.network, next.length - 1));
  return { blocks: withNetworks(blocks, selection.block, next), selection: { block: selection.block, network, id: null, point: null } };
}

export function moveNetwork(blocks: readonly LadBlock[], selection: Selection, delta: -1 | 1): Outcome | null {
  const block = blocks[selection.block];
  const to = selection.network + delta;
  if (!block || to < 0 || to >= block.networks.length) return null;
  const next = [...block.networks];
  const [moved] = next.splice(selection.network, 1);
  if (moved) next.splice(to, 0, moved);
  return { blocks: withNetworks(blocks, selection.block, next), selection: { ...selection, network: to } };
}

export function changeNetwork(blocks: readonly LadBlock[], selection: Selection, change: Partial<Network>): Outcome | null {
  const network = networkAt(blocks, selection);
  if (!network) return null;
  return { blocks: withNetwork(blocks, selection.block, selection.network, { ...network, ...change }), selection };
}

/** Every block in LAD or in FBD (the view switch: the file remembers the block's language). */
export function setLanguage(blocks: readonly LadBlock[], language: 'LAD' | 'FBD'): readonly LadBlock[] {
  if (blocks.every((block) => block.language === language)) return blocks;
  return blocks.map((block) => (block.language === language ? block : { ...block, language }));
}
