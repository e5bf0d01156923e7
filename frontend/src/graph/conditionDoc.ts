/**
 * S7-Graph's conditions and permanent instructions edited in the LAD/FBD editor: a
 * {@link LadDocument} over a synthetic LAD block made from the Graph model, whose edits are
 * mapped back into the Graph block in one `doc.edit` each (one undo step, shared with the chart).
 *
 * A condition (interlock C, supervision V, a transition's condition) is one network: the
 * condition as the rung's logic and a fixed pseudo coil named `C`, `V` or the transition, as
 * S7-Graph draws them. An edit that leaves that shape (a second coil, another network, the
 * pseudo coil changed, a network title) is refused with a reason the view shows: a condition
 * is only a series of contacts, parallels and comparators. Contacts placed in front of the
 * pseudo coil (the coil's own branch) are the same AND and are moved into the logic.
 *
 * The permanent instructions are whole networks (coils, calls) and map one to one.
 */
import { useCallback, useMemo, useRef } from 'react';
import type { ElementStatus } from '../api/monitor';
import type { LadBlock, Network, Series } from '../lad/model';
import type { Diagnostic } from '../api/types';
import type { RungProblem } from '../lad/LadRung';
import type { Problems } from '../lad/problems';
import type { ElementState } from '../lad/status';
import type { LadDocument } from '../lad/useLadDocument';
import type { LadMonitoring } from '../lad/useLadMonitoring';
import type { GraphBlock } from './model';
import type { GraphDocument } from './useGraphDocument';

/** The id of the pseudo coil: never one the LAD editor gives (`e<n>`). */
export const PSEUDO_COIL = 'graph-out';

/** One condition shown as a network. */
export interface ConditionSlot {
  /** What the pseudo coil says: `C`, `V`, the transition's name. */
  coil: string;
  /** The network's title in the editor. */
  title: string;
  series: Series | null;
  /** The element origins' prefix in the monitoring (`S2/C/`, `T3/`). */
  origin: string;
  /** The Graph block with this condition replaced. */
  write: (block: GraphBlock, series: Series) => GraphBlock;
  /** The state of the pseudo coil online (the transition's TT, the error flag), if known. */
  coilState?: boolean | null;
}

/** Why an edit of a condition was not taken (the view shows it, translated). */
export type Refusal = 'networks' | 'outputs' | 'coil' | 'header' | 'stl';

const EMPTY: Series = { elements: [] };
const networkCache = new WeakMap<Series, Map<string, Network>>();

/** The network that shows a condition: the series and the pseudo coil. Cached per series. */
export function conditionNetwork(series: Series | null, coil: string, title: string): Network {
  const logic = series ?? EMPTY;
  const key = `${coil}\u0000${title}`;
  let byCoil = networkCache.get(logic);
  if (!byCoil) networkCache.set(logic, (byCoil = new Map()));
  const found = byCoil.get(key);
  if (found) return found;
  const network: Network = {
    title,
    comment: '',
    label: null,
    logic,
    outputs: [{ conditions: { elements: [] }, target: { id: PSEUDO_COIL, kind: 'coil', coil: '=', operand: coil, value: null } }],
    stl: null,
    stl_reason: null,
  };
  byCoil.set(key, network);
  return network;
}

/** The condition an edited network stands for, or why it is not one. */
export function seriesOf(before: Network, after: Network): Series | Refusal {
  if (after === before) return before.logic;
  if (after.stl !== null) return 'stl';
  if (after.title !== before.title || after.comment !== before.comment || after.label !== before.label) return 'header';
  if (after.outputs.length !== 1) return 'outputs';
  const [output] = after.outputs;
  const target = output?.target;
  const pseudo = before.outputs[0]?.target;
  if (!output || !target || target.kind !== 'coil' || target.id !== PSEUDO_COIL || !pseudo || pseudo.kind !== 'coil') return 'outputs';
  if (target.coil !== pseudo.coil || target.operand !== pseudo.operand || target.value !== pseudo.value) return 'coil';
  if (output.conditions.elements.length === 0) return after.logic;
  return { elements: [...after.logic.elements, ...output.conditions.elements] };
}

/** The synthetic LAD block of a Graph block: its name and declarations, the given networks. */
export function syntheticBlock(block: GraphBlock, networks: Network[]): LadBlock {
  return { language: 'LAD', kind: 'FB', name: block.name, return_type: null, title: block.title, declarations: block.declarations, networks };
}

/**
 * Maps an edit of the synthetic block of `slots` back: the Graph block with every changed
 * condition written, or the reason it cannot be.
 */
export function applyConditionEdit(block: GraphBlock, slots: readonly ConditionSlot[], before: LadBlock, after: LadBlock): GraphBlock | Refusal {
  if (after.networks.length !== before.networks.length) return 'networks';
  let result = block;
  for (let k = 0; k < slots.length; k += 1) {
    const slot = slots[k];
    const was = before.networks[k];
    const now = after.networks[k];
    if (!slot || !was || !now || now === was) continue;
    const series = seriesOf(was, now);
    if (typeof series === 'string') return series;
    if (series !== slot.series) result = slot.write(result, series);
  }
  return result;
}

interface Mapping {
  /** The synthetic block of the Graph block. */
  build: (block: GraphBlock) => LadBlock;
  /** The Graph block after the synthetic block changed from `before` to `after`. */
  apply: (block: GraphBlock, before: LadBlock, after: LadBlock) => GraphBlock | Refusal;
}

/**
 * A LAD document over Graph block `index` of `doc` through `mapping`; `onRefused` hears of an
 * edit that was not taken. Undo and redo are the Graph document's.
 */
function useMappedDoc(doc: GraphDocument, index: number, mapping: Mapping, onRefused: (why: Refusal) => void): LadDocument {
  const graphBlock = doc.blocks?.[index] ?? null;
  const blocks = useMemo(() => (graphBlock ? [mapping.build(graphBlock)] : null), [graphBlock, mapping]);
  const refusedRef = useRef(onRefused);
  refusedRef.current = onRefused;
  const { edit: graphEdit } = doc;
  const edit = useCallback(
    (change: (blocks: readonly LadBlock[]) => readonly LadBlock[], label: string) => {
      let refused: Refusal | null = null;
      graphEdit((all) => {
        const current = all[index];
        if (!current) return all;
        const before = mapping.build(current);
        const after = change([before])[0];
        if (!after || after === before) return all;
        const mapped = mapping.apply(current, before, after);
        if (typeof mapped === 'string') {
          refused = mapped;
          return all;
        }
        if (mapped === current) return all;
        return all.map((block, k) => (k === index ? mapped : block));
      }, label);
      if (refused) refusedRef.current(refused);
    },
    [graphEdit, index, mapping],
  );
  return {
    state: doc.state,
    blocks,
    pending: doc.pending,
    edit,
    undo: doc.undo,
    redo: doc.redo,
    canUndo: doc.canUndo,
    canRedo: doc.canRedo,
    retry: doc.retry,
  };
}

/** The LAD document of the conditions `slotsOf` gives for Graph block `index` (one network each). */
export function useConditionDoc(
  doc: GraphDocument,
  index: number,
  slotsOf: (block: GraphBlock) => readonly ConditionSlot[],
  onRefused: (why: Refusal) => void,
): LadDocument {
  const mapping = useMemo<Mapping>(
    () => ({
      build: (block) => syntheticBlock(block, slotsOf(block).map((slot) => conditionNetwork(slot.series, slot.coil, slot.title))),
      apply: (block, before, after) => applyConditionEdit(block, slotsOf(block), before, after),
    }),
    [slotsOf],
  );
  return useMappedDoc(doc, index, mapping, onRefused);
}

/** The LAD document of the permanent pre- or post-instructions of Graph block `index`. */
export function usePermanentDoc(
  doc: GraphDocument,
  index: number,
  which: 'pre' | 'post',
  setPermanent: (block: GraphBlock, which: 'pre' | 'post', networks: Network[]) => GraphBlock,
): LadDocument {
  const mapping = useMemo<Mapping>(
    () => ({
      build: (block) => permanentBlock(block, which),
      apply: (block, _before, after) => setPermanent(block, which, after.networks),
    }),
    [which, setPermanent],
  );
  return useMappedDoc(doc, index, mapping, () => undefined);
}

const permanentCache = new WeakMap<Network[], LadBlock>();

/** The synthetic block of the permanent networks (cached per network list, so views keep their layouts). */
export function permanentBlock(block: GraphBlock, which: 'pre' | 'post'): LadBlock {
  const networks = block[which];
  const found = permanentCache.get(networks);
  if (found && found.name === block.name && found.declarations === block.declarations) return found;
  const made = syntheticBlock(block, networks);
  permanentCache.set(networks, made);
  return made;
}

/**
 * The element states of the synthetic networks from the Graph monitoring: network k's states
 * are the elements whose origin starts with slot k's prefix (`S2/C/e1` → `e1`), and the pseudo
 * coil shows the slot's own state.
 */
export function conditionStates(
  elements: ReadonlyMap<string, ElementStatus>,
  slots: readonly { origin: string; coilState?: boolean | null }[],
): ReadonlyMap<string, ElementState>[] {
  const out = slots.map(() => new Map<string, ElementState>());
  for (const [origin, status] of elements) {
    for (let k = 0; k < slots.length; k += 1) {
      const prefix = slots[k]?.origin ?? '';
      if (origin.startsWith(prefix) && !origin.slice(prefix.length).includes('/')) {
        out[k]?.set(origin.slice(prefix.length), { value: status.value, out: status.out, pins: status.pins });
      }
    }
  }
  slots.forEach((slot, k) => {
    if (slot.coilState !== undefined && slot.coilState !== null) out[k]?.set(PSEUDO_COIL, { value: slot.coilState, out: slot.coilState, pins: {} });
  });
  return out;
}

/** A {@link LadMonitoring} over states computed by the host (null: offline). */
export function externalStatus(states: readonly ReadonlyMap<string, ElementState>[] | null): LadMonitoring | null {
  if (!states) return null;
  return { online: true, statesOf: (network) => states[network - 1], heldNetwork: null };
}

/**
 * The checker's findings on the synthetic networks (the file's diagnostics whose element is
 * `S2/C`, `S2/C/e1`, `T3/e2` ...): network k gets those of slot k, on its elements or on itself.
 */
export function conditionProblems(diagnostics: readonly Diagnostic[], file: string | null, slots: readonly { origin: string }[], message: (d: Diagnostic) => string): Problems {
  const out: Problems = { block: new Map(), networks: new Map() };
  if (!file) return out;
  for (const diagnostic of diagnostics) {
    const element = diagnostic.span?.element;
    if (diagnostic.span?.file !== file || !element || diagnostic.severity === 'info') continue;
    const k = slots.findIndex((slot) => element === slot.origin.slice(0, -1) || (element.startsWith(slot.origin) && !element.slice(slot.origin.length).includes('/')));
    const slot = slots[k];
    if (!slot) continue;
    const key = `0:${k}`;
    const entry = out.networks.get(key) ?? { network: [] as RungProblem[], elements: new Map<string, RungProblem[]>(), elementCount: 0 };
    const problem: RungProblem = { code: diagnostic.code, message: message(diagnostic), severity: diagnostic.severity };
    const id = element.startsWith(slot.origin) ? element.slice(slot.origin.length) : null;
    if (id) {
      entry.elements.set(id, [...(entry.elements.get(id) ?? []), problem]);
      entry.elementCount += 1;
    } else entry.network.push(problem);
    out.networks.set(key, entry);
  }
  return out;
}
