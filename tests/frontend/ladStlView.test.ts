/**
 * The STL view of a LAD block goes back network by network (frontend/src/lad/stlView.ts): what
 * the user did not touch keeps its drawing, the rest is lifted anew.
 */
import { describe, expect, it } from 'vitest';
import { emptyNetwork } from '../../frontend/src/lad/edits';
import type { LadBlock, Network } from '../../frontend/src/lad/model';
import { matchInOrder, mergeLifted, splitStl } from '../../frontend/src/lad/stlView';

const SHOWN = `ORGANIZATION_BLOCK OB 1
TITLE = Conveyor
BEGIN
NETWORK
TITLE = one
      A     I 0.0
      =     Q 4.0
NETWORK
TITLE = two
      A     I 0.1
      =     Q 4.1
END_ORGANIZATION_BLOCK
`;

const network = (title: string): Network => ({ ...emptyNetwork(), title });

function block(...networks: Network[]): LadBlock {
  return { language: 'LAD', kind: 'OB', name: 'OB 1', return_type: null, title: 'Conveyor', declarations: '', networks };
}

describe('the STL view', () => {
  it('cuts an STL source into headers and networks', () => {
    const [only] = splitStl(SHOWN);
    expect(only?.header).toBe('ORGANIZATION_BLOCK OB 1\nTITLE = Conveyor\nBEGIN');
    expect(only?.networks.map((text) => text.split('\n')[1])).toEqual(['TITLE = one', 'TITLE = two']);
  });

  it('matches equal items in order', () => {
    expect(matchInOrder(['a', 'b', 'c'], ['a', 'x', 'c', 'b'])).toEqual([0, -1, 2, -1]);
    expect(matchInOrder(['a', 'b'], [])).toEqual([]);
  });

  it('keeps the drawing of the networks the user did not touch, lifts the others', () => {
    const one = network('one');
    const two = network('two');
    const model = [block(one, two)];
    const edited = SHOWN.replace('TITLE = one', 'TITLE = one\n      A     I 0.7').replace('END_ORGANIZATION_BLOCK', 'NETWORK\nTITLE = three\n      A     I 0.2\n      =     Q 4.2\nEND_ORGANIZATION_BLOCK');
    const lifted = [block(network('one, lifted'), network('two, lifted'), network('three'))];
    const merged = mergeLifted(model, SHOWN, edited, lifted);
    expect(merged?.[0]?.networks.map((n) => n.title)).toEqual(['one, lifted', 'two', 'three']);
    expect(merged?.[0]?.networks[1]).toBe(two);
  });

  it('takes the lifted blocks whole when blocks were added or removed', () => {
    const model = [block(network('one'))];
    expect(mergeLifted(model, SHOWN, `${SHOWN}\nFUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\n`, [block(), block()])).toBeNull();
  });
});
