/**
 * The context menus of the diagram editors: what right-clicking an element or a network's header
 * offers, as TIA Portal does. Offline: edit, negate, connect a call's parameter, delete; online:
 * modify a bit to 1 or 0 (an input is driven as the I/O panel does), force and unforce, modify a
 * box pin's word. The entries are built here from what the element is; the editor supplies what
 * each one does.
 */
import type { MenuAction } from '../projects/RowMenu';
import type { CallPin } from './calls';
import { isPlaceholder } from './edits';
import type { Element, Final } from './tree';

type Translate = (key: string, options?: Record<string, unknown>) => string;

export interface ElementMenuHandlers {
  edit: () => void;
  negate: () => void;
  /** Writes a bit once: `input` says it is a process input (set like the I/O panel's switch). */
  write: (operand: string, value: boolean, input: boolean) => void;
  force: (operand: string, value: boolean) => void;
  unforce: (operand: string) => void;
  connect: (pin: CallPin) => void;
  /** Asks for a value to write into `operand` (a box pin's word). */
  modify: (operand: string) => void;
  remove: () => void;
}

export interface ElementMenuContext {
  t: Translate;
  element: Element | Final;
  editable: boolean;
  online: boolean;
  /** The parameters of the block a call box calls (null: not a call, or not known). */
  callPins: readonly CallPin[] | null;
  isInput: (operand: string) => boolean;
  on: ElementMenuHandlers;
}

/** The bit operand an element reads or writes, where modify and force make sense. */
function bitOperand(element: Element | Final): string | null {
  if (element.kind === 'contact' || element.kind === 'midline') return element.operand;
  if (element.kind === 'coil' && (element.coil === '=' || element.coil === 'S' || element.coil === 'R')) return element.operand;
  return null;
}

/** A box input a value can be written into: an operand, not a constant or logic. */
function writablePin(value: unknown): value is string {
  return typeof value === 'string' && !isPlaceholder(value) && !/^[-+]?\d|#/.test(value);
}

export function elementMenu({ t, element, editable, online, callPins, isInput, on }: ElementMenuContext): MenuAction[] {
  const actions: MenuAction[] = [];
  if (editable) {
    actions.push({ id: 'edit', label: t('lad.menu.edit'), onSelect: on.edit });
    if (element.kind === 'contact' || element.kind === 'status') actions.push({ id: 'negate', label: t('lad.menu.negate'), onSelect: on.negate });
  }
  const operand = bitOperand(element);
  if (online && operand && !isPlaceholder(operand)) {
    const input = isInput(operand);
    actions.push({ id: 'modify1', label: t('lad.menu.modify1'), onSelect: () => on.write(operand, true, input) });
    actions.push({ id: 'modify0', label: t('lad.menu.modify0'), onSelect: () => on.write(operand, false, input) });
    actions.push({ id: 'force1', label: t('lad.menu.force1'), onSelect: () => on.force(operand, true) });
    actions.push({ id: 'force0', label: t('lad.menu.force0'), onSelect: () => on.force(operand, false) });
    actions.push({ id: 'unforce', label: t('lad.menu.unforce'), onSelect: () => on.unforce(operand) });
  }
  if (element.kind === 'box') {
    if (editable) {
      for (const pin of callPins ?? []) {
        if (pin.name in element.inputs || pin.name in element.outputs) continue;
        actions.push({ id: `connect-${pin.name}`, label: t('lad.menu.connect', { pin: pin.name, type: pin.type }), onSelect: () => on.connect(pin) });
      }
    }
    if (online) {
      for (const [pin, value] of Object.entries(element.inputs)) {
        if (writablePin(value)) actions.push({ id: `modify-${pin}`, label: t('lad.menu.modifyPin', { pin, operand: value }), onSelect: () => on.modify(value) });
      }
    }
  }
  if (editable) actions.push({ id: 'delete', label: t('lad.menu.delete'), danger: true, onSelect: on.remove });
  return actions;
}

export interface NetworkMenuHandlers {
  insert: () => void;
  editField: (field: 'title' | 'comment' | 'label') => void;
  move: (delta: -1 | 1) => void;
  clipboard: (action: 'copy' | 'cut' | 'paste') => void;
  toggleBreakpoint: () => void;
  breakpointCondition: () => void;
  remove: () => void;
}

export function networkMenu({ t, editable, breakpoints, on }: { t: Translate; editable: boolean; breakpoints: boolean; on: NetworkMenuHandlers }): MenuAction[] {
  const actions: MenuAction[] = [];
  if (editable) {
    actions.push({ id: 'insert', label: t('lad.menu.insertNetwork'), onSelect: on.insert });
    actions.push({ id: 'title', label: t('lad.menu.editTitle'), onSelect: () => on.editField('title') });
    actions.push({ id: 'comment', label: t('lad.menu.editComment'), onSelect: () => on.editField('comment') });
    actions.push({ id: 'label', label: t('lad.menu.editLabel'), onSelect: () => on.editField('label') });
    actions.push({ id: 'up', label: t('lad.menu.moveUp'), onSelect: () => on.move(-1) });
    actions.push({ id: 'down', label: t('lad.menu.moveDown'), onSelect: () => on.move(1) });
  }
  actions.push({ id: 'copy', label: t('lad.menu.copy'), onSelect: () => on.clipboard('copy') });
  if (editable) {
    actions.push({ id: 'cut', label: t('lad.menu.cut'), onSelect: () => on.clipboard('cut') });
    actions.push({ id: 'paste', label: t('lad.menu.paste'), onSelect: () => on.clipboard('paste') });
  }
  if (breakpoints) {
    actions.push({ id: 'breakpoint', label: t('lad.menu.breakpoint'), onSelect: on.toggleBreakpoint });
    actions.push({ id: 'condition', label: t('lad.menu.breakpointCondition'), onSelect: on.breakpointCondition });
  }
  if (editable) actions.push({ id: 'delete', label: t('lad.menu.deleteNetwork'), danger: true, onSelect: on.remove });
  return actions;
}
