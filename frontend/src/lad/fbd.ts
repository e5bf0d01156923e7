/**
 * The FBD view of the network model: the rung drawn as boxes and wires. A port of the LAD → FBD
 * direction of backend/nasaq/lang/lad/fbd.py (`to_fbd`), held equal to it by
 * tests/frontend/ladParity.test.ts; reading FBD back into LAD (`from_fbd`) stays on the server.
 *
 * A series is an AND box, a parallel an OR box; a contact is an operand on a pin (a normally closed
 * one negated); an element taking the power flow so far (NOT, an edge, a midline, a box with EN or
 * a timer's S) is a box whose flow input is everything left of it, and what follows it is ANDed to
 * its output. The common logic feeds every output through a T-branch. A parallel after other
 * elements whose branches act on the flow becomes an OR whose `flow` is the AND of the flow into
 * it, each branch starting from a T-branch of that AND's wire, as the lowering to STL reads it.
 */
import { boxSpec, flowPins } from './boxes';
import type {
  Box,
  Element,
  FbdBox,
  FbdBranch,
  FbdFinal,
  FbdLogic,
  FbdNetwork,
  FbdNode,
  Network,
  Output,
  Parallel,
  Series,
} from './model';

/** Whether box `name` takes the power flow so far (EN, S ...) rather than being ANDed. */
export function takesFlow(name: string): boolean {
  return flowPins(name)[0] !== null;
}

/**
 * Whether an element acts on the whole power flow into it (it writes memory, runs code or inverts
 * the flow): inside a parallel after other elements it must see that flow too. The lowering's
 * `needs_whole_flow` (to_stl_boxes.py), which decides both the STL and the FBD shape.
 */
export function needsWholeFlow(element: Element): boolean {
  switch (element.kind) {
    case 'edge':
    case 'midline':
    case 'not':
      return true;
    case 'box': {
      const spec = boxSpec(element.name);
      return spec === null || spec.family !== 'compare';
    }
    case 'parallel':
      return element.branches.some((branch) => branch.elements.some(needsWholeFlow));
    default:
      return false;
  }
}

function logic(id: string, op: FbdLogic['op'], inputs: FbdNode[], flow: FbdNode | null = null): FbdLogic {
  return { id, kind: 'logic', op, inputs, flow };
}

function branch(source = ''): FbdBranch {
  return { id: '', kind: 'branch', source };
}

/** A network kept as STL: no logic (the empty AND) and no outputs. */
function stlNetwork(network: Network): FbdNetwork {
  return {
    title: network.title,
    comment: network.comment,
    label: network.label,
    logic: logic('', 'AND', []),
    outputs: [],
    stl: network.stl,
    stl_reason: network.stl_reason,
  };
}

/** Numbers the AND boxes it creates (`&1`, `&2` ...) in reading order, as the server does. */
class ToFbd {
  private ands = 0;

  network(network: Network): FbdNetwork {
    if (network.stl !== null) return stlNetwork(network);
    const common = this.series(network.logic);
    const outputs = network.outputs.map((output) => this.final(output));
    return { title: network.title, comment: network.comment, label: network.label, logic: common, outputs, stl: null, stl_reason: null };
  }

  final(output: Output): FbdFinal {
    const flow = this.series(output.conditions, branch());
    const target = output.target;
    switch (target.kind) {
      case 'coil':
        return { id: target.id, kind: 'assign', coil: target.coil, operand: target.operand, value: target.value, input: flow };
      case 'jump':
        return { id: target.id, kind: 'jump', negated: target.negated, label: target.label, input: flow };
      case 'ret':
        return { id: target.id, kind: 'ret', input: flow };
      case 'opn':
        return { id: target.id, kind: 'opn', block: target.block, input: flow };
      case 'box':
        return this.box(target, flow);
    }
  }

  /** AND of the series' terms; an element taking the flow so far closes the AND. */
  series(series: Series, head: FbdNode | null = null): FbdNode {
    let terms: FbdNode[] = head === null ? [] : [head];
    for (const element of series.elements) {
      if (element.kind === 'contact') {
        terms.push({ id: element.id, kind: 'operand', operand: element.operand, negated: element.negated });
      } else if (element.kind === 'status') {
        terms.push({ id: element.id, kind: 'status', bit: element.bit, negated: element.negated });
      } else if (element.kind === 'parallel') {
        terms = this.parallel(element, terms);
      } else if (element.kind === 'box' && !takesFlow(element.name)) {
        terms.push(this.box(element, null));
      } else {
        terms = [this.flowElement(element, this.conjunction(terms))];
      }
    }
    return this.conjunction(terms);
  }

  /**
   * The terms with the OR box of `parallel` added; when its branches act on the flow and something
   * comes before it, the OR replaces the terms: they become its `flow`.
   */
  parallel(parallel: Parallel, terms: FbdNode[]): FbdNode[] {
    if (terms.length === 0 || !needsWholeFlow(parallel)) {
      const branches = parallel.branches.map((item) => this.series(item));
      return [...terms, logic(parallel.id, 'OR', branches)];
    }
    this.ands += 1;
    const flow = logic(`&${this.ands}`, 'AND', terms);
    const branches = parallel.branches.map((item) => this.series(item, branch(flow.id)));
    return [logic(parallel.id, 'OR', branches, flow)];
  }

  flowElement(element: Exclude<Element, { kind: 'contact' | 'status' | 'parallel' }>, flow: FbdNode): FbdNode {
    switch (element.kind) {
      case 'not':
        return { id: element.id, kind: 'not', input: flow };
      case 'edge':
        return { id: element.id, kind: 'edge', edge: element.edge, memory: element.memory, input: flow };
      case 'midline':
        return { id: element.id, kind: 'midline', operand: element.operand, input: flow };
      case 'box':
        return this.box(element, flow);
    }
  }

  box(box: Box, flow: FbdNode | null): FbdBox {
    const inputs: Record<string, string | FbdNode> = {};
    for (const [pin, value] of Object.entries(box.inputs)) {
      inputs[pin] = typeof value === 'string' ? value : this.series(value);
    }
    return { id: box.id, kind: 'box', name: box.name, instance: box.instance, en: flow, inputs, outputs: { ...box.outputs } };
  }

  conjunction(terms: FbdNode[]): FbdNode {
    if (terms.length === 1 && terms[0] !== undefined) return terms[0];
    this.ands += 1;
    return logic(`&${this.ands}`, 'AND', terms);
  }
}

/** The FBD view of a LAD network; every network has one. */
export function toFbd(network: Network): FbdNetwork {
  return new ToFbd().network(network);
}
