/**
 * The edits of the LAD/FBD editors: pure functions from a network to a network, as TIA Portal's
 * LAD commands do them (insert on the wire, open and close a branch, a parallel output, delete,
 * move along the rung). Both views edit the same series/parallel tree, so the FBD editor's
 * commands are these too.
 *
 * Every edit ends in {@link settle}: the tree is put in the form the text format reads back (no
 * parallel of one branch, no empty branch, a box ending an output-less rung is its final
 * element) and its ids are numbered in reading order, so the editor's model and the model parsed
 * from the saved text are the same object for object. An edit answers which element to select
 * afterwards; ids change with the numbering, so that is found by object identity.
 */
import { numberNetwork } from './ids';
import type { Network, Series } from './model';
import {
  childSeries,
  elementAt,
  mapElements,
  parentOf,
  placeOfObject,
  replaceAt,
  seriesAt,
  updateSeries,
  type Element,
  type Final,
  type InsertPoint,
  type Place,
  type SeriesRef,
} from './tree';

/** What a bit operand not filled in yet shows (TIA Portal's placeholder). */
export const BIT_PLACEHOLDER = '<??.?>';
/** Any other operand not filled in yet. */
export const PLACEHOLDER = '<???>';

export function isPlaceholder(operand: string | null | undefined): boolean {
  return !!operand && /^<[?.]+>$/.test(operand);
}

/** The result of an edit: the new network and the id of the element to select (or null). */
export interface Edited {
  network: Network;
  select: string | null;
}

const DEFAULT_ID = /^e\d+$/;

/** A new, empty network (an empty rung). */
export function emptyNetwork(): Network {
  return { title: '', comment: '', label: null, logic: { elements: [] }, outputs: [], stl: null, stl_reason: null };
}

/** The network in the form the text format reads back, its elements numbered; `focus` is found again. */
export function settle(network: Network, focus: Element | Final | null = null): Edited {
  if (network.stl !== null) return { network, select: null };
  let tidy = tidySeries(network);
  if (tidy.outputs.length === 0) {
    const last = tidy.logic.elements[tidy.logic.elements.length - 1];
    if (last && last.kind === 'box') {
      tidy = { ...tidy, logic: { elements: tidy.logic.elements.slice(0, -1) }, outputs: [{ conditions: { elements: [] }, target: last }] };
    }
  }
  const place = focus ? placeOfObject(tidy, focus) : null;
  const cleared = mapElements(tidy, (element) => (DEFAULT_ID.test(element.id) ? { ...element, id: '' } : element));
  const numbered = numberNetwork(cleared);
  const selected = place ? elementAt(numbered, place) : null;
  return { network: numbered, select: selected?.id ?? null };
}

/** Removes empty branches and unwraps parallels left with one branch; drops empty pin logic. */
function tidySeries(network: Network): Network {
  const series = (items: Series): Series => {
    const elements: Element[] = [];
    for (const element of items.elements) {
      if (element.kind === 'parallel') {
        const branches = element.branches.map(series).filter((branch) => branch.elements.length > 0);
        if (branches.length === 0) continue;
        if (branches.length === 1) elements.push(...(branches[0]?.elements ?? []));
        else elements.push(branches.length === element.branches.length && branches.every((b, k) => b === element.branches[k]) ? element : { ...element, branches });
      } else if (element.kind === 'box') {
        elements.push(tidyBox(element, series));
      } else {
        elements.push(element);
      }
    }
    const same = elements.length === items.elements.length && elements.every((item, k) => item === items.elements[k]);
    return same ? items : { ...items, elements };
  };
  const outputs = network.outputs.map((output) => {
    const conditions = series(output.conditions);
    const target = output.target.kind === 'box' ? tidyBox(output.target, series) : output.target;
    return conditions === output.conditions && target === output.target ? output : { conditions, target };
  });
  return { ...network, logic: series(network.logic), outputs };
}

function tidyBox<B extends Extract<Element | Final, { kind: 'box' }>>(box: B, series: (items: Series) => Series): B {
  let changed = false;
  const inputs: Record<string, string | Series> = {};
  for (const [pin, value] of Object.entries(box.inputs)) {
    if (typeof value !== 'object' || value === null) {
      inputs[pin] = value;
      continue;
    }
    const tidy = series(value);
    if (tidy !== value) changed = true;
    if (tidy.elements.length > 0) inputs[pin] = tidy;
    else changed = true;
  }
  return changed ? { ...box, inputs } : box;
}

// -- where an insertion goes -------------------------------------------------------------------

/**
 * The wire position right of an element (TIA Portal inserts after the selection); for a final
 * element, before it: the end of its output's conditions, or of the common logic when the
 * network has only that output.
 */
export function pointAfter(network: Network, place: Place): InsertPoint {
  if (place.kind === 'series') return { series: place.series, index: place.index + 1 };
  return pointBeforeTarget(network, place.output);
}

export function pointBeforeTarget(network: Network, output: number): InsertPoint {
  const conditions = network.outputs[output]?.conditions.elements ?? [];
  if (network.outputs.length === 1 && conditions.length === 0) return { series: { root: 'logic', steps: [] }, index: network.logic.elements.length };
  return { series: { root: output, steps: [] }, index: conditions.length };
}

/** The end of the rung: where elements go when nothing is selected. */
export function endOfRung(network: Network): InsertPoint {
  if (network.outputs.length === 0) return { series: { root: 'logic', steps: [] }, index: network.logic.elements.length };
  return pointBeforeTarget(network, 0);
}

// -- inserting ---------------------------------------------------------------------------------

/** Inserts an element of the power flow (contact, NOT, box ...) at the wire position. */
export function insertElement(network: Network, at: InsertPoint, element: Element): Edited {
  const series = seriesAt(network, at.series);
  if (!series) return settle(network);
  const index = Math.max(0, Math.min(at.index, series.elements.length));
  const changed = updateSeries(network, at.series, (items) => ({
    ...items,
    elements: [...items.elements.slice(0, index), element, ...items.elements.slice(index)],
  }));
  return settle(changed, element);
}

/**
 * Places a rung's end (coil, jump, RET, OPN, or a box that ends the rung). A rung without an
 * output gets it at its end. Otherwise it becomes a new output branch, as a parallel coil: split
 * from the common logic at the wire position when that lies in the common logic (the elements
 * right of it move into every existing output's own conditions), else from the end of the
 * common logic.
 */
export function insertFinal(network: Network, at: InsertPoint | null, final: Final): Edited {
  if (network.outputs.length === 0) {
    return settle({ ...network, outputs: [{ conditions: { elements: [] }, target: final }] }, final);
  }
  let logic = network.logic.elements;
  let outputs = network.outputs;
  if (at && at.series.root === 'logic' && at.series.steps.length === 0 && at.index < logic.length) {
    const moved = logic.slice(at.index);
    logic = logic.slice(0, at.index);
    outputs = outputs.map((output) => ({ ...output, conditions: { elements: [...moved, ...output.conditions.elements] } }));
  }
  const after = at && typeof at.series.root === 'number' ? at.series.root + 1 : outputs.length;
  const added = { conditions: { elements: [] }, target: final };
  const next = [...outputs.slice(0, after), added, ...outputs.slice(after)];
  return settle({ ...network, logic: { elements: logic }, outputs: next }, final);
}

/**
 * A rung's end placed after a box that ends the rung (a coil after a timer box): the box moves
 * into the rung and feeds the new end with its ENO or Q, as in TIA Portal.
 */
export function finalAfterBox(network: Network, output: number, final: Final): Edited {
  const current = network.outputs[output];
  if (!current || current.target.kind !== 'box') return insertFinal(network, null, final);
  const box = current.target as Element;
  if (network.outputs.length === 1 && current.conditions.elements.length === 0) {
    return settle({ ...network, logic: { elements: [...network.logic.elements, box] }, outputs: [{ conditions: { elements: [] }, target: final }] }, final);
  }
  const changed = { conditions: { elements: [...current.conditions.elements, box] }, target: final };
  return settle({ ...network, outputs: network.outputs.map((item, k) => (k === output ? changed : item)) }, final);
}

// -- removing ----------------------------------------------------------------------------------

/**
 * Deletes the element at `place`. A final element takes its output branch with it (its own
 * conditions too) unless it is the only output, whose conditions stay as the rung's logic. A
 * branch left empty disappears, a parallel left with one branch becomes that branch.
 */
export function removeAt(network: Network, place: Place): Edited {
  if (place.kind === 'target') {
    if (network.outputs.length === 1) {
      const only = network.outputs[0];
      const logic = { elements: [...network.logic.elements, ...(only?.conditions.elements ?? [])] };
      return settle({ ...network, logic, outputs: [] }, neighbourAfterRemoval(network, place));
    }
    return settle({ ...network, outputs: network.outputs.filter((_, k) => k !== place.output) }, null);
  }
  const neighbour = neighbourAfterRemoval(network, place);
  const changed = updateSeries(network, place.series, (items) => ({
    ...items,
    elements: items.elements.filter((_, k) => k !== place.index),
  }));
  return settle(changed, neighbour);
}

/** What to select after a deletion: the element left of it, else right of it, else nothing. */
function neighbourAfterRemoval(network: Network, place: Place): Element | Final | null {
  if (place.kind === 'target') {
    const output = network.outputs[place.output];
    const conditions = output?.conditions.elements ?? [];
    return conditions[conditions.length - 1] ?? network.logic.elements[network.logic.elements.length - 1] ?? null;
  }
  const series = seriesAt(network, place.series);
  const sibling = series?.elements[place.index - 1] ?? series?.elements[place.index + 1];
  if (sibling) return sibling;
  // The last element of a branch: the first element of a neighbouring branch.
  const parent = parentOf(place.series);
  if (!parent || !('branch' in parent.step)) return null;
  const parallel = seriesAt(network, parent.series)?.elements[parent.step.element];
  if (!parallel || parallel.kind !== 'parallel') return null;
  const other = parallel.branches[parent.step.branch === 0 ? 1 : 0];
  return other?.elements[0] ?? null;
}

// -- branches ----------------------------------------------------------------------------------

/**
 * Shift+F8 "open branch": a new parallel branch below the selected element, holding a new
 * normally open contact to fill in (a parallel selected gets one more branch). On a final element
 * it is a new parallel output.
 */
export function openBranch(network: Network, place: Place, contact: Element, coil: Final): Edited {
  if (place.kind === 'target') return insertFinal(network, pointAfter(network, place), coil);
  const element = elementAt(network, place);
  if (!element) return settle(network);
  const branch: Series = { elements: [contact] };
  const replacement: Element =
    element.kind === 'parallel'
      ? { ...element, branches: [...element.branches, branch] }
      : { kind: 'parallel', id: '', branches: [{ elements: [element as Element] }, branch] };
  return settle(replaceAt(network, place, replacement), contact);
}

/**
 * Shift+F9 "close branch": the parallel around the selected element closes one element further
 * right, taking the next element of its series into its first branch (the branch of the main
 * rung). Nothing happens when no element follows the parallel.
 */
export function closeBranch(network: Network, place: Place): Edited {
  const selected = elementAt(network, place);
  const found = place.kind === 'series' ? enclosingParallel(place.series) : null;
  if (!found || !selected) return settle(network, selected);
  const { series: outer, index } = found;
  const items = seriesAt(network, outer);
  const parallel = items?.elements[index];
  const next = items?.elements[index + 1];
  if (!items || !parallel || parallel.kind !== 'parallel' || !next) return settle(network, selected);
  const [first, ...rest] = parallel.branches;
  const widened: Element = { ...parallel, branches: [{ elements: [...(first?.elements ?? []), next] }, ...rest] };
  const changed = updateSeries(network, outer, (series) => ({
    ...series,
    elements: [...series.elements.slice(0, index), widened, ...series.elements.slice(index + 2)],
  }));
  return settle(changed, selected);
}

/** The innermost parallel a series is a branch of: its series and index. */
function enclosingParallel(ref: SeriesRef): { series: SeriesRef; index: number } | null {
  let current: SeriesRef | null = ref;
  while (current) {
    const parent = parentOf(current);
    if (!parent) return null;
    if ('branch' in parent.step) return { series: parent.series, index: parent.step.element };
    current = parent.series;
  }
  return null;
}

// -- moving ------------------------------------------------------------------------------------

/** Moves an element one place left (-1) or right (+1) along its series; finals do not move. */
export function shiftAlong(network: Network, place: Place, delta: -1 | 1): Edited {
  const element = elementAt(network, place);
  if (place.kind !== 'series' || !element) return settle(network, element);
  const series = seriesAt(network, place.series);
  const to = place.index + delta;
  if (!series || to < 0 || to >= series.elements.length) return settle(network, element);
  const changed = updateSeries(network, place.series, (items) => {
    const elements = [...items.elements];
    const [moved] = elements.splice(place.index, 1);
    if (moved) elements.splice(to, 0, moved);
    return { ...items, elements };
  });
  return settle(changed, element);
}

/** Moves an element to another wire position (a drag along the rung or into a branch). */
export function moveTo(network: Network, from: Place, to: InsertPoint): Edited {
  const element = elementAt(network, from);
  if (from.kind !== 'series' || !element) return settle(network, element);
  const inside = to.series.steps.length > from.series.steps.length && isUnder(to.series, childOf(from));
  if (inside) return settle(network, element); // into itself: a parallel into its own branch
  // Insert the element first (an identical object), then remove the original by identity.
  const inserted = updateSeries(network, to.series, (items) => {
    const index = Math.max(0, Math.min(to.index, items.elements.length));
    return { ...items, elements: [...items.elements.slice(0, index), element as Element, ...items.elements.slice(index)] };
  });
  const original = findOriginal(inserted, from, to);
  if (!original) return settle(network, element);
  const removed = updateSeries(inserted, original.series, (items) => ({
    ...items,
    elements: items.elements.filter((_, k) => k !== original.index),
  }));
  return settle(removed, element);
}

function childOf(place: Extract<Place, { kind: 'series' }>): SeriesRef {
  return childSeries(place.series, { element: place.index, branch: 0 });
}

function isUnder(inner: SeriesRef, outer: SeriesRef): boolean {
  if (inner.root !== outer.root || !!inner.target !== !!outer.target) return false;
  const last = outer.steps.length - 1;
  return outer.steps.every((step, k) => {
    const other = inner.steps[k];
    if (!other || other.element !== step.element) return false;
    return k === last ? true : JSON.stringify(other) === JSON.stringify(step);
  });
}

/** Where the moved element's original is after the copy was inserted (same series: it may shift). */
function findOriginal(network: Network, from: Extract<Place, { kind: 'series' }>, to: InsertPoint): Extract<Place, { kind: 'series' }> | null {
  const sameSeries = JSON.stringify(from.series) === JSON.stringify(to.series);
  const index = sameSeries && to.index <= from.index ? from.index + 1 : from.index;
  // An insertion earlier in a parent series shifts the original's path too.
  const series = shiftedPath(from.series, to);
  return seriesAt(network, series) ? { kind: 'series', series, index } : null;
}

function shiftedPath(ref: SeriesRef, inserted: InsertPoint): SeriesRef {
  const base = inserted.series;
  if (ref.root !== base.root || !!ref.target !== !!base.target || ref.steps.length <= base.steps.length) return ref;
  const prefixSame = base.steps.every((step, k) => JSON.stringify(step) === JSON.stringify(ref.steps[k]));
  if (!prefixSame) return ref;
  const steps = ref.steps.map((step, k) =>
    k === base.steps.length && step.element >= inserted.index ? { ...step, element: step.element + 1 } : step,
  );
  return { ...ref, steps };
}

// -- replacing ---------------------------------------------------------------------------------

/** The element at `place` replaced (an operand typed, a contact turned normally closed ...). */
export function replaceElement(network: Network, place: Place, element: Element | Final): Edited {
  return settle(replaceAt(network, place, element), element);
}
