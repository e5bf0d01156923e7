/**
 * Addresses in a network's series/parallel tree, and immutable updates at an address.
 *
 * Element ids are renumbered after every edit (the n-th element in reading order is `en`, as the
 * text format numbers them), so the editors address places structurally: a {@link SeriesRef}
 * names one series (the common logic, an output's conditions, and from there branches of
 * parallels and logic wired into box pins), an index names an element in it. An update copies
 * only the path from the network down to the changed series; everything else is shared, which
 * keeps undo snapshots small.
 */
import type { Network, Output, Series } from './model';

export type Element = Series['elements'][number];
export type Final = Output['target'];
export type Box = Extract<Element, { kind: 'box' }>;
export type Parallel = Extract<Element, { kind: 'parallel' }>;
export type Contact = Extract<Element, { kind: 'contact' }>;
export type Coil = Extract<Final, { kind: 'coil' }>;

/** One step down from an element of a series: into a parallel's branch, or a box pin's logic. */
export type Step = { element: number; branch: number } | { element: number; pin: string };

/**
 * A series of the network: the common logic or output `root`'s conditions, then steps down.
 * With `target`, the root is output `root`'s final element seen as a series of one (a timer box
 * ending the rung with logic on its R pin): only the pins' series under it are edited.
 */
export interface SeriesRef {
  root: 'logic' | number;
  target?: boolean;
  steps: readonly Step[];
}

/** A wire position in a series: before element `index` (`index` = length: at its end). */
export interface InsertPoint {
  series: SeriesRef;
  index: number;
}

/** Where an element is: in a series, or the final element of output `output`. */
export type Place = { kind: 'series'; series: SeriesRef; index: number } | { kind: 'target'; output: number };

export const LOGIC: SeriesRef = { root: 'logic', steps: [] };

export function conditionsOf(output: number): SeriesRef {
  return { root: output, steps: [] };
}

export function sameSeries(a: SeriesRef, b: SeriesRef): boolean {
  if (a.root !== b.root || !!a.target !== !!b.target || a.steps.length !== b.steps.length) return false;
  return a.steps.every((step, k) => {
    const other = b.steps[k];
    if (!other || other.element !== step.element) return false;
    return 'branch' in step ? 'branch' in other && other.branch === step.branch : 'pin' in other && other.pin === step.pin;
  });
}

export function samePlace(a: Place, b: Place): boolean {
  if (a.kind === 'target' || b.kind === 'target') return a.kind === b.kind && a.kind === 'target' && b.kind === 'target' && a.output === b.output;
  return a.index === b.index && sameSeries(a.series, b.series);
}

/** The series at `ref`, or null when the network has no such series (a stale address). */
export function seriesAt(network: Network, ref: SeriesRef): Series | null {
  let series: Series | undefined = rootSeries(network, ref);
  for (const step of ref.steps) {
    const element: Element | undefined = series?.elements[step.element];
    if (!element) return null;
    if ('branch' in step) {
      series = element.kind === 'parallel' ? element.branches[step.branch] : undefined;
    } else {
      const value = element.kind === 'box' ? element.inputs[step.pin] : undefined;
      series = typeof value === 'object' && value !== null ? value : undefined;
    }
  }
  return series ?? null;
}

export function elementAt(network: Network, place: Place): Element | Final | null {
  if (place.kind === 'target') return network.outputs[place.output]?.target ?? null;
  return seriesAt(network, place.series)?.elements[place.index] ?? null;
}

function rootSeries(network: Network, ref: SeriesRef): Series | undefined {
  if (ref.root === 'logic') return network.logic;
  const output = network.outputs[ref.root];
  if (!output) return undefined;
  return ref.target ? { elements: [output.target as Element] } : output.conditions;
}

/** The parent series of a series (and the step that led down from it), or null at a root. */
export function parentOf(ref: SeriesRef): { series: SeriesRef; step: Step } | null {
  const step = ref.steps[ref.steps.length - 1];
  if (!step) return null;
  return { series: { ...ref, steps: ref.steps.slice(0, -1) }, step };
}

export function childSeries(ref: SeriesRef, step: Step): SeriesRef {
  return { ...ref, steps: [...ref.steps, step] };
}

/** The network with the series at `ref` replaced by `change(series)`; unchanged if there is none. */
export function updateSeries(network: Network, ref: SeriesRef, change: (series: Series) => Series): Network {
  const down = (series: Series, depth: number): Series => {
    const step = ref.steps[depth];
    if (!step) return change(series);
    const element = series.elements[step.element];
    if (!element) return series;
    let replaced: Element = element;
    if ('branch' in step) {
      if (element.kind !== 'parallel') return series;
      const branch = element.branches[step.branch];
      if (!branch) return series;
      const branches = element.branches.map((item, k) => (k === step.branch ? down(branch, depth + 1) : item));
      replaced = { ...element, branches };
    } else {
      if (element.kind !== 'box') return series;
      const value = element.inputs[step.pin];
      if (typeof value !== 'object' || value === null) return series;
      replaced = { ...element, inputs: { ...element.inputs, [step.pin]: down(value, depth + 1) } };
    }
    return { ...series, elements: series.elements.map((item, k) => (k === step.element ? replaced : item)) };
  };
  if (ref.root === 'logic') return { ...network, logic: down(network.logic, 0) };
  const output = network.outputs[ref.root];
  if (!output) return network;
  let changed: Output;
  if (ref.target) {
    if (ref.steps.length === 0) return network; // the final element is no series to edit
    const target = down({ elements: [output.target as Element] }, 0).elements[0];
    changed = { ...output, target: target as Final };
  } else {
    changed = { ...output, conditions: down(output.conditions, 0) };
  }
  return { ...network, outputs: network.outputs.map((item, k) => (k === ref.root ? changed : item)) };
}

/** The network with the element at `place` replaced. */
export function replaceAt(network: Network, place: Place, element: Element | Final): Network {
  if (place.kind === 'target') {
    const outputs = network.outputs.map((item, k) => (k === place.output ? { ...item, target: element as Final } : item));
    return { ...network, outputs };
  }
  return updateSeries(network, place.series, (series) => ({
    ...series,
    elements: series.elements.map((item, k) => (k === place.index ? (element as Element) : item)),
  }));
}

/** Calls `visit` for every element in reading order (the order ids are numbered in). */
export function walk(network: Network, visit: (element: Element | Final, place: Place) => void): void {
  const series = (items: Series, ref: SeriesRef) => {
    items.elements.forEach((element, index) => {
      visit(element, { kind: 'series', series: ref, index });
      if (element.kind === 'parallel') {
        element.branches.forEach((branch, k) => series(branch, childSeries(ref, { element: index, branch: k })));
      } else if (element.kind === 'box') {
        for (const [pin, value] of Object.entries(element.inputs)) {
          if (typeof value === 'object' && value !== null) series(value, childSeries(ref, { element: index, pin }));
        }
      }
    });
  };
  series(network.logic, LOGIC);
  network.outputs.forEach((output, k) => {
    series(output.conditions, conditionsOf(k));
    const target = output.target;
    visit(target, { kind: 'target', output: k });
    if (target.kind === 'box') {
      for (const [pin, value] of Object.entries(target.inputs)) {
        if (typeof value === 'object' && value !== null) series(value, { root: k, target: true, steps: [{ element: 0, pin }] });
      }
    }
  });
}

/** Where each element id of the network is. */
export function placesById(network: Network): Map<string, Place> {
  const places = new Map<string, Place>();
  walk(network, (element, place) => {
    if (element.id && !places.has(element.id)) places.set(element.id, place);
  });
  return places;
}

/** The place of an element object (by identity): edits find what they moved after the tree changed. */
export function placeOfObject(network: Network, wanted: Element | Final): Place | null {
  let found: Place | null = null;
  walk(network, (element, place) => {
    if (found === null && element === wanted) found = place;
  });
  return found;
}

/** A copy of the network with every element passed through `change` (children first). */
export function mapElements(network: Network, change: <T extends Element | Final>(element: T) => T): Network {
  const series = (items: Series): Series => ({ ...items, elements: items.elements.map(element) });
  const element = <T extends Element | Final>(item: T): T => {
    if (item.kind === 'parallel') return change({ ...item, branches: item.branches.map(series) });
    if (item.kind === 'box') {
      const inputs = Object.fromEntries(
        Object.entries(item.inputs).map(([pin, value]) => [pin, typeof value === 'object' && value !== null ? series(value) : value]),
      );
      return change({ ...item, inputs });
    }
    return change(item);
  };
  return {
    ...network,
    logic: series(network.logic),
    outputs: network.outputs.map((output) => ({ conditions: series(output.conditions), target: element(output.target) })),
  };
}
