/**
 * The pure edits of a Graph block (frontend/src/graph/edits.ts) on the course's charts (the
 * blocks of fixtures/graph-parity.json, as the server's reader gives them): each result is a legal
 * chart by the checker's structure rules (a small validator below), the text spliced for it reads
 * as the edited model (every step and transition written as the printer writes it, in the model's
 * order), and the specific edits on the two-conveyor sequence (g17) give S7-Graph's shapes.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import {
  addSequencer,
  deleteItem,
  insertAlternativeBranch,
  insertJump,
  insertSequenceEnd,
  insertSimultaneousBranch,
  insertStepAfter,
  moveBranch,
  renameStep,
  renameTransition,
  renumber,
  setPermanent,
  setSettings,
  setStepNumber,
  setTransitionNumber,
  updateStep,
  updateTransition,
} from '../../frontend/src/graph/edits';
import type { GraphBlock, Sequencer, Step, Transition } from '../../frontend/src/graph/model';
import { stepLines, transitionLines } from '../../frontend/src/graph/print';
import type { GraphItem } from '../../frontend/src/graph/selection';
import { scanText, spliceText } from '../../frontend/src/graph/textEdit';

interface Entry {
  name: string;
  source: string;
  blocks: GraphBlock[];
}

const entries = (JSON.parse(fs.readFileSync(path.join(__dirname, 'fixtures', 'graph-parity.json'), 'utf-8')) as { entries: Entry[] }).entries;
const scenarios = entries.filter((entry) => entry.name.startsWith('tests/scenarios/graph/'));
const g17 = scenarios.find((entry) => entry.name.endsWith('g17_conveyors.graph')) as Entry;
const conveyors = g17.blocks[0] as GraphBlock;

const upper = (name: string) => name.toUpperCase();

/** The checker's structure errors (check_structure.py) and unreachable steps, as messages. */
function structureProblems(block: GraphBlock): string[] {
  const problems: string[] = [];
  const steps = block.sequencers.flatMap((sequencer, seq) => sequencer.steps.map((step) => ({ step, seq })));
  const transitions = block.sequencers.flatMap((sequencer, seq) => sequencer.transitions.map((transition) => ({ transition, seq })));
  const stepSeq = new Map(steps.map(({ step, seq }) => [upper(step.name), seq]));
  const numbers = (list: number[], what: string) => {
    const seen = new Set<number>();
    for (const n of list) {
      if (seen.has(n) || n < 1) problems.push(`${what} number ${n} twice or invalid`);
      seen.add(n);
    }
  };
  numbers(steps.map(({ step }) => step.number), 'step');
  numbers(transitions.map(({ transition }) => transition.number), 'transition');
  const names = new Set<string>();
  for (const item of [...steps.map(({ step }) => step), ...transitions.map(({ transition }) => transition)]) {
    if (names.has(upper(item.name))) problems.push(`name ${item.name} twice`);
    if (!/^[A-Za-z_]\w*$/.test(item.name)) problems.push(`name ${item.name} invalid`);
    names.add(upper(item.name));
  }
  const left = new Set<string>();
  for (const { transition, seq } of transitions) {
    for (const list of [transition.source, transition.target]) {
      if (new Set(list.map(upper)).size !== list.length) problems.push(`${transition.name} names a step twice`);
      for (const name of list) if (!stepSeq.has(upper(name))) problems.push(`${transition.name}: no step ${name}`);
    }
    if (transition.source.length === 0) problems.push(`${transition.name} has no source`);
    for (const name of transition.source) {
      left.add(upper(name));
      if (stepSeq.get(upper(name)) !== seq) problems.push(`${transition.name} leaves ${name} of another sequencer`);
    }
    if (transition.target.length > 1 && transition.target.some((name) => stepSeq.get(upper(name)) !== seq)) {
      problems.push(`${transition.name} opens branches in another sequencer`);
    }
    if (transition.jump && transition.target.length !== 1) problems.push(`${transition.name} jumps to ${transition.target.length} steps`);
  }
  for (const { step } of steps) if (!left.has(upper(step.name))) problems.push(`no transition leaves ${step.name}`);
  block.sequencers.forEach((sequencer) => {
    if (sequencer.steps.length === 0) problems.push(`sequencer ${sequencer.name} is empty`);
  });
  // Reachability from the initial steps (a convergence is followed when any source is reached).
  const reached = new Set(steps.filter(({ step }) => step.initial).map(({ step }) => upper(step.name)));
  for (let changed = true; changed; ) {
    changed = false;
    for (const { transition } of transitions) {
      if (!transition.source.some((name) => reached.has(upper(name)))) continue;
      for (const name of transition.target) {
        if (!reached.has(upper(name))) {
          reached.add(upper(name));
          changed = true;
        }
      }
    }
  }
  if (reached.size > 0) for (const { step } of steps) if (!reached.has(upper(step.name))) problems.push(`${step.name} unreachable`);
  return problems;
}

/**
 * The spliced text reads as `after`: the scanner finds every step and transition of the model in
 * its order, and each is written exactly as the printer writes it (what the parity test holds to
 * the Python reader).
 */
function expectTextOf(text: string, after: GraphBlock): void {
  const spans = scanText(text, [after]);
  expect(spans, 'the spliced text has the model structure').not.toBeNull();
  const lines = text.split('\n');
  after.sequencers.forEach((sequencer, s) => {
    const found = spans?.[0]?.sequencers[s];
    for (const item of found?.items ?? []) {
      const model =
        item.kind === 'step'
          ? stepLines(sequencer.steps.find((step) => step.name === item.name) as Step)
          : transitionLines(sequencer.transitions.find((t) => t.name === item.name) as Transition);
      const written = lines.slice(item.start, item.end);
      if (written.join('\n') !== model.join('\n')) {
        // Untouched hand-written items keep their layout: they must be what they were in the source.
        expect(g17.source.includes(written.join('\n')) || scenarios.some((e) => e.source.includes(written.join('\n'))), `${item.name} written`).toBe(true);
      }
    }
  });
}

function legal(block: GraphBlock): void {
  expect(structureProblems(block)).toEqual([]);
}

function sequencer(block: GraphBlock, seq = 0): Sequencer {
  return block.sequencers[seq] as Sequencer;
}

function step(block: GraphBlock, name: string): Step {
  return block.sequencers.flatMap((s) => s.steps).find((s) => s.name === name) as Step;
}

function transition(block: GraphBlock, name: string): Transition {
  return block.sequencers.flatMap((s) => s.transitions).find((t) => t.name === name) as Transition;
}

const S = (name: string): GraphItem => ({ kind: 'step', name });
const T = (name: string): GraphItem => ({ kind: 'transition', name });

describe('the course charts are legal to start with', () => {
  it('g17 and the other scenarios', () => {
    legal(conveyors);
    const legalOnes = scenarios.filter((entry) => entry.blocks.every((block) => structureProblems(block).length === 0));
    expect(legalOnes.length).toBeGreaterThan(25);
  });
});

describe('edits on the two-conveyor sequence (g17)', () => {
  it('inserts a step+transition after a step: the step\'s exits leave from the new step', () => {
    const { block, select } = insertStepAfter(conveyors, 0, S('A_on'));
    legal(block);
    expect(select).toEqual(S('Step7'));
    expect(step(block, 'Step7')).toMatchObject({ number: 7, initial: false, actions: [] });
    expect(transition(block, 'Trans11')).toMatchObject({ number: 11, source: ['A_on'], target: ['Step7'], jump: false, condition: null });
    expect(transition(block, 'Trans6')).toMatchObject({ source: ['Step7'], target: ['Idle'], jump: true });
    expect(sequencer(block).steps.map((s) => s.name)).toEqual(['Idle', 'B_on', 'A_on', 'Step7', 'A_off', 'B_off', 'Emergency']);
    const text = spliceText(g17.source, g17.blocks, [block]);
    expectTextOf(text, block);
    expect(text).toContain('TRANSITION Trans11 (11) FROM A_on TO Step7\nEND_TRANSITION');
    expect(text.startsWith(g17.source.slice(0, g17.source.indexOf('STEP A_on')))).toBe(true);
  });

  it('inserts a step+transition at a transition: T -> new step -> T\'s old target', () => {
    const { block, select } = insertStepAfter(conveyors, 0, T('Trans5'));
    legal(block);
    expect(select).toEqual(S('Step7'));
    expect(transition(block, 'Trans5')).toMatchObject({ source: ['B_on'], target: ['Step7'], jump: false });
    expect(transition(block, 'Trans11')).toMatchObject({ source: ['Step7'], target: ['A_on'], jump: false });
    expect(sequencer(block).steps.map((s) => s.name).slice(0, 4)).toEqual(['Idle', 'B_on', 'Step7', 'A_on']);
    expectTextOf(spliceText(g17.source, g17.blocks, [block]), block);
    // At a jump, the new transition jumps.
    const jumped = insertStepAfter(conveyors, 0, T('Trans6')).block;
    legal(jumped);
    expect(transition(jumped, 'Trans11')).toMatchObject({ source: ['Step7'], target: ['Idle'], jump: true });
    expect(transition(jumped, 'Trans6')).toMatchObject({ target: ['Step7'], jump: false });
  });

  it('inserts an alternative branch at a step, closing into the first exit\'s target', () => {
    const { block, select } = insertAlternativeBranch(conveyors, 0, S('Idle'));
    legal(block);
    expect(select).toEqual(S('Step7'));
    const fromIdle = sequencer(block).transitions.filter((t) => t.source[0] === 'Idle').map((t) => t.name);
    expect(fromIdle).toEqual(['Trans1', 'Trans2', 'Trans3', 'Trans11']); // the lowest priority
    expect(transition(block, 'Trans12')).toMatchObject({ source: ['Step7'], target: ['Emergency'], jump: false });
    expectTextOf(spliceText(g17.source, g17.blocks, [block]), block);
  });

  it('inserts a simultaneous branch at a transition, joined where the first branch goes on', () => {
    const { block, select } = insertSimultaneousBranch(conveyors, 0, T('Trans2'));
    legal(block);
    expect(select).toEqual(S('Step7'));
    expect(transition(block, 'Trans2').target).toEqual(['B_on', 'Step7']);
    expect(transition(block, 'Trans4').source).toEqual(['B_on', 'Step7']);
    expect(transition(block, 'Trans5').source).toEqual(['B_on', 'Step7']);
    expectTextOf(spliceText(g17.source, g17.blocks, [block]), block);
    // From a transition whose target goes on nowhere: the new branch ends.
    const ended = insertSequenceEnd(conveyors, 0, S('B_off')).block;
    const stop = sequencer(ended).transitions.find((t) => t.target.length === 0) as Transition;
    const branched = insertSimultaneousBranch(ended, 0, T(stop.name)).block;
    legal(branched);
  });

  it('inserts a jump and a sequence end, each the lowest priority of its step', () => {
    const jumped = insertJump(conveyors, 0, S('B_off'), 'Emergency');
    legal(jumped.block);
    expect(jumped.select).toEqual(T('Trans11'));
    expect(transition(jumped.block, 'Trans11')).toMatchObject({ source: ['B_off'], target: ['Emergency'], jump: true });
    expect(sequencer(jumped.block).transitions.map((t) => t.name).slice(8, 10)).toEqual(['Trans9', 'Trans11']);
    expect(insertJump(conveyors, 0, S('B_off'), 'Nowhere').block).toBe(conveyors);
    const ended = insertSequenceEnd(conveyors, 0, S('A_on'));
    legal(ended.block);
    expect(transition(ended.block, 'Trans11')).toMatchObject({ source: ['A_on'], target: [], jump: false });
    const text = spliceText(g17.source, g17.blocks, [ended.block]);
    expect(text).toContain('TRANSITION Trans11 (11) FROM A_on STOP\nEND_TRANSITION');
    expectTextOf(text, ended.block);
  });

  it('deletes a step with the transition below it; its entries lead on', () => {
    const deleted = deleteItem(conveyors, 0, S('A_on'));
    expect(deleted).not.toBeNull();
    legal(deleted!.block);
    expect(sequencer(deleted!.block).steps.map((s) => s.name)).not.toContain('A_on');
    expect(sequencer(deleted!.block).transitions.map((t) => t.name)).not.toContain('Trans6');
    expect(transition(deleted!.block, 'Trans5')).toMatchObject({ source: ['B_on'], target: ['Idle'], jump: true });
    const text = spliceText(g17.source, g17.blocks, [deleted!.block]);
    expectTextOf(text, deleted!.block);
    expect(text).not.toContain('A_on (3)');
    // The initial step: the mark moves on.
    const noIdle = deleteItem(insertStepAfter(conveyors, 0, S('Idle')).block, 0, S('Idle'));
    expect(noIdle).not.toBeNull();
    legal(noIdle!.block);
    expect(step(noIdle!.block, 'Step7').initial).toBe(true);
  });

  it('deletes a step with several exits together with the transition above it', () => {
    const deleted = deleteItem(conveyors, 0, S('B_on'));
    expect(deleted).not.toBeNull();
    legal(deleted!.block);
    expect(transition(deleted!.block, 'Trans4').source).toEqual(['Idle']);
    expect(transition(deleted!.block, 'Trans5').source).toEqual(['Idle']);
    expect(sequencer(deleted!.block).transitions.map((t) => t.name)).not.toContain('Trans2');
  });

  it('deletes transitions: an alternative branch alone, a chain link with its step, refuses the rest', () => {
    const jump = deleteItem(conveyors, 0, T('Trans4'));
    expect(jump).not.toBeNull();
    legal(jump!.block);
    expect(sequencer(jump!.block).transitions.length).toBe(9);
    const link = deleteItem(conveyors, 0, T('Trans5'));
    expect(link).not.toBeNull();
    legal(link!.block);
    expect(sequencer(link!.block).steps.map((s) => s.name)).not.toContain('A_on');
    expect(transition(link!.block, 'Trans6').source).toEqual(['B_on']);
    // The only exit of the last step, into the initial step: removing it would leave Emergency dead.
    expect(deleteItem(conveyors, 0, T('Trans10'))).toBeNull();
    // A lone step cannot go.
    const lone = addSequencer(conveyors);
    expect(deleteItem(lone.block, 1, lone.select)).toBeNull();
  });

  it('moves an alternative branch left and right (its priority)', () => {
    const moved = moveBranch(conveyors, 0, T('Trans2'), -1);
    expect(moved).not.toBeNull();
    legal(moved!);
    expect(sequencer(moved!).transitions.slice(0, 3).map((t) => t.name)).toEqual(['Trans2', 'Trans1', 'Trans3']);
    expect(moveBranch(conveyors, 0, T('Trans1'), -1)).toBeNull();
    expect(moveBranch(conveyors, 0, T('Trans3'), 1)).toBeNull();
    const text = spliceText(g17.source, g17.blocks, [moved!]);
    expectTextOf(text, moved!);
    // The two transitions swap their written lines; nothing else changes.
    const one = g17.source.slice(g17.source.indexOf('TRANSITION Trans1 '), g17.source.indexOf('TRANSITION Trans2 '));
    const two = g17.source.slice(g17.source.indexOf('TRANSITION Trans2 '), g17.source.indexOf('TRANSITION Trans3 '));
    expect(text).toBe(g17.source.replace(one + two, two + one));
  });

  it('renames a step everywhere: FROM/TO, step variables in conditions; refuses taken and invalid names', () => {
    const renamed = renameStep(conveyors, 'B_on', 'Belt_B_on');
    expect(renamed).not.toBeNull();
    legal(renamed!);
    expect(transition(renamed!, 'Trans2').target).toEqual(['Belt_B_on']);
    expect(transition(renamed!, 'Trans5').source).toEqual(['Belt_B_on']);
    expect(JSON.stringify(transition(renamed!, 'Trans5').condition)).toContain('Belt_B_on.T');
    expect(JSON.stringify(renamed)).not.toMatch(/"B_on/);
    expect(renameStep(conveyors, 'B_on', 'idle')).toBeNull();
    expect(renameStep(conveyors, 'B_on', 'Trans3')).toBeNull();
    expect(renameStep(conveyors, 'B_on', 'END_STEP')).toBeNull();
    expect(renameStep(conveyors, 'B_on', '2fast')).toBeNull();
    expect(renameTransition(conveyors, 'Trans1', 'Emergency')).toBeNull();
    const t = renameTransition(conveyors, 'Trans1', 'Panic');
    legal(t!);
    expectTextOf(spliceText(g17.source, g17.blocks, [renamed!]), renamed!);
  });

  it('renumbers in chart order and refuses duplicate numbers', () => {
    const grown = insertStepAfter(conveyors, 0, S('Idle')).block; // Step7 right after Idle
    const numbered = renumber(grown);
    legal(numbered);
    expect(sequencer(numbered).steps.map((s) => [s.name, s.number])).toEqual([
      ['Idle', 1],
      ['Step7', 2],
      ['B_on', 3],
      ['A_on', 4],
      ['A_off', 5],
      ['B_off', 6],
      ['Emergency', 7],
    ]);
    expect(sequencer(numbered).transitions.map((t) => t.number)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11].slice(0, 11));
    expect(renumber(numbered)).toBe(numbered);
    expect(setStepNumber(conveyors, 'B_on', 3)).toBeNull();
    expect(setStepNumber(conveyors, 'B_on', 0)).toBeNull();
    expect(step(setStepNumber(conveyors, 'B_on', 12)!, 'B_on').number).toBe(12);
    expect(setTransitionNumber(conveyors, 'Trans1', 2)).toBeNull();
    expect(transition(setTransitionNumber(conveyors, 'Trans1', 20)!, 'Trans1').number).toBe(20);
  });

  it('updates a step, a transition, the settings and the permanent networks; only their lines change', () => {
    const edited = updateStep(conveyors, 'A_on', (s) => ({ ...s, comment: 'belt A runs' }));
    const text = spliceText(g17.source, g17.blocks, [edited]);
    expect(text).toBe(g17.source.replace('STEP A_on (3)\n', 'STEP A_on (3)\nCOMMENT = belt A runs\n'));
    const cond = updateTransition(conveyors, 'Trans6', (t) => ({ ...t, condition: { elements: [{ kind: 'contact', id: 'e1', operand: '"Run"', negated: false }] } as Transition['condition'] }));
    expect(spliceText(g17.source, g17.blocks, [cond])).toBe(g17.source.replace('FROM A_on JUMP Idle\nCONDITION END_CONDITION', 'FROM A_on JUMP Idle\nCONDITION\n  Contact("Run")\nEND_CONDITION'));
    expect(updateStep(conveyors, 'A_on', (s) => s)).toBe(conveyors);
    const settings = setSettings(conveyors, { ...conveyors.settings, skip_steps: true });
    const withSettings = spliceText(g17.source, g17.blocks, [settings]);
    expect(withSettings).toBe(
      g17.source.replace(
        'Start B then A, stop A then B, emergency stops both\n',
        'Start B then A, stop A then B, emergency stops both\nSETTINGS\n  PARAMETERS := STANDARD;\n  SKIP_STEPS := TRUE;\n  ACKNOWLEDGE := TRUE;\n  INTERLOCK_BLOCKS := FALSE;\nEND_SETTINGS\n',
      ),
    );
    expect(spliceText(withSettings, [settings], g17.blocks)).toBe(g17.source);
    expect(setSettings(conveyors, { ...conveyors.settings })).toBe(conveyors);
    const network = { title: '', comment: '', label: null, logic: { elements: [{ kind: 'contact', id: 'e1', operand: '"Start"', negated: false }] }, outputs: [{ conditions: { elements: [] }, target: { kind: 'coil', id: 'e2', coil: '=', operand: '"Lamp"', value: null } }], stl: null, stl_reason: null };
    const pre = setPermanent(conveyors, 'pre', [network] as unknown as GraphBlock['pre']);
    const post = setPermanent(pre, 'post', [network] as unknown as GraphBlock['post']);
    const withBoth = spliceText(g17.source, g17.blocks, [post]);
    expect(withBoth).toContain('BEGIN\nPERMANENT_PRE\nNETWORK\nRUNG\n  Contact("Start")\n  Coil("Lamp")\nEND_RUNG\nEND_PERMANENT_PRE\nSEQUENCER CONV');
    expect(withBoth).toContain('END_SEQUENCER\n\nPERMANENT_POST\nNETWORK');
    expectTextOf(withBoth, post);
    expect(spliceText(withBoth, [post], g17.blocks)).toBe(g17.source);
  });

  it('adds a sequencer with an initial step and a sequence end', () => {
    const { block, select } = addSequencer(conveyors);
    legal(block);
    expect(block.sequencers.length).toBe(2);
    expect(select).toEqual(S('Step7'));
    expect(sequencer(block, 1)).toMatchObject({ name: 'Seq2', steps: [{ name: 'Step7', number: 7, initial: true }], transitions: [{ name: 'Trans11', source: ['Step7'], target: [] }] });
    const text = spliceText(g17.source, g17.blocks, [block]);
    expect(text).toBe(g17.source.replace('END_SEQUENCER\n', 'END_SEQUENCER\n\nSEQUENCER Seq2\n\nINITIAL_STEP Step7 (7)\nEND_STEP\n\nTRANSITION Trans11 (11) FROM Step7 STOP\nEND_TRANSITION\n\nEND_SEQUENCER\n'));
  });
});

describe('every edit at every place of every legal course chart gives a legal chart', () => {
  const legalOnes = scenarios.filter((entry) => entry.blocks.every((block) => structureProblems(block).length === 0));
  it.each(legalOnes.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    let count = 0;
    const check = (block: GraphBlock | null | undefined, b: number, what: string) => {
      if (!block) return;
      count += 1;
      expect(structureProblems(block), what).toEqual([]);
      const after = entry.blocks.map((old, k) => (k === b ? block : old));
      const text = spliceText(entry.source, entry.blocks, after);
      expect(scanText(text, after), `${what}: text`).not.toBeNull();
      // Every step and transition the edit did not touch keeps its lines as written.
      const written = (source: string, blocks: GraphBlock[]) => {
        const lines = source.split('\n');
        const found = new Map<string, string>();
        scanText(source, blocks)?.forEach((span, k) =>
          span.sequencers.forEach((sq, q) => sq.items.forEach((item) => found.set(`${k}/${q}/${item.kind}/${item.name}`, lines.slice(item.start, item.end).join('\n')))),
        );
        return found;
      };
      const before = written(entry.source, entry.blocks);
      const now = written(text, after);
      const old = entry.blocks[b] as GraphBlock;
      block.sequencers.forEach((sq, q) => {
        const oldSeq = old.sequencers[q];
        for (const x of [...sq.steps, ...sq.transitions]) {
          const kind = 'actions' in x ? 'step' : 'transition';
          const untouched = oldSeq && (kind === 'step' ? oldSeq.steps : oldSeq.transitions).some((y: Step | Transition) => y === x);
          if (untouched) expect(now.get(`${b}/${q}/${kind}/${x.name}`), `${what}: ${x.name} kept`).toBe(before.get(`${b}/${q}/${kind}/${x.name}`));
        }
      });
    };
    entry.blocks.forEach((block, b) =>
      block.sequencers.forEach((seq, s) => {
        const initial = seq.steps.find((x) => x.initial)?.name ?? seq.steps[0]?.name ?? '';
        for (const x of seq.steps) {
          check(insertStepAfter(block, s, S(x.name)).block, b, `insert after ${x.name}`);
          check(insertAlternativeBranch(block, s, S(x.name)).block, b, `alternative at ${x.name}`);
          check(insertJump(block, s, S(x.name), initial).block, b, `jump from ${x.name}`);
          check(insertSequenceEnd(block, s, S(x.name)).block, b, `end after ${x.name}`);
          check(deleteItem(block, s, S(x.name))?.block, b, `delete ${x.name}`);
          check(renameStep(block, x.name, `${x.name}_r`), b, `rename ${x.name}`);
        }
        for (const t of seq.transitions) {
          check(insertStepAfter(block, s, T(t.name)).block, b, `insert after ${t.name}`);
          check(insertSimultaneousBranch(block, s, T(t.name)).block, b, `simultaneous at ${t.name}`);
          check(deleteItem(block, s, T(t.name))?.block, b, `delete ${t.name}`);
          check(moveBranch(block, s, T(t.name), 1), b, `move ${t.name}`);
        }
      }),
    );
    entry.blocks.forEach((block, b) => {
      check(renumber(block), b, 'renumber');
      check(addSequencer(block).block, b, 'add sequencer');
    });
    expect(count).toBeGreaterThan(5);
  });
});
