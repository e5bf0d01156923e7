/**
 * Element ids in reading order: the n-th element of a network is `en` unless it has an id. A port
 * of backend/nasaq/lang/lad/text_ids.py, held equal to it by tests/frontend/ladParity.test.ts.
 *
 * Reading order is the order of the text format: the rung's logic left to right (a PARALLEL before
 * its branches, a box before the logic wired into its pins), then each output's conditions and its
 * final element. The editor numbers a network after every edit the way the server's reader numbers
 * the saved text, so both hold the same ids.
 */
import type { Box, Element, Final, Network, Output, Series } from './model';

export function defaultId(position: number): string {
  return `e${position}`;
}

/** The network with every element named (given ids kept), and the ids naming more than one. */
export interface Numbered {
  network: Network;
  duplicates: string[];
}

/** One walk over a network in reading order, counting positions and remembering the names. */
class Numbering {
  private count = 0;
  private readonly seen = new Set<string>();
  readonly duplicates: string[] = [];

  name(given: string): string {
    this.count += 1;
    const chosen = given || defaultId(this.count);
    if (this.seen.has(chosen)) this.duplicates.push(chosen);
    this.seen.add(chosen);
    return chosen;
  }

  series(series: Series): Series {
    return { ...series, elements: series.elements.map((element) => this.element(element)) };
  }

  element(element: Element): Element {
    // The element is named before what it holds: that is its place in reading order.
    const named = this.name(element.id);
    if (element.kind === 'parallel') {
      return { ...element, id: named, branches: element.branches.map((branch) => this.series(branch)) };
    }
    if (element.kind === 'box') return this.box(element, named);
    return { ...element, id: named };
  }

  box(box: Box, named: string): Box {
    const inputs: Record<string, string | Series> = {};
    for (const [pin, value] of Object.entries(box.inputs)) {
      inputs[pin] = typeof value === 'string' ? value : this.series(value);
    }
    return { ...box, id: named, inputs };
  }

  final(final: Final): Final {
    const named = this.name(final.id);
    if (final.kind === 'box') return this.box(final, named);
    return { ...final, id: named };
  }

  output(output: Output): Output {
    // Conditions first, then the target: the order the text writes an output in.
    const conditions = this.series(output.conditions);
    return { ...output, conditions, target: this.final(output.target) };
  }
}

/**
 * The network with every element named (given ids kept), and the ids that name more than one
 * element (a given id may also clash with the number of a later element).
 */
export function numberElements(network: Network): Numbered {
  const numbering = new Numbering();
  const logic = numbering.series(network.logic);
  const outputs = network.outputs.map((output) => numbering.output(output));
  return { network: { ...network, logic, outputs }, duplicates: numbering.duplicates };
}

/** The network with every element named, as the server's reader numbers it. */
export function numberNetwork(network: Network): Network {
  return numberElements(network).network;
}
