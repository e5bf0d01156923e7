/**
 * The fields a user types on an element: its operand, a box's type, pins and the operand above
 * it (timer, counter, instance DB), a timer coil's value, a jump's label, a status bit. Reading a
 * field for the editor, and writing what was typed back into the element.
 */
import { boxSpec, callTarget } from './boxes';
import { BIT_PLACEHOLDER, PLACEHOLDER, isPlaceholder } from './edits';
import { newCallBox, type CallPin } from './calls';
import { newBox } from './elements';
import type { Element, Final } from './tree';

export const STATUS_BITS = ['OV', 'OS', 'BR', 'UO', '==0', '<>0', '>0', '<0', '>=0', '<=0'] as const;
const LABEL = /^[A-Za-z_]\w*$/;

/** The text a field holds now ('' for a placeholder, so typing starts afresh). */
export function fieldText(element: Element | Final, field: string): string {
  const shown = (text: string | null | undefined) => (text && !isPlaceholder(text) ? text : '');
  if (field.startsWith('pin:') && element.kind === 'box') {
    const pin = field.slice(4);
    const value = element.inputs[pin] ?? element.outputs[pin];
    return typeof value === 'string' ? shown(value) : '';
  }
  switch (field) {
    case 'operand':
      if (element.kind === 'contact' || element.kind === 'midline' || element.kind === 'coil') return shown(element.operand);
      if (element.kind === 'edge') return shown(element.memory);
      if (element.kind === 'opn') return shown(element.block);
      return '';
    case 'bit':
      return element.kind === 'status' ? element.bit : '';
    case 'label':
      return element.kind === 'jump' ? element.label : '';
    case 'value':
      return element.kind === 'coil' ? shown(element.value) : '';
    case 'instance':
      return element.kind === 'box' ? shown(element.instance) : '';
    case 'name':
      return element.kind === 'box' ? shown(element.name) : '';
    default:
      return '';
  }
}

export type FieldResult = { element: Element | Final } | { error: 'label' | 'box' | 'bit' | 'pinLogic' };

/** Whether a field of this element takes a bit (its placeholder is `<??.?>`). */
function bitField(element: Element | Final, field: string): boolean {
  if (element.kind === 'contact' || element.kind === 'midline' || element.kind === 'edge') return true;
  if (element.kind === 'coil') return field === 'operand' && (element.coil === '=' || element.coil === 'S' || element.coil === 'R');
  if (element.kind === 'box' && field === 'instance') return boxSpec(element.name)?.address === 'bit';
  return false;
}

/**
 * The element with `text` typed into `field`; an empty operand is the placeholder again.
 * `interfaceOf` gives a called block's parameters (a box typed as a call gets them).
 */
export function withField(element: Element | Final, field: string, text: string, interfaceOf: (name: string) => CallPin[] | null = () => null): FieldResult {
  const value = text.trim();
  const operand = value || (bitField(element, field) ? BIT_PLACEHOLDER : PLACEHOLDER);
  if (field.startsWith('pin:') && element.kind === 'box') return { element: withPin(element, field.slice(4), value) };
  switch (field) {
    case 'operand':
      if (element.kind === 'contact' || element.kind === 'midline' || element.kind === 'coil') return { element: { ...element, operand } };
      if (element.kind === 'edge') return { element: { ...element, memory: operand } };
      if (element.kind === 'opn') return { element: { ...element, block: operand } };
      return { element };
    case 'bit': {
      const bit = STATUS_BITS.find((b) => b === value.toUpperCase());
      if (element.kind !== 'status' || !bit) return { error: 'bit' };
      return { element: { ...element, bit } };
    }
    case 'label':
      if (element.kind !== 'jump' || !LABEL.test(value)) return { error: 'label' };
      return { element: { ...element, label: value } };
    case 'value':
      return element.kind === 'coil' ? { element: { ...element, value: operand } } : { element };
    case 'instance':
      return element.kind === 'box' ? { element: { ...element, instance: operand } } : { element };
    case 'name':
      return element.kind === 'box' ? renamedBox(element, value, interfaceOf) : { element };
    default:
      return { element };
  }
}

type BoxElement = Extract<Element | Final, { kind: 'box' }>;

/** A pin connected to an operand, or unconnected when the text is empty. */
function withPin(box: BoxElement, pin: string, value: string): BoxElement {
  const spec = boxSpec(box.name);
  const isOutput = spec ? spec.pins.some((p) => p.name === pin && p.direction === 'out') : pin in box.outputs;
  if (isOutput) {
    const outputs = { ...box.outputs };
    if (value) outputs[pin] = value;
    else delete outputs[pin];
    return { ...box, outputs };
  }
  const inputs = { ...box.inputs };
  if (value) inputs[pin] = value;
  else delete inputs[pin];
  return { ...box, inputs };
}

/**
 * The box turned into another type (the empty box of Shift+F5 gets its type, a MOVE becomes an
 * ADD_I): pins of the same name keep their operands, an instance of the same kind is kept.
 */
function renamedBox(box: BoxElement, name: string, interfaceOf: (name: string) => CallPin[] | null): FieldResult {
  const spec = boxSpec(name);
  let fresh: Element;
  if (spec) fresh = newBox(spec);
  else {
    const call = callTarget(name);
    if (!call) return { error: 'box' };
    const kind = /^(SFC|SFB|FC|FB)/i.exec(call[0])?.[1]?.toUpperCase() ?? (call[1] ? 'FB' : 'FC');
    fresh = newCallBox(call[0], kind, interfaceOf(call[0]) ?? []);
  }
  if (fresh.kind !== 'box') return { error: 'box' };
  const oldSpec = boxSpec(box.name);
  const keep = (pin: string) => (spec ? spec.pins.some((p) => p.name === pin) : !oldSpec);
  const inputs = { ...fresh.inputs };
  for (const [pin, value] of Object.entries(box.inputs)) if (keep(pin) && !(typeof value === 'string' && isPlaceholder(value))) inputs[pin] = value;
  const outputs = { ...fresh.outputs };
  for (const [pin, value] of Object.entries(box.outputs)) if (keep(pin) && !isPlaceholder(value)) outputs[pin] = value;
  const sameAddress = spec && oldSpec && spec.address === oldSpec.address;
  const instance = sameAddress && box.instance && !isPlaceholder(box.instance) ? box.instance : fresh.instance;
  return { element: { ...fresh, id: box.id, inputs, outputs, instance } };
}
