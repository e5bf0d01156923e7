/**
 * The LAD/FBD editors' edits on the network model (frontend/src/lad/edits.ts): what TIA Portal's
 * commands do to a rung, checked through the text the file gets (the printer is the backend's,
 * held equal by ladParity.test.ts), so a test reads like the `.lad` file a user would see.
 */
import { describe, expect, it } from 'vitest';
import {
  BIT_PLACEHOLDER,
  closeBranch,
  emptyNetwork,
  endOfRung,
  insertElement,
  insertFinal,
  openBranch,
  pointAfter,
  removeAt,
  replaceElement,
  settle,
  shiftAlong,
  moveTo,
} from '../../frontend/src/lad/edits';
import type { LadBlock, Network } from '../../frontend/src/lad/model';
import { printLad } from '../../frontend/src/lad/print';
import { placesById, type Element, type Final, type Place } from '../../frontend/src/lad/tree';

const contact = (operand: string, negated = false): Element => ({ kind: 'contact', id: '', operand, negated });
const coil = (operand: string, kind: 'coil' = 'coil'): Final => ({ kind, id: '', coil: '=', operand, value: null });

function block(network: Network): LadBlock {
  return { language: 'LAD', kind: 'OB', name: 'OB 1', return_type: null, title: '', declarations: '', networks: [network] };
}

/** The rung's lines of the printed file (between RUNG and END_RUNG, trimmed). */
function rung(network: Network): string[] {
  const lines = printLad([block(network)]).split('\n');
  const start = lines.findIndex((line) => line.trim() === 'RUNG');
  const end = lines.findIndex((line) => line.trim() === 'END_RUNG');
  return lines.slice(start + 1, end).map((line) => line.trim());
}

function place(network: Network, id: string): Place {
  const found = placesById(network).get(id);
  if (!found) throw new Error(`no element ${id}`);
  return found;
}

/** The start/stop latch of the course, built as a user does with the favourites. */
function latch(): Network {
  let net = emptyNetwork();
  let edited = insertElement(net, endOfRung(net), contact('"Start"'));
  net = edited.network;
  edited = openBranch(net, place(net, edited.select as string), contact(BIT_PLACEHOLDER), coil(BIT_PLACEHOLDER));
  net = edited.network;
  const branchContact = edited.select as string;
  net = replaceElement(net, place(net, branchContact), contact('"Motor"')).network;
  edited = insertElement(net, endOfRung(net), contact('"Stop"', true));
  net = edited.network;
  edited = insertFinal(net, endOfRung(net), coil('"Motor"'));
  return edited.network;
}

describe('building a rung', () => {
  it('starts from an empty rung and numbers what it inserts in reading order', () => {
    const net = emptyNetwork();
    const edited = insertElement(net, endOfRung(net), contact('I 0.0'));
    expect(edited.select).toBe('e1');
    expect(rung(edited.network)).toEqual(['Contact(I 0.0)']);
    expect(edited.network.outputs).toEqual([]);
  });

  it('builds the start/stop latch: a parallel holding contact, a normally closed stop, the coil', () => {
    expect(rung(latch())).toEqual([
      'PARALLEL',
      'BRANCH Contact("Start") END_BRANCH',
      'BRANCH Contact("Motor") END_BRANCH',
      'END_PARALLEL',
      'ContactNC("Stop")',
      'Coil("Motor")',
    ]);
  });

  it('inserts right of the selected element, and before a coil when the coil is selected', () => {
    const net = latch();
    const stop = place(net, 'e4');
    const afterStop = insertElement(net, pointAfter(net, stop), contact('I 1.0')).network;
    expect(rung(afterStop).slice(4)).toEqual(['ContactNC("Stop")', 'Contact(I 1.0)', 'Coil("Motor")']);
    const beforeCoil = insertElement(net, pointAfter(net, place(net, 'e5')), contact('I 1.1')).network;
    expect(rung(beforeCoil).slice(-2)).toEqual(['Contact(I 1.1)', 'Coil("Motor")']);
  });

  it('a second coil on the common logic becomes a parallel output, splitting the rung where it was placed', () => {
    const net = latch();
    // After the parallel (before the NC stop): the stop moves into the first output's conditions.
    const split = insertFinal(net, { series: { root: 'logic', steps: [] }, index: 1 }, coil('Q 4.1')).network;
    expect(split.logic.elements.map((e) => e.kind)).toEqual(['parallel']);
    expect(split.outputs.map((o) => o.conditions.elements.length)).toEqual([1, 0]);
    expect(rung(split).slice(4)).toEqual(['OUTPUTS', 'BRANCH ContactNC("Stop") Coil("Motor") END_BRANCH', 'BRANCH Coil(Q 4.1) END_BRANCH', 'END_OUTPUTS']);
  });

  it('a box left at the end of a rung without a coil ends the rung, as the text reads it back', () => {
    const net = emptyNetwork();
    const box: Element = { kind: 'box', id: '', name: 'MOVE', instance: null, inputs: { IN: 'MW 0' }, outputs: { OUT: 'MW 2' } };
    const edited = insertElement(net, endOfRung(net), box);
    expect(edited.network.logic.elements).toEqual([]);
    expect(edited.network.outputs[0]?.target.kind).toBe('box');
    expect(edited.select).toBe('e1');
  });
});

describe('branches', () => {
  it('open branch on a parallel adds one more branch; on a coil it adds a parallel output', () => {
    const net = latch();
    const three = openBranch(net, place(net, 'e1'), contact('I 2.0'), coil(BIT_PLACEHOLDER)).network;
    const parallel = three.logic.elements[0];
    expect(parallel?.kind === 'parallel' ? parallel.branches.length : 0).toBe(3);
    const outputs = openBranch(net, place(net, 'e5'), contact('x'), coil('Q 4.2')).network;
    expect(outputs.outputs.map((o) => (o.target.kind === 'coil' ? o.target.operand : ''))).toEqual(['"Motor"', 'Q 4.2']);
  });

  it('close branch takes the next element into the main branch of the parallel', () => {
    const net = latch();
    const closed = closeBranch(net, place(net, 'e3')).network;
    expect(rung(closed)).toEqual([
      'PARALLEL',
      'BRANCH Contact("Start") ContactNC("Stop") END_BRANCH',
      'BRANCH Contact("Motor") END_BRANCH',
      'END_PARALLEL',
      'Coil("Motor")',
    ]);
  });

  it('deleting the only element of a branch removes the branch, and a parallel of one branch unwraps', () => {
    const net = latch();
    const removed = removeAt(net, place(net, 'e3'));
    expect(rung(removed.network)).toEqual(['Contact("Start")', 'ContactNC("Stop")', 'Coil("Motor")']);
    expect(removed.select).toBe('e1');
  });
});

describe('deleting and moving', () => {
  it('deleting the only coil keeps the rung unfinished; deleting one of several outputs takes its conditions', () => {
    const net = latch();
    const noCoil = removeAt(net, place(net, 'e5')).network;
    expect(noCoil.outputs).toEqual([]);
    expect(rung(noCoil)).toEqual(['PARALLEL', 'BRANCH Contact("Start") END_BRANCH', 'BRANCH Contact("Motor") END_BRANCH', 'END_PARALLEL', 'ContactNC("Stop")']);
    const two = insertFinal(net, { series: { root: 'logic', steps: [] }, index: 1 }, coil('Q 4.1')).network;
    const back = removeAt(two, { kind: 'target', output: 1 }).network;
    expect(back.outputs.length).toBe(1);
  });

  it('moves an element along its series, and to another wire position', () => {
    let net = emptyNetwork();
    for (const operand of ['a', 'b', 'c']) net = insertElement(net, endOfRung(net), contact(operand)).network;
    const shifted = shiftAlong(net, place(net, 'e1'), 1);
    expect(rung(shifted.network)).toEqual(['Contact(b)', 'Contact(a)', 'Contact(c)']);
    expect(shifted.select).toBe('e2');
    const moved = moveTo(net, place(net, 'e1'), { series: { root: 'logic', steps: [] }, index: 3 });
    expect(rung(moved.network)).toEqual(['Contact(b)', 'Contact(c)', 'Contact(a)']);
    expect(moved.select).toBe('e3');
  });

  it('moves an element into a branch of a parallel', () => {
    const net = latch();
    const moved = moveTo(net, place(net, 'e4'), { series: { root: 'logic', steps: [{ element: 0, branch: 1 }] }, index: 1 });
    expect(rung(moved.network)).toEqual(['PARALLEL', 'BRANCH Contact("Start") END_BRANCH', 'BRANCH Contact("Motor") ContactNC("Stop") END_BRANCH', 'END_PARALLEL', 'Coil("Motor")']);
  });
});

describe('settle', () => {
  it('keeps ids the user gave and renumbers the default ones', () => {
    const net: Network = {
      ...emptyNetwork(),
      logic: { elements: [{ ...contact('a'), id: 'start' }, { ...contact('b'), id: 'e7' }] },
      outputs: [{ conditions: { elements: [] }, target: { ...coil('q'), id: 'e1' } }],
    };
    const settled = settle(net).network;
    expect(settled.logic.elements.map((e) => e.id)).toEqual(['start', 'e2']);
    expect(settled.outputs[0]?.target.id).toBe('e3');
  });
});
