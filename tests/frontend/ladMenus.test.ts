/**
 * The diagram editors' context menus (frontend/src/lad/menus.ts) and where the compiler's
 * problems of a LAD file are shown (frontend/src/lad/problems.ts).
 */
import { describe, expect, it, vi } from 'vitest';
import type { Diagnostic } from '../../frontend/src/api/types';
import { elementMenu, networkMenu, type ElementMenuHandlers } from '../../frontend/src/lad/menus';
import { isInput } from '../../frontend/src/lad/operands';
import { blockLines, problemsByNetwork } from '../../frontend/src/lad/problems';

const t = (key: string, options?: Record<string, unknown>) => (options ? `${key} ${JSON.stringify(options)}` : key);

function handlers(): ElementMenuHandlers {
  return { edit: vi.fn(), negate: vi.fn(), write: vi.fn(), force: vi.fn(), unforce: vi.fn(), connect: vi.fn(), modify: vi.fn(), remove: vi.fn() };
}

describe('element menu', () => {
  it('offline: edit, negate a contact, delete', () => {
    const on = handlers();
    const actions = elementMenu({ t, element: { kind: 'contact', id: 'e1', operand: 'I 0.0', negated: false }, editable: true, online: false, callPins: null, isInput: () => true, on });
    expect(actions.map((a) => a.id)).toEqual(['edit', 'negate', 'delete']);
    actions[1]!.onSelect();
    expect(on.negate).toHaveBeenCalled();
  });

  it('online: a contact on an input is driven, a coil is written, both can be forced', () => {
    const on = handlers();
    const contact = elementMenu({ t, element: { kind: 'contact', id: 'e1', operand: '"Start"', negated: false }, editable: false, online: true, callPins: null, isInput: (o) => isInput(o, new Map([['start', 'I 0.0']])), on });
    expect(contact.map((a) => a.id)).toEqual(['modify1', 'modify0', 'force1', 'force0', 'unforce']);
    contact[0]!.onSelect();
    expect(on.write).toHaveBeenCalledWith('"Start"', true, true);
    const coil = elementMenu({ t, element: { kind: 'coil', id: 'e2', coil: '=', operand: 'Q 4.0', value: null }, editable: false, online: true, callPins: null, isInput: (o) => isInput(o, new Map()), on });
    coil[1]!.onSelect();
    expect(on.write).toHaveBeenLastCalledWith('Q 4.0', false, false);
    coil[2]!.onSelect();
    expect(on.force).toHaveBeenCalledWith('Q 4.0', true);
  });

  it('a call box offers its unconnected parameters; online its operand inputs can be modified', () => {
    const on = handlers();
    const box = { kind: 'box' as const, id: 'e3', name: 'FB 5', instance: 'DB 5', inputs: { Open: 'M 0.0', Speed: '100' }, outputs: {} };
    const pins = [
      { section: 'IN' as const, name: 'Open', type: 'BOOL' },
      { section: 'OUT' as const, name: 'Opened', type: 'BOOL' },
    ];
    const actions = elementMenu({ t, element: box, editable: true, online: true, callPins: pins, isInput: () => false, on });
    expect(actions.map((a) => a.id)).toEqual(['edit', 'connect-Opened', 'modify-Open', 'delete']);
    actions[1]!.onSelect();
    expect(on.connect).toHaveBeenCalledWith(pins[1]);
  });

  it('a placeholder operand is not offered for modify', () => {
    const actions = elementMenu({ t, element: { kind: 'contact', id: 'e1', operand: '<??.?>', negated: false }, editable: false, online: true, callPins: null, isInput: () => false, on: handlers() });
    expect(actions).toEqual([]);
  });
});

describe('network menu', () => {
  it('read-only without a file: copy only; editable with breakpoints: everything', () => {
    const on = { insert: vi.fn(), editField: vi.fn(), move: vi.fn(), clipboard: vi.fn(), toggleBreakpoint: vi.fn(), breakpointCondition: vi.fn(), remove: vi.fn() };
    expect(networkMenu({ t, editable: false, breakpoints: false, on }).map((a) => a.id)).toEqual(['copy']);
    const all = networkMenu({ t, editable: true, breakpoints: true, on });
    expect(all.map((a) => a.id)).toEqual(['insert', 'title', 'comment', 'label', 'up', 'down', 'copy', 'cut', 'paste', 'breakpoint', 'condition', 'delete']);
    all.find((a) => a.id === 'down')!.onSelect();
    expect(on.move).toHaveBeenCalledWith(1);
  });
});

describe('problems of a LAD file', () => {
  const text = 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG END_RUNG\nEND_ORGANIZATION_BLOCK\n\nFUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nRUNG END_RUNG\nEND_FUNCTION\n';
  const problem = (code: string, line: number, network: number | null, element: string | null): Diagnostic => ({
    code,
    severity: 'error',
    key: code,
    message: `${code} message`,
    params: {},
    span: { file: 'Main.lad', line, column: null, end_line: null, end_column: null, network, element },
  });

  it('go to their element, their network or their block, by the block\'s lines', () => {
    expect(blockLines(text)).toEqual([1, 7]);
    const placed = problemsByNetwork(
      [problem('STL204', 3, 1, 'e2'), problem('LAD211', 9, 1, null), problem('LAD106', 7, null, null), { ...problem('X', 1, 1, null), span: { ...problem('X', 1, 1, null).span!, file: 'Other.lad' } }],
      'Main.lad',
      blockLines(text),
      (d) => d.message,
    );
    expect(placed.networks.get('0:0')?.elements.get('e2')?.[0]?.code).toBe('STL204');
    expect(placed.networks.get('0:0')?.elementCount).toBe(1);
    expect(placed.networks.get('1:0')?.network.map((p) => p.code)).toEqual(['LAD211']);
    expect(placed.block.get(1)?.map((p) => p.code)).toEqual(['LAD106']);
  });
});
