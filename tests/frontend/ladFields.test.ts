/**
 * What a user types on a LAD/FBD element (frontend/src/lad/fields.ts) and the call boxes' pins
 * (frontend/src/lad/calls.ts): operands, a box's type, pins, the operand above a box, the
 * parameters of a called FC, FB or system block.
 */
import { describe, expect, it } from 'vitest';
import type { ProjectOutline } from '../../frontend/src/api/outline';
import { callInterface, callItems, connectPin, newCallBox } from '../../frontend/src/lad/calls';
import { BIT_PLACEHOLDER, PLACEHOLDER } from '../../frontend/src/lad/edits';
import { emptyBox, newBox } from '../../frontend/src/lad/elements';
import { boxSpec } from '../../frontend/src/lad/boxes';
import { fieldText, withField } from '../../frontend/src/lad/fields';
import type { Box } from '../../frontend/src/lad/model';
import type { Element, Final } from '../../frontend/src/lad/tree';

const member = (name: string, section: 'IN' | 'OUT' | 'IN_OUT' | 'STAT', type: string) => ({
  path: name,
  name,
  type,
  section,
  depth: 0,
  offset: null,
  initial: null,
  actual: null,
  comment: '',
  elementary: true,
  file: null,
  line: null,
});

const outline: ProjectOutline = {
  symbols: [],
  blocks: [
    { kind: 'FC', number: 10, name: 'Scale', language: 'scl', file: 'Scale.scl', line: 1, return_type: 'REAL', instance_of: null, members: [member('Raw', 'IN', 'INT'), member('Enable', 'IN', 'BOOL')] },
    { kind: 'FB', number: 5, name: 'Valve', language: 'stl', file: 'Valve.awl', line: 1, return_type: null, instance_of: null, members: [member('Open', 'IN', 'BOOL'), member('Opened', 'OUT', 'BOOL'), member('State', 'STAT', 'INT')] },
  ],
};

function box(element: Element | Final): Box {
  if (element.kind !== 'box') throw new Error('not a box');
  return element;
}

function applied(element: Element | Final, field: string, text: string): Element | Final {
  const result = withField(element, field, text, (name) => callInterface(name, outline));
  if ('error' in result) throw new Error(result.error);
  return result.element;
}

describe('fields typed on elements', () => {
  it('an operand, and an empty one is the placeholder again', () => {
    const contact: Element = { kind: 'contact', id: 'e1', operand: BIT_PLACEHOLDER, negated: false };
    expect(fieldText(contact, 'operand')).toBe('');
    const typed = applied(contact, 'operand', '  "Start" ');
    expect(typed).toMatchObject({ operand: '"Start"' });
    expect(applied(typed, 'operand', '')).toMatchObject({ operand: BIT_PLACEHOLDER });
  });

  it('refuses a jump label that is no name and a status bit that does not exist', () => {
    const jump: Final = { kind: 'jump', id: 'e1', negated: false, label: 'M001' };
    expect(withField(jump, 'label', '2x')).toEqual({ error: 'label' });
    const status: Element = { kind: 'status', id: 'e1', bit: 'OV', negated: false };
    expect(withField(status, 'bit', 'XX')).toEqual({ error: 'bit' });
    expect(applied(status, 'bit', '>=0')).toMatchObject({ bit: '>=0' });
  });

  it('the empty box becomes the box typed, with its operands to fill in', () => {
    const timer = box(applied(emptyBox(), 'name', 's_odt'));
    expect(timer.name).toBe('S_ODT');
    expect(timer.instance).toBe(PLACEHOLDER);
    expect(timer.inputs).toEqual({ TV: PLACEHOLDER });
    expect(withField(emptyBox(), 'name', 'NO_SUCH_BOX')).toEqual({ error: 'box' });
  });

  it('a box turned into another type keeps the pins they share', () => {
    const move = { ...box(newBox(boxSpec('MOVE')!)), inputs: { IN: 'MW 0' }, outputs: { OUT: 'MW 2' } };
    const negate = box(applied(move, 'name', 'NEG_I'));
    expect(negate.inputs).toEqual({ IN: 'MW 0' });
    expect(negate.outputs).toEqual({ OUT: 'MW 2' });
  });

  it('connects and disconnects pins', () => {
    const timer = box(newBox(boxSpec('S_ODT')!));
    const reset = box(applied(timer, 'pin:R', 'I 1.0'));
    expect(reset.inputs.R).toBe('I 1.0');
    const value = box(applied(reset, 'pin:BI', 'MW 10'));
    expect(value.outputs.BI).toBe('MW 10');
    expect(box(applied(value, 'pin:BI', '')).outputs).toEqual({});
  });
});

describe('call boxes', () => {
  it('an FC call has every parameter to fill in, its return value too', () => {
    const fc = callItems(outline).find((item) => item.key === 'call:FC 10')!;
    expect(fc.symbol).toBe('FC 10 "Scale"');
    expect(fc.make()).toMatchObject({ name: 'FC 10', instance: null, inputs: { Raw: PLACEHOLDER, Enable: BIT_PLACEHOLDER }, outputs: { RET_VAL: PLACEHOLDER } });
  });

  it('an FB or SFB call asks for its instance DB, its parameters are connected one by one', () => {
    const fb = box(callItems(outline).find((item) => item.key === 'call:FB 5')!.make());
    expect(fb).toMatchObject({ instance: PLACEHOLDER, inputs: {}, outputs: {} });
    const pins = callInterface('"Valve"', outline)!;
    expect(pins.map((pin) => pin.name)).toEqual(['Open', 'Opened']);
    expect(connectPin(fb, pins[1]!).outputs).toEqual({ Opened: BIT_PLACEHOLDER });
    const ton = callInterface('SFB 4', null)!;
    expect(ton.map((pin) => `${pin.section} ${pin.name} ${pin.type}`)).toEqual(['IN IN BOOL', 'IN PT TIME', 'OUT Q BOOL', 'OUT ET TIME']);
    expect(newCallBox('SFC 64', 'SFC', callInterface('SFC 64', null)!)).toMatchObject({ instance: null, outputs: { RET_VAL: PLACEHOLDER } });
  });

  it('a box typed as a call gets the called block\'s parameters', () => {
    expect(applied(emptyBox(), 'name', 'FC 10')).toMatchObject({ name: 'FC 10', inputs: { Raw: PLACEHOLDER } });
  });
});
