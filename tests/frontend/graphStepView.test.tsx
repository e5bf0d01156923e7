/**
 * S7-Graph's step view and permanent instructions over an in-memory Graph document (the model,
 * one undo history): the action table's editing (add, operand, qualifier, event, time, move,
 * delete), an illegal qualifier/event pair kept and marked on its cell with its GRA code, the
 * qualifiers offered for an event, conditions edited in the LAD editor mapped back into the
 * step or transition (and refused when they stop being a condition), permanent networks added.
 */
import { act, fireEvent, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useCallback, useRef, useState } from 'react';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it, vi } from 'vitest';

vi.setConfig({ testTimeout: 30_000 });
import { applyConditionEdit, conditionNetwork, conditionProblems, PSEUDO_COIL, seriesOf, syntheticBlock, type ConditionSlot } from '../../frontend/src/graph/conditionDoc';
import { updateTransition } from '../../frontend/src/graph/edits';
import type { Action, GraphBlock, Step } from '../../frontend/src/graph/model';
import { PermanentView } from '../../frontend/src/graph/PermanentView';
import type { GraphSelection } from '../../frontend/src/graph/selection';
import { StepView } from '../../frontend/src/graph/StepView';
import type { GraphDocument } from '../../frontend/src/graph/useGraphDocument';
import type { GraphMonitor } from '../../frontend/src/graph/useGraphMonitoring';
import type { ElementStatus } from '../../frontend/src/api/monitor';
import { createI18n } from '../../frontend/src/i18n/setup';
import type { Network, Series } from '../../frontend/src/lad/model';

const contact = (id: string, operand: string) => ({ id, kind: 'contact' as const, operand, negated: false });

const step = (number: number, name: string, extra: Partial<Step> = {}): Step => ({
  number,
  name,
  initial: number === 1,
  comment: '',
  interlock: null,
  supervision: null,
  actions: [],
  ...extra,
});

const action = (id: string, qualifier: Action['qualifier'], operand: string, extra: Partial<Action> = {}): Action => ({
  id,
  event: null,
  qualifier,
  interlock: false,
  operand,
  time: null,
  comment: '',
  ...extra,
});

const BLOCK: GraphBlock = {
  name: 'FB 1',
  title: '',
  comment: '',
  settings: { parameters: 'STANDARD', skip_steps: false, acknowledge_required: true, interlock_blocks: false },
  declarations: '',
  pre: [],
  post: [],
  sequencers: [
    {
      name: 'SEQ1',
      comment: '',
      steps: [
        step(1, 'Idle'),
        step(2, 'Fill', { interlock: { elements: [contact('e1', 'I 0.1')] }, actions: [action('a1', 'N', 'Q 4.0'), action('a2', 'S', 'M 1.0')] }),
        step(3, 'Drain'),
      ],
      transitions: [
        { number: 1, name: 'Trans1', comment: '', source: ['Idle'], target: ['Fill'], jump: false, condition: { elements: [contact('e1', 'I 0.0')] } },
        { number: 2, name: 'Trans2', comment: '', source: ['Fill'], target: ['Drain'], jump: false, condition: { elements: [contact('e1', 'I 0.2')] } },
        { number: 3, name: 'Trans3', comment: '', source: ['Fill'], target: ['Idle'], jump: true, condition: null },
      ],
    },
  ],
};

/** The document: the model and one undo history, as useGraphDocument keeps them. */
function useMemoryDoc(initial: GraphBlock): GraphDocument & { history: string[] } {
  const [states, setStates] = useState<{ list: (readonly GraphBlock[])[]; at: number }>({ list: [[initial]], at: 0 });
  const history = useRef<string[]>([]);
  const edit = useCallback((change: (blocks: readonly GraphBlock[]) => readonly GraphBlock[], label: string) => {
    setStates((current) => {
      const before = current.list[current.at]!;
      const after = change(before);
      if (after === before) return current;
      history.current.push(label);
      return { list: [...current.list.slice(0, current.at + 1), after], at: current.at + 1 };
    });
  }, []);
  return {
    state: { status: 'ready' },
    blocks: states.list[states.at]!,
    problems: [],
    places: [],
    pending: false,
    edit,
    undo: () => setStates((c) => ({ ...c, at: Math.max(0, c.at - 1) })),
    redo: () => setStates((c) => ({ ...c, at: Math.min(c.list.length - 1, c.at + 1) })),
    canUndo: states.at > 0,
    canRedo: states.at < states.list.length - 1,
    retry: () => undefined,
    history: history.current,
  };
}

let current: (GraphDocument & { history: string[] }) | null = null;
const model = (): GraphBlock => current!.blocks![0]!;
const fill = (): Step => model().sequencers[0]!.steps[1]!;

function Harness({ initial = BLOCK, view = 'step', monitor = null }: { initial?: GraphBlock; view?: 'step' | 'permanent'; monitor?: GraphMonitor | null }) {
  const doc = useMemoryDoc(initial);
  current = doc;
  const [selection, setSelection] = useState<GraphSelection>({ block: 0, sequencer: 0, item: { kind: 'step', name: 'Fill' } });
  return view === 'step' ? (
    <StepView doc={doc} selection={selection} onSelect={setSelection} monitor={monitor} projectId={null} file={null} active />
  ) : (
    <PermanentView doc={doc} block={0} monitor={monitor} projectId={null} file={null} active />
  );
}

async function show(view: 'step' | 'permanent' = 'step', initial = BLOCK, monitor: GraphMonitor | null = null) {
  const i18n = await createI18n('en');
  render(
    <I18nextProvider i18n={i18n}>
      <Harness initial={initial} view={view} monitor={monitor} />
    </I18nextProvider>,
  );
}

const row = (k: number) => screen.getByTestId(`graph-action-${k}`);

/** Types `text` into a field as its last value and takes it with Enter (one change event: the
 * three LAD editors on the page make key-by-key typing slow in jsdom). */
function enter(field: HTMLElement, text: string) {
  fireEvent.focus(field);
  fireEvent.change(field, { target: { value: text } });
  fireEvent.keyDown(field, { key: 'Enter' });
}

describe('step view: the action table', () => {
  it('shows the selected step and its rows', async () => {
    await show();
    expect(screen.getByTestId('graph-step-picker')).toHaveProperty('value', 'Fill');
    const table = screen.getByRole('table', { name: 'Actions of step Fill' });
    expect(within(table).getAllByRole('row')).toHaveLength(3);
    expect(within(row(1)).getByRole('combobox', { name: 'Operand' })).toHaveProperty('value', 'Q 4.0');
    expect(within(row(2)).getByLabelText('Qualifier')).toHaveProperty('value', 'S');
  });

  it('adds a row, writes its operand, qualifier, event and time into the step', async () => {
    const user = userEvent.setup();
    await show();
    await user.click(screen.getByTestId('graph-action-add'));
    expect(fill().actions).toHaveLength(3);
    expect(fill().actions[2]).toMatchObject({ id: 'a3', qualifier: 'N', operand: '' });
    // A row without an operand is kept and marked (GRA247).
    expect(within(screen.getByTestId('graph-action-problems-3')).getByText('GRA247')).toBeTruthy();

    const operand = within(row(3)).getByRole('combobox', { name: 'Operand' });
    enter(operand, 'Q 5.1');
    expect(fill().actions[2]!.operand).toBe('Q 5.1');

    const qualifier = within(row(3)).getByLabelText('Qualifier');
    enter(qualifier, 'dc');
    expect(fill().actions[2]).toMatchObject({ qualifier: 'D', interlock: true });

    const time = within(row(3)).getByLabelText('Time');
    enter(time, 'T#3S');
    expect(fill().actions[2]!.time).toBe('T#3S');
    expect(screen.queryByTestId('graph-action-problems-3')).toBeNull();

    enter(within(row(1)).getByLabelText('Event'), 'S1');
    expect(fill().actions[0]!.event).toBe('S1');
    expect(current!.history).toEqual(['add action', 'change operand', 'change qualifier', 'change time', 'change event']);
  });

  it('moves and deletes rows', async () => {
    const user = userEvent.setup();
    await show();
    await user.click(screen.getByTestId('graph-action-down-1'));
    expect(fill().actions.map((a) => a.operand)).toEqual(['M 1.0', 'Q 4.0']);
    fireEvent.keyDown(within(row(2)).getByLabelText('Time'), { key: 'ArrowUp', altKey: true });
    expect(fill().actions.map((a) => a.operand)).toEqual(['Q 4.0', 'M 1.0']);
    await user.click(screen.getByTestId('graph-action-delete-1'));
    expect(fill().actions.map((a) => a.operand)).toEqual(['M 1.0']);
    // Ctrl+Z outside a text field undoes in the Graph document; inside a field it is the field's.
    fireEvent.keyDown(within(row(1)).getByLabelText('Time'), { key: 'z', ctrlKey: true });
    expect(fill().actions.map((a) => a.operand)).toEqual(['M 1.0']);
    fireEvent.keyDown(screen.getByTestId('graph-action-add'), { key: 'z', ctrlKey: true });
    expect(fill().actions.map((a) => a.operand)).toEqual(['Q 4.0', 'M 1.0']);
    fireEvent.keyDown(screen.getByTestId('graph-action-add'), { key: 'y', ctrlKey: true });
    expect(fill().actions.map((a) => a.operand)).toEqual(['M 1.0']);
  });

  it('keeps an illegal event/qualifier pair and marks it on the cell with its code', async () => {
    await show();
    const qualifier = within(row(1)).getByLabelText('Qualifier');
    enter(qualifier, 'D');
    enter(within(row(1)).getByLabelText('Time'), 'T#2S');
    expect(within(row(1)).getByLabelText('Qualifier').getAttribute('aria-invalid')).toBeNull();
    enter(within(row(1)).getByLabelText('Event'), 'S1');
    // Kept as chosen ...
    expect(fill().actions[0]).toMatchObject({ event: 'S1', qualifier: 'D' });
    // ... and marked: the qualifier's cell and input, the code and the message under the row.
    const marked = within(row(1)).getByLabelText('Qualifier');
    expect(marked.getAttribute('aria-invalid')).toBe('true');
    expect(marked.closest('td')!.getAttribute('aria-invalid')).toBe('true');
    expect(marked.getAttribute('title')).toMatch(/^GRA231: S1 D: D works on the time since the step became active/);
    const problems = screen.getByTestId('graph-action-problems-1');
    expect(within(problems).getByText('GRA231')).toBeTruthy();
    expect(problems.textContent).toContain('Remove S1.');
    // The events offered are those D takes: none.
    const events = within(row(1)).getByLabelText('Event').getAttribute('list')!;
    expect(document.getElementById(events)!.querySelectorAll('option')).toHaveLength(0);
  });

  it('keeps a typed word that is no qualifier or event in its field, marked, without changing the step', async () => {
    await show();
    const qualifier = within(row(2)).getByLabelText('Qualifier');
    enter(qualifier, 'SX');
    expect(fill().actions[1]!.qualifier).toBe('S');
    const field = within(row(2)).getByLabelText('Qualifier') as HTMLInputElement;
    expect(field.value).toBe('SX');
    expect(field.getAttribute('aria-invalid')).toBe('true');
    expect(screen.getByTestId('graph-action-problems-2').textContent).toContain('SX is not a qualifier');
    enter(field, 'R');
    expect(fill().actions[1]!.qualifier).toBe('R');
    expect(screen.queryByTestId('graph-action-problems-2')).toBeNull();
    // The same for an event.
    enter(within(row(2)).getByLabelText('Event'), 'X1');
    expect(fill().actions[1]!.event).toBeNull();
    expect(within(row(2)).getByLabelText('Event').getAttribute('aria-invalid')).toBe('true');
    expect(screen.getByTestId('graph-action-problems-2').textContent).toContain('X1 is not an event');
    enter(within(row(2)).getByLabelText('Event'), 'v1');
    expect(fill().actions[1]!.event).toBe('V1');
  });

  it('offers only the qualifiers that go with the row’s event', async () => {
    await show();
    const offered = () => {
      const list = within(row(1)).getByLabelText('Qualifier').getAttribute('list')!;
      return [...document.getElementById(list)!.querySelectorAll('option')].map((o) => o.getAttribute('value'));
    };
    expect(offered()).toContain('D');
    expect(offered()).not.toContain('ON');
    expect(offered()).not.toContain('TL');
    enter(within(row(1)).getByLabelText('Event'), 'S1');
    expect(offered()).toContain('ON');
    expect(offered()).toContain('NC');
    expect(offered()).not.toContain('D');
    enter(within(row(1)).getByLabelText('Event'), 'S0');
    expect(offered()).not.toContain('NC');
    expect(offered()).toContain('CALL');
  });
});

describe('step view: the step and its conditions', () => {
  it('renames the step and switches to another through the picker', async () => {
    const user = userEvent.setup();
    await show();
    const name = screen.getByTestId('graph-step-name');
    enter(name, 'Filling');
    expect(model().sequencers[0]!.steps[1]!.name).toBe('Filling');
    expect(model().sequencers[0]!.transitions[0]!.target).toEqual(['Filling']);
    await user.selectOptions(screen.getByTestId('graph-step-picker'), 'Drain');
    expect(screen.getByRole('table', { name: 'Actions of step Drain' })).toBeTruthy();
    // A name another step has is refused, and said so.
    const again = screen.getByTestId('graph-step-name');
    enter(again, 'Idle');
    expect(screen.getByTestId('graph-step-notice').textContent).toContain('Idle');
    expect(model().sequencers[0]!.steps[2]!.name).toBe('Drain');
  });

  it('draws the interlock and each leaving transition as a network ending in its pseudo coil', async () => {
    await show();
    const interlock = screen.getByTestId('graph-interlock');
    expect(within(interlock).getByTestId('lad-editor')).toBeTruthy();
    expect(within(interlock).getByTestId(`lad-1-1-${PSEUDO_COIL}`)).toBeTruthy();
    expect(within(interlock).getByTestId('lad-1-1-e1')).toBeTruthy();
    expect(within(interlock).queryByTestId('lad-insert-network')).toBeNull();
    const transitions = screen.getByTestId('graph-step-transitions');
    expect(within(transitions).getByTestId('lad-1-1-e1')).toBeTruthy();
    expect(within(transitions).getByTestId(`lad-1-2-${PSEUDO_COIL}`)).toBeTruthy();
    expect(transitions.textContent).toContain('T2 Trans2 → Drain');
    expect(transitions.textContent).toContain('T3 Trans3 ↷ Idle');
    // No supervision yet: a button adds an empty one.
    const supervision = screen.getByTestId('graph-supervision');
    expect(within(supervision).queryByTestId('lad-editor')).toBeNull();
    fireEvent.click(within(supervision).getByTestId('graph-supervision-add'));
    expect(fill().supervision).toEqual({ elements: [] });
    expect(within(screen.getByTestId('graph-supervision')).getByTestId('lad-editor')).toBeTruthy();
  });

  it('maps an edit of a condition in the LAD editor back into the step and the transition', async () => {
    await show();
    const interlock = screen.getByTestId('graph-interlock');
    const list = interlock.querySelector('.lad-editor__list') as HTMLElement;
    fireEvent.click(within(interlock).getByTestId('lad-1-1-e1'));
    fireEvent.keyDown(list, { key: 'F3', shiftKey: true }); // a normally closed contact after e1
    // The new contact asks for its operand.
    enter(within(interlock).getByTestId('operand-input'), 'I 0.3');
    expect(fill().interlock!.elements.map((e) => e.kind)).toEqual(['contact', 'contact']);
    expect(fill().interlock!.elements[1]).toMatchObject({ kind: 'contact', negated: true, operand: 'I 0.3' });
    expect(current!.history).toHaveLength(2);

    fireEvent.click(within(interlock).getByTestId('lad-1-1-e1'));
    fireEvent.keyDown(list, { key: 'Delete' });
    expect(fill().interlock!.elements).toHaveLength(1);
    expect(fill().interlock!.elements[0]).toMatchObject({ negated: true, operand: 'I 0.3' });

    // The transition Trans2 (network 1 of the transitions' editor).
    const transitions = screen.getByTestId('graph-step-transitions');
    const tlist = transitions.querySelector('.lad-editor__list') as HTMLElement;
    fireEvent.click(within(transitions).getByTestId('lad-1-1-e1'));
    fireEvent.keyDown(tlist, { key: 'Delete' });
    expect(model().sequencers[0]!.transitions[1]!.condition).toEqual({ elements: [] });
    expect(model().sequencers[0]!.transitions[0]!.condition!.elements).toHaveLength(1);

    // Undo is the Graph document's: back to the contact.
    act(() => current!.undo());
    expect(model().sequencers[0]!.transitions[1]!.condition!.elements).toHaveLength(1);
  });

  it('keeps the keyboard focus in the condition editor the user clicked', async () => {
    await show();
    const transitions = screen.getByTestId('graph-step-transitions');
    const element = within(transitions).getByTestId('lad-1-1-e1');
    fireEvent.click(element);
    // Every condition editor has a network 1 with an element e1: the focus goes to this one's.
    await waitFor(() => expect(document.activeElement).toBe(element));
    fireEvent.keyDown(document.activeElement!, { key: 'F2', shiftKey: true });
    enter(within(transitions).getByTestId('operand-input'), 'I 0.7');
    expect(model().sequencers[0]!.transitions[1]!.condition!.elements.map((e) => (e.kind === 'contact' ? e.operand : e.kind))).toEqual(['I 0.2', 'I 0.7']);
    expect(fill().interlock!.elements).toHaveLength(1);
  });

  it('refuses, and says so, an edit that would leave a condition’s shape', async () => {
    await show();
    const interlock = screen.getByTestId('graph-interlock');
    const list = interlock.querySelector('.lad-editor__list') as HTMLElement;
    fireEvent.click(within(interlock).getByTestId('lad-1-1-e1'));
    fireEvent.keyDown(list, { key: 'r', ctrlKey: true }); // a second network
    expect(screen.getByTestId('graph-step-notice').textContent).toContain('single network');
    expect(fill().interlock!.elements).toHaveLength(1);
    expect(current!.history).toHaveLength(0);
  });
});

describe('step view online', () => {
  const element = (id: string, value: ElementStatus['value'], out: boolean | null = null): [string, ElementStatus] => [id, { network: 0, id, value, out, pins: {} }];
  const monitor = (): GraphMonitor => ({
    status: {
      db: 'DB1',
      at: 0,
      mode: 'AUTO',
      steps: [
        { number: 1, name: 'Idle', state: 'inactive', t_ms: 0, u_ms: 0, interlock_error: false, supervision_error: false },
        { number: 2, name: 'Fill', state: 'disturbed', t_ms: 12_340, u_ms: 2_000, interlock_error: true, supervision_error: false },
        { number: 3, name: 'Drain', state: 'inactive', t_ms: 0, u_ms: 0, interlock_error: false, supervision_error: false },
      ],
      transitions: [
        { number: 1, name: 'Trans1', tt: false },
        { number: 2, name: 'Trans2', tt: true },
        { number: 3, name: 'Trans3', tt: false },
      ],
    },
    elements: new Map([element('S2/A1', true, true), element('S2/A2', false, false), element('S2/C/e1', false), element('T2/e1', true), element('T1/e1', true)]),
    session: null,
    db: 'DB1',
    hold: null,
    problem: null,
  });

  it('shows the step’s state and times, the actions’ values and the conditions’ power flow', async () => {
    await show('step', BLOCK, monitor());
    const online = screen.getByTestId('graph-step-online');
    expect(online.getAttribute('data-state')).toBe('disturbed');
    expect(online.textContent).toContain('12.3 s');
    expect(online.textContent).toContain('Interlock not fulfilled');
    expect(screen.getByTestId('graph-action-value-1').textContent).toBe('1');
    expect(screen.getByTestId('graph-action-value-1').getAttribute('data-out')).toBe('true');
    expect(screen.getByTestId('graph-action-value-2').textContent).toBe('0');
    // The interlock's contact I 0.1 reads 0: open, no flow to C (the interlock error).
    const interlock = screen.getByTestId('graph-interlock');
    expect(within(interlock).getByTestId('lad-1-1-e1').getAttribute('data-contact')).toBe('off');
    expect(within(interlock).getByTestId(`lad-1-1-${PSEUDO_COIL}`).getAttribute('data-flow')).toBe('off');
    // Trans2's contact conducts (T2/e1), Trans1's element (another step's transition) is not shown here.
    const transitions = screen.getByTestId('graph-step-transitions');
    expect(within(transitions).getByTestId('lad-1-1-e1').getAttribute('data-contact')).toBe('on');
    expect(within(transitions).getByTestId('lad-1-1-e1').getAttribute('data-flow')).toBe('on');
  });
});

describe('condition adapter', () => {
  const series: Series = { elements: [contact('e1', 'I 0.0')] };
  const network = conditionNetwork(series, 'Trans1', 'T1');

  it('is one network: the condition and the fixed pseudo coil, the same object for the same condition', () => {
    expect(network.logic).toBe(series);
    expect(network.outputs).toEqual([{ conditions: { elements: [] }, target: { id: PSEUDO_COIL, kind: 'coil', coil: '=', operand: 'Trans1', value: null } }]);
    expect(conditionNetwork(series, 'Trans1', 'T1')).toBe(network);
  });

  it('takes contacts placed before the pseudo coil into the condition, refuses other outputs', () => {
    const before: Network = network;
    const withBranch: Network = { ...network, outputs: [{ ...network.outputs[0]!, conditions: { elements: [contact('e2', 'I 0.5')] } }] };
    expect(seriesOf(before, withBranch)).toEqual({ elements: [contact('e1', 'I 0.0'), contact('e2', 'I 0.5')] });
    const twoCoils: Network = { ...network, outputs: [...network.outputs, { conditions: { elements: [] }, target: { id: 'e3', kind: 'coil', coil: '=', operand: 'Q 0.0', value: null } }] };
    expect(seriesOf(before, twoCoils)).toBe('outputs');
    const renamed: Network = { ...network, outputs: [{ conditions: { elements: [] }, target: { id: PSEUDO_COIL, kind: 'coil', coil: 'S', operand: 'Trans1', value: null } }] };
    expect(seriesOf(before, renamed)).toBe('coil');
    expect(seriesOf(before, { ...network, title: 'x' })).toBe('header');
  });

  it('writes only the conditions that changed', () => {
    const transition = BLOCK.sequencers[0]!.transitions[0]!;
    const slots: ConditionSlot[] = [
      { coil: 'Trans1', title: 'T1', series: transition.condition, origin: 'T1/', write: (b, s) => updateTransition(b, 'Trans1', (t) => ({ ...t, condition: s })) },
    ];
    const before = syntheticBlock(BLOCK, [conditionNetwork(transition.condition, 'Trans1', 'T1')]);
    expect(applyConditionEdit(BLOCK, slots, before, before)).toBe(BLOCK);
    const changed = { elements: [contact('e1', 'I 0.0'), contact('e2', 'I 1.0')] };
    const after = { ...before, networks: [{ ...before.networks[0]!, logic: changed }] };
    const written = applyConditionEdit(BLOCK, slots, before, after);
    expect(typeof written).toBe('object');
    expect((written as GraphBlock).sequencers[0]!.transitions[0]!.condition).toEqual(changed);
    expect(applyConditionEdit(BLOCK, slots, before, { ...before, networks: [] })).toBe('networks');
  });
});

describe('condition problems', () => {
  it('places the checker’s findings on the networks and elements of the conditions', () => {
    const diagnostic = (code: string, element: string, file = 'Seq.graph') => ({ code, severity: 'error' as const, key: 'k', message: `${code} here`, params: {}, span: { file, line: 3, element } });
    const found = conditionProblems(
      [diagnostic('GRA260', 'S2/C/e3'), diagnostic('GRA262', 'T3'), diagnostic('GRA261', 'T2/e1'), diagnostic('GRA231', 'S2/A1'), diagnostic('GRA260', 'S2/C/e4', 'Other.graph')],
      'Seq.graph',
      [{ origin: 'S2/C/' }, { origin: 'T3/' }],
      (d) => d.message,
    );
    expect([...found.networks.keys()]).toEqual(['0:0', '0:1']);
    expect(found.networks.get('0:0')!.elements.get('e3')).toEqual([{ code: 'GRA260', message: 'GRA260 here', severity: 'error' }]);
    expect(found.networks.get('0:0')!.elementCount).toBe(1);
    expect(found.networks.get('0:1')!.network.map((p) => p.code)).toEqual(['GRA262']);
  });
});

describe('permanent instructions', () => {
  it('adds a network to the pre-instructions and edits it in the LAD editor', async () => {
    await show('permanent');
    const pre = screen.getByTestId('graph-permanent-pre');
    expect(within(pre).getByTestId('lad-editor')).toBeTruthy();
    fireEvent.click(within(pre).getByTestId('lad-add-network-1'));
    expect(model().pre).toHaveLength(1);
    expect(model().post).toHaveLength(0);
    // A coil is fine here (a permanent instruction sets markers).
    const list = pre.querySelector('.lad-editor__list') as HTMLElement;
    fireEvent.click(within(pre).getByTestId('network-1-1-header'));
    fireEvent.keyDown(list, { key: 'F7', shiftKey: true });
    enter(within(pre).getByTestId('operand-input'), 'M 10.0');
    expect(model().pre[0]!.outputs.map((o) => o.target)).toMatchObject([{ kind: 'coil', coil: '=', operand: 'M 10.0' }]);
    act(() => current!.undo());
    act(() => current!.undo());
    act(() => current!.undo());
    expect(model().pre).toHaveLength(0);
  });
});
