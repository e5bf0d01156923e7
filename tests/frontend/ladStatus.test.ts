/**
 * Program status of a rung (frontend/src/lad/status.ts): the power flow on every wire from what
 * the CPU reported for each element, the way the model reads a rung.
 */
import { describe, expect, it } from 'vitest';
import type { Network } from '../../frontend/src/lad/model';
import { networkFlows, type ElementState } from '../../frontend/src/lad/status';

const contact = (id: string, operand: string, negated = false) => ({ kind: 'contact' as const, id, operand, negated });

/** ( Start OR Motor ) AND NOT Stop -> Motor, with a NOT in a second output. */
const latch: Network = {
  title: '',
  comment: '',
  label: null,
  stl: null,
  stl_reason: null,
  logic: {
    elements: [
      { kind: 'parallel', id: 'e1', branches: [{ elements: [contact('e2', 'Start')] }, { elements: [contact('e3', 'Motor')] }] },
      contact('e4', 'Stop', true),
    ],
  },
  outputs: [{ conditions: { elements: [] }, target: { kind: 'coil', id: 'e5', coil: '=', operand: 'Motor', value: null } }],
};

const state = (value: boolean | null, out: boolean | null = null): ElementState => ({ value, out, pins: {} });

describe('networkFlows', () => {
  it('ANDs a series, ORs a parallel, and a normally closed contact conducts when its bit is 0', () => {
    const flows = networkFlows(latch, new Map([['e2', state(true)], ['e3', state(false)], ['e4', state(false)], ['e5', state(true, true)]]));
    expect(flows.get('rail')).toBe(1);
    expect(flows.get('e2')).toBe(1);
    expect(flows.get('e3')).toBe(0);
    expect(flows.get('e1')).toBe(1);
    expect(flows.get('e4')).toBe(1);
    expect(flows.get('e5:in')).toBe(1);
  });

  it('a pressed stop breaks the flow after it, not before', () => {
    const flows = networkFlows(latch, new Map([['e2', state(true)], ['e3', state(true)], ['e4', state(true)], ['e5', state(false, false)]]));
    expect(flows.get('e1')).toBe(1);
    expect(flows.get('e4:in')).toBe(1);
    expect(flows.get('e4')).toBe(0);
    expect(flows.get('e5:in')).toBe(0);
  });

  it('a network the CPU did not process is grey everywhere; an element it skipped is grey', () => {
    const none = networkFlows(latch, new Map());
    expect([...none.values()].every((flow) => flow === null)).toBe(true);
    const partly = networkFlows(latch, new Map([['e2', state(true)], ['e3', state(true)]]));
    expect(partly.get('e4')).toBeNull();
    expect(partly.get('e5:in')).toBeNull();
  });

  it('takes an EN/ENO box and a NOT at their reported result', () => {
    const network: Network = {
      ...latch,
      logic: { elements: [contact('e1', 'a'), { kind: 'box', id: 'e2', name: 'ADD_I', instance: null, inputs: { IN1: 'MW0', IN2: '1' }, outputs: { OUT: 'MW0' } }, { kind: 'not', id: 'e3' }] },
      outputs: [{ conditions: { elements: [] }, target: { kind: 'coil', id: 'e4', coil: '=', operand: 'q', value: null } }],
    };
    const flows = networkFlows(network, new Map([['e1', state(true)], ['e2', state(null, false)], ['e3', state(null, true)], ['e4', state(true, true)]]));
    expect(flows.get('e2:in')).toBe(1);
    expect(flows.get('e2')).toBe(0);
    expect(flows.get('e3')).toBe(1);
    expect(flows.get('e4:in')).toBe(1);
  });
});
