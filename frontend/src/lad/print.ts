/**
 * Writes LAD/FBD blocks in the text format the server reads (grammars/lad.lark). A port of
 * backend/nasaq/lang/lad/text_print.py whose output is byte for byte the same (held by
 * tests/frontend/ladParity.test.ts), so the editor saves what the server would write.
 *
 * The layout aims at small diffs: one element per line in a rung, a PARALLEL over several lines
 * with each branch on one line while it fits, a box on one line while it fits (else one pin per
 * line). Ids equal to their reading-order number are left out; the reader numbers them again.
 */
import { PYTHON_SPACE } from './boxes';
import { defaultId } from './ids';
import type { Box, Element, Final, LadBlock, Network, Series } from './model';

const WIDTH = 100;
const INDENT = '  ';
const OPENERS = { OB: 'ORGANIZATION_BLOCK', FB: 'FUNCTION_BLOCK', FC: 'FUNCTION' } as const;
const COILS: Readonly<Record<string, string>> = { '=': 'Coil', S: 'SetCoil', R: 'ResetCoil' };

type Node = Element | Final;

/** The length Python's `len` gives: code points, so a symbol outside the BMP counts once. */
function length(text: string): number {
  return [...text].length;
}

function fits(depth: number, line: string): boolean {
  return length(INDENT.repeat(depth) + line) <= WIDTH;
}

const LEADING_SPACE = new RegExp(`^[${PYTHON_SPACE}]+`, 'u');
const TRAILING_SPACE = new RegExp(`[${PYTHON_SPACE}]+$`, 'u');

/** Python's `str.rstrip()`: the whitespace Python knows, not JavaScript's `trimEnd` set. */
export function rstrip(text: string): string {
  return text.replace(TRAILING_SPACE, '');
}

export function strip(text: string): string {
  return rstrip(text).replace(LEADING_SPACE, '');
}

/** A title written on one line: its lines joined by spaces. */
export function oneLine(text: string): string {
  return strip(text.split('\n').join(' '));
}

/** An element without nested elements, without its id. */
function simple(node: Node): string {
  switch (node.kind) {
    case 'contact':
      return `${node.negated ? 'ContactNC' : 'Contact'}(${node.operand})`;
    case 'status':
      return `${node.negated ? 'StatusNC' : 'Status'}(${node.bit})`;
    case 'not':
      return 'Not';
    case 'edge':
      return `Edge(${node.edge}, ${node.memory})`;
    case 'midline':
      return `Midline(${node.operand})`;
    case 'coil': {
      if (node.coil === 'SAVE') return 'Save';
      const value = node.value === null ? '' : `, ${node.value}`;
      return `${COILS[node.coil] ?? node.coil}(${node.operand}${value})`;
    }
    case 'jump':
      return `${node.negated ? 'JumpN' : 'Jump'}(${node.label})`;
    case 'ret':
      return 'Return';
    case 'opn':
      return `Open(${node.block})`;
    case 'box':
    case 'parallel':
      throw new Error(`a ${node.kind} holds elements: it is not a simple element`);
  }
}

function hasParallel(nodes: readonly Node[]): boolean {
  return nodes.some((node) => node.kind === 'parallel');
}

/** Writes one block's lines, counting elements in reading order to know which ids to write. */
class Printer {
  count = 0;
  readonly out: string[] = [];

  /** ` @id` unless the id is the one the reader gives this position. */
  tag(elementId: string): string {
    this.count += 1;
    return elementId && elementId !== defaultId(this.count) ? ` @${elementId}` : '';
  }

  // ---- one line ---------------------------------------------------------------------------
  inline(node: Node): string {
    if (node.kind === 'parallel') {
      const tag = this.tag(node.id);
      const branches = node.branches.map((branch) => `BRANCH ${this.seriesInline(branch)}END_BRANCH`).join(' ');
      return `PARALLEL${tag} ${branches} END_PARALLEL`;
    }
    if (node.kind === 'box') {
      const tag = this.tag(node.id);
      return `Box(${this.boxItems(node).join(', ')})${tag}`;
    }
    return simple(node) + this.tag(node.id);
  }

  seriesInline(series: Series): string {
    return series.elements.map((element) => `${this.inline(element)} `).join('');
  }

  boxItems(box: Box): string[] {
    const items = [box.name];
    if (box.instance !== null) items.push(`INSTANCE ${box.instance}`);
    for (const [pin, value] of Object.entries(box.inputs)) {
      items.push(typeof value === 'string' ? `${pin} := ${value}` : `${pin} := RUNG ${this.seriesInline(value)}END_RUNG`);
    }
    for (const [pin, value] of Object.entries(box.outputs)) items.push(`${pin} => ${value}`);
    return items;
  }

  // ---- lines ------------------------------------------------------------------------------
  emit(depth: number, text: string): void {
    this.out.push(INDENT.repeat(depth) + text);
  }

  element(node: Node, depth: number): void {
    if (node.kind === 'parallel') {
      this.emit(depth, `PARALLEL${this.tag(node.id)}`);
      for (const branch of node.branches) this.branch(branch, null, depth + 1);
      this.emit(depth, 'END_PARALLEL');
      return;
    }
    // A line is tried first; when a box does not fit, its ids are counted again over its lines.
    const start = this.count;
    const line = this.inline(node);
    if (node.kind !== 'box' || fits(depth, line)) {
      this.emit(depth, line);
      return;
    }
    this.count = start;
    this.boxLines(node, depth);
  }

  /**
   * A box too wide for one line: one pin a line, logic in a pin over several lines when it does
   * not fit or holds a PARALLEL.
   */
  boxLines(box: Box, depth: number): void {
    const tag = this.tag(box.id);
    const pins: [string, string | Series][] = [];
    if (box.instance !== null) pins.push(['INSTANCE ', box.instance]);
    for (const [pin, value] of Object.entries(box.inputs)) pins.push([`${pin} := `, value]);
    for (const [pin, value] of Object.entries(box.outputs)) pins.push([`${pin} => `, value]);
    this.emit(depth, `Box(${box.name},`);
    pins.forEach(([head, value], index) => {
      const end = index + 1 === pins.length ? `)${tag}` : ',';
      if (typeof value === 'string') this.emit(depth + 2, head + value + end);
      else this.pinLogic(head, value, end, depth + 2);
    });
  }

  pinLogic(head: string, value: Series, end: string, depth: number): void {
    const start = this.count;
    const line = `${head}RUNG ${this.seriesInline(value)}END_RUNG${end}`;
    if (!hasParallel(value.elements) && fits(depth, line)) {
      this.emit(depth, line);
      return;
    }
    this.count = start;
    this.emit(depth, `${head}RUNG`);
    for (const element of value.elements) this.element(element, depth + 1);
    this.emit(depth, `END_RUNG${end}`);
  }

  /** `BRANCH ... END_BRANCH` on one line when it fits and holds no PARALLEL. */
  branch(series: Series, final: Final | null, depth: number): void {
    const nodes: Node[] = [...series.elements, ...(final ? [final] : [])];
    const start = this.count;
    if (!hasParallel(nodes)) {
      const line = `BRANCH ${nodes.map((node) => `${this.inline(node)} `).join('')}END_BRANCH`;
      if (fits(depth, line)) {
        this.emit(depth, line);
        return;
      }
    }
    this.count = start;
    this.emit(depth, 'BRANCH');
    for (const node of nodes) this.element(node, depth + 1);
    this.emit(depth, 'END_BRANCH');
  }

  network(network: Network): void {
    this.count = 0;
    this.emit(0, 'NETWORK');
    if (network.title) this.emit(0, `TITLE = ${oneLine(network.title)}`);
    if (network.comment) {
      for (const line of network.comment.split('\n')) this.emit(0, rstrip(`COMMENT = ${line}`));
    }
    if (network.label !== null) this.emit(0, `LABEL ${network.label}`);
    if (network.stl !== null) {
      const reason = network.stl_reason ? ` REASON ${network.stl_reason}` : '';
      this.emit(0, `STL${reason}`);
      if (network.stl) this.out.push(...network.stl.split('\n'));
      this.emit(0, 'END_STL');
      return;
    }
    this.emit(0, 'RUNG');
    for (const element of network.logic.elements) this.element(element, 1);
    this.outputs(network);
    this.emit(0, 'END_RUNG');
  }

  outputs(network: Network): void {
    const outputs = network.outputs;
    const logic = network.logic.elements;
    const only = outputs.length === 1 ? outputs[0] : undefined;
    if (outputs.length === 0 && logic.length > 0 && logic[logic.length - 1]?.kind === 'box') {
      // A rung being drawn that ends in a box: without the empty OUTPUTS the reader would take
      // the box for the rung's final element.
      this.emit(1, 'OUTPUTS');
      this.emit(1, 'END_OUTPUTS');
    } else if (only !== undefined && only.conditions.elements.length === 0) {
      this.element(only.target, 1);
    } else if (outputs.length > 0) {
      this.emit(1, 'OUTPUTS');
      for (const output of outputs) this.branch(output.conditions, output.target, 2);
      this.emit(1, 'END_OUTPUTS');
    }
  }

  block(block: LadBlock): void {
    const opener = OPENERS[block.kind];
    let head = `${opener} ${block.name}`;
    if (block.return_type !== null) head += ` : ${block.return_type}`;
    this.emit(0, head);
    if (block.title) this.emit(0, `TITLE = ${oneLine(block.title)}`);
    if (block.language === 'FBD') this.emit(0, 'LANGUAGE FBD');
    if (strip(block.declarations)) this.out.push(rstrip(block.declarations));
    this.emit(0, 'BEGIN');
    for (const network of block.networks) this.network(network);
    this.emit(0, `END_${opener}`);
  }
}

/** The text of `blocks`, one blank line between blocks, ending with a newline. */
export function printLad(blocks: readonly LadBlock[]): string {
  return blocks
    .map((block) => {
      const printer = new Printer();
      printer.block(block);
      return `${printer.out.join('\n')}\n`;
    })
    .join('\n');
}

/** The lines of one network (the Graph format's permanent instructions are LAD networks). */
export function networkLines(network: Network): string[] {
  const printer = new Printer();
  printer.network(network);
  return printer.out;
}

/**
 * The elements of `series` one per line at `depth`, ids numbered from `e1` as in a rung without
 * its final element (the Graph format's conditions).
 */
export function seriesLines(series: Series, depth: number): string[] {
  const printer = new Printer();
  for (const element of series.elements) printer.element(element, depth);
  return printer.out;
}
