/**
 * The graphical editor writes only what an edit changed into the `.lad` text
 * (frontend/src/lad/textEdit.ts): comments and hand-written layout of other networks stay.
 */
import { describe, expect, it } from 'vitest';
import { emptyNetwork } from '../../frontend/src/lad/edits';
import type { LadBlock, Network } from '../../frontend/src/lad/model';
import { printLad } from '../../frontend/src/lad/print';
import { spliceText, splitText } from '../../frontend/src/lad/textEdit';

const contact = (operand: string) => ({ kind: 'contact' as const, id: 'e1', operand, negated: false });
const coil = (operand: string, id: string) => ({ kind: 'coil' as const, id, coil: '=' as const, operand, value: null });

function rung(input: string, output: string, title = ''): Network {
  return { ...emptyNetwork(), title, logic: { elements: [contact(input)] }, outputs: [{ conditions: { elements: [] }, target: coil(output, 'e2') }] };
}

const HAND_WRITTEN = `// A file written by hand: this comment must stay.
ORGANIZATION_BLOCK OB 1
TITLE = Two rungs
BEGIN
NETWORK
TITLE = first
RUNG
    Contact(I 0.0)      // odd spacing, kept
    Coil(Q 4.0)
END_RUNG

// between the networks
NETWORK
TITLE = second
RUNG
  Contact(I 0.1)
  Coil(Q 4.1)
END_RUNG
END_ORGANIZATION_BLOCK
`;

function model(): LadBlock[] {
  return [
    {
      language: 'LAD',
      kind: 'OB',
      name: 'OB 1',
      return_type: null,
      title: 'Two rungs',
      declarations: '',
      networks: [rung('I 0.0', 'Q 4.0', 'first'), rung('I 0.1', 'Q 4.1', 'second')],
    },
  ];
}

describe('spliceText', () => {
  it('finds the blocks and networks of a hand-written file', () => {
    const spans = splitText(HAND_WRITTEN);
    expect(spans?.blocks.length).toBe(1);
    expect(spans?.blocks[0]?.networks.map((n) => n.body[1])).toEqual(['TITLE = first', 'TITLE = second']);
    expect(spans?.blocks[0]?.networks[1]?.lead).toEqual(['', '// between the networks']);
  });

  it('prints only the network that changed; comments and other networks stay as written', () => {
    const before = model();
    const first = before[0]!;
    const after: LadBlock[] = [{ ...first, networks: [first.networks[0]!, rung('I 0.2', 'Q 4.1', 'second')] }];
    const text = spliceText(HAND_WRITTEN, before, after);
    expect(text).toContain('// A file written by hand: this comment must stay.');
    expect(text).toContain('    Contact(I 0.0)      // odd spacing, kept');
    expect(text).toContain('// between the networks');
    expect(text).toContain('  Contact(I 0.2)');
    expect(text).not.toContain('Contact(I 0.1)');
  });

  it('inserts, deletes and reorders networks in place', () => {
    const before = model();
    const first = before[0]!;
    const [one, two] = first.networks as [Network, Network];
    const added = spliceText(HAND_WRITTEN, before, [{ ...first, networks: [one, emptyNetwork(), two] }]);
    expect(added.split('NETWORK').length - 1).toBe(3);
    expect(added).toMatch(/END_RUNG\nNETWORK\nRUNG\nEND_RUNG\n\n\/\/ between/);
    const removed = spliceText(HAND_WRITTEN, before, [{ ...first, networks: [two] }]);
    expect(removed).not.toContain('TITLE = first');
    expect(removed).toContain('// between the networks');
    const swapped = spliceText(HAND_WRITTEN, before, [{ ...first, networks: [two, one] }]);
    expect(swapped.indexOf('TITLE = second')).toBeLessThan(swapped.indexOf('TITLE = first'));
    expect(swapped).toContain('    Contact(I 0.0)      // odd spacing, kept');
  });

  it('rewrites the header when the block changes (LAD to FBD) and keeps the networks', () => {
    const before = model();
    const text = spliceText(HAND_WRITTEN, before, [{ ...before[0]!, language: 'FBD' }]);
    expect(text).toContain('LANGUAGE FBD');
    expect(text).toContain('    Contact(I 0.0)      // odd spacing, kept');
  });

  it('prints the whole file when a block comment hides its structure', () => {
    const before = model();
    const text = spliceText(`(* NETWORK *)\n${HAND_WRITTEN}`, before, before);
    expect(text).toBe(printLad(before));
  });
});
