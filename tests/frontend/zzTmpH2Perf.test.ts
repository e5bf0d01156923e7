import { it } from 'vitest';
import * as E from '../../frontend/src/graph/edits';
import type { GraphBlock, Step, Transition } from '../../frontend/src/graph/model';
import { printGraph } from '../../frontend/src/graph/print';
import { scanText, spliceText } from '../../frontend/src/graph/textEdit';

it('perf', () => {
  const steps: Step[] = []; const transitions: Transition[] = [];
  for (let n = 1; n <= 200; n++) {
    steps.push({ number: n, name: `S${n}x`, initial: n === 1, comment: '', interlock: null, supervision: null, actions: Array.from({ length: 10 }, (_, k) => ({ id: `a${k + 1}`, event: null, qualifier: 'N', interlock: false, operand: `Q ${n}.${k % 8}`, time: null, comment: '' })) });
    transitions.push({ number: n, name: `T${n}x`, comment: '', source: [`S${n}x`], target: [n === 200 ? 'S1x' : `S${n + 1}x`], jump: n === 200, condition: { elements: [{ kind: 'contact', id: 'e1', operand: `I ${n}.0`, negated: false }] } as Transition['condition'] });
  }
  const block: GraphBlock = { name: 'FB 1', title: '', comment: '', settings: { parameters: 'STANDARD', skip_steps: false, acknowledge_required: true, interlock_blocks: false }, declarations: '', pre: [], post: [], sequencers: [{ name: 'A', comment: '', steps, transitions }] };
  const text = printGraph([block]);
  for (let round = 0; round < 3; round++) {
    let t0 = performance.now();
    for (let k = 0; k < 20; k++) scanText(text, [block]);
    console.log('scan', ((performance.now() - t0) / 20).toFixed(1));
    t0 = performance.now();
    for (let k = 0; k < 20; k++) E.renameStep(block, 'S100x', 'Mid');
    console.log('rename', ((performance.now() - t0) / 20).toFixed(1));
    const ins = E.insertStepAfter(block, 0, { kind: 'step', name: 'S100x' }).block;
    t0 = performance.now();
    for (let k = 0; k < 20; k++) spliceText(text, [block], [ins]);
    console.log('splice-insert', ((performance.now() - t0) / 20).toFixed(1));
    for (const what of ['insert', 'rename', 'renumber', 'delete']) {
      t0 = performance.now();
      const after = what === 'insert' ? E.insertStepAfter(block, 0, { kind: 'step', name: 'S100x' }).block : what === 'rename' ? E.renameStep(block, 'S100x', 'Mid')! : what === 'renumber' ? E.renumber(E.insertStepAfter(block, 0, { kind: 'step', name: 'S100x' }).block) : E.deleteItem(block, 0, { kind: 'step', name: 'S100x' })!.block;
      const t1 = performance.now();
      spliceText(text, [block], [after]);
      console.log(what, 'edit', (t1 - t0).toFixed(1), 'splice', (performance.now() - t1).toFixed(1));
    }
  }
});
