/**
 * The rules of one row of a step's action table, ported from the checker
 * (`backend/nasaq/lang/graph/check_actions.py`, GRA230–GRA247): which event goes with which
 * qualifier and C suffix, which qualifiers need a value after the comma, which operand each
 * qualifier takes. The step view checks a row as it is typed, without waiting for the server;
 * `tests/frontend/graphStepRules.test.ts` holds this port to the Python checker entry by entry
 * (fixture `tests/frontend/fixtures/graph-action-rules.json`).
 */
import type { Action, GraphBlock, Step } from './model';

export type Event = NonNullable<Action['event']>;
export type Qualifier = Action['qualifier'];

export const EVENTS: readonly Event[] = ['S1', 'S0', 'V1', 'V0', 'L1', 'L0', 'A1', 'R1'];
export const QUALIFIERS: readonly Qualifier[] = ['N', 'S', 'R', 'D', 'L', 'CALL', 'ON', 'OFF', 'CS', 'CU', 'CD', 'CR', 'TL', 'TD', 'TR'];

/** The events a C suffix goes with (none included). */
const C_EVENTS: ReadonlySet<Event | null> = new Set<Event | null>([null, 'S1', 'V1', 'A1', 'R1']);
const OFF_ALL_EVENTS: ReadonlySet<Event> = new Set<Event>(['S1', 'V1', 'L1']);
/** D and L act on the step's time since its activation: never with an event. */
const WITHOUT_EVENT: ReadonlySet<Qualifier> = new Set<Qualifier>(['D', 'L']);
/** These act once: only with an event. */
const NEEDS_EVENT: ReadonlySet<Qualifier> = new Set<Qualifier>(['ON', 'OFF', 'CS', 'CU', 'CD', 'CR', 'TL', 'TD', 'TR']);
const COUNTERS: ReadonlySet<Qualifier> = new Set<Qualifier>(['CS', 'CU', 'CD', 'CR']);
const TIMERS: ReadonlySet<Qualifier> = new Set<Qualifier>(['TL', 'TD', 'TR']);
const BITS: ReadonlySet<Qualifier> = new Set<Qualifier>(['N', 'S', 'R', 'D', 'L']);

/** The qualifiers that take a value after the comma: the constant prefixes that do not fit, and an example. */
const VALUES: Partial<Record<Qualifier, { refused: readonly string[]; example: string }>> = {
  D: { refused: ['S5T#', 'S5TIME#', 'C#'], example: 'T#5S' },
  L: { refused: ['S5T#', 'S5TIME#', 'C#'], example: 'T#5S' },
  CS: { refused: ['T#', 'TIME#', 'S5T#', 'S5TIME#'], example: 'C#10' },
  TL: { refused: ['T#', 'TIME#', 'C#'], example: 'S5T#5S' },
  TD: { refused: ['T#', 'TIME#', 'C#'], example: 'S5T#5S' },
};

const SYMBOL = '"[^"]+"';
const LOCAL = '#[A-Za-z_]\\w*(?:\\.[A-Za-z_]\\w*)*';
const BLOCK = new RegExp(`^(?:(?:FC|FB|SFC|SFB)\\s*\\d+|${SYMBOL})(?:\\s*,\\s*(?:DB\\s*\\d+|DI\\s*\\d+|${SYMBOL}|${LOCAL}))?$`, 'i');
const COUNTER = new RegExp(`^(?:C\\s*\\d+|Z\\s*\\d+|${SYMBOL}|${LOCAL})$`, 'i');
const TIMER = new RegExp(`^(?:T\\s*\\d+|${SYMBOL}|${LOCAL})$`, 'i');
const NOT_A_BIT = /^(?:(?:T|C|Z|FC|FB|SFC|SFB|DB|DI|OB|UDT)\s*\d+|S_ALL)$/i;
const NUMBER = /^[+-]?\d+$/;
const STEP_BY_NUMBER = /^S(\d+)$/i;

export type RuleCode =
  | 'GRA230' | 'GRA231' | 'GRA232' | 'GRA233' | 'GRA234' | 'GRA235' | 'GRA236' | 'GRA237'
  | 'GRA238' | 'GRA239' | 'GRA240' | 'GRA241' | 'GRA242' | 'GRA243' | 'GRA246' | 'GRA247';

/** A finding on one row: its catalogue code, message key and parameters (as the server's). */
export interface RowProblem {
  code: RuleCode;
  key: string;
  severity: 'error' | 'warning';
  params: Record<string, string>;
  /** The cell it belongs on. */
  cell: 'event' | 'qualifier' | 'operand' | 'time';
}

const KEYS: Record<RuleCode, [string, RowProblem['severity'], RowProblem['cell']]> = {
  GRA230: ['graph_interlock_with_event', 'error', 'qualifier'],
  GRA231: ['graph_time_action_with_event', 'error', 'qualifier'],
  GRA232: ['graph_action_needs_event', 'error', 'qualifier'],
  GRA233: ['graph_off_all_event', 'error', 'event'],
  GRA234: ['graph_on_all', 'error', 'operand'],
  GRA235: ['graph_action_unknown_step', 'error', 'operand'],
  GRA236: ['graph_action_needs_value', 'error', 'time'],
  GRA237: ['graph_action_unexpected_value', 'error', 'time'],
  GRA238: ['graph_action_wrong_value', 'error', 'time'],
  GRA239: ['graph_call_not_block', 'error', 'operand'],
  GRA240: ['graph_counter_operand', 'error', 'operand'],
  GRA241: ['graph_timer_operand', 'error', 'operand'],
  GRA242: ['graph_assignment_needs_n', 'error', 'operand'],
  GRA243: ['graph_interlock_missing', 'warning', 'qualifier'],
  GRA246: ['graph_bit_operand', 'error', 'operand'],
  GRA247: ['graph_action_without_operand', 'error', 'operand'],
};

function problem(code: RuleCode, params: Record<string, string>): RowProblem {
  const [key, severity, cell] = KEYS[code];
  return { code, key, severity, params, cell };
}

/** The qualifier with its C suffix as written: `NC`, `CALL`. */
export function qualifierText(qualifier: Qualifier, interlock: boolean): string {
  return qualifier + (interlock ? 'C' : '');
}

/** The row's instruction as written: `S1 NC`, `D` (the checker's `written`). */
export function written(action: Pick<Action, 'event' | 'qualifier' | 'interlock'>): string {
  const qualifier = qualifierText(action.qualifier, action.interlock);
  return action.event ? `${action.event} ${qualifier}` : qualifier;
}

/** A typed qualifier (`n`, `NC`, `CALL`) as the reader takes it; null when it is none. */
export function parseQualifier(typed: string): { qualifier: Qualifier; interlock: boolean } | null {
  const word = typed.trim().toUpperCase();
  if ((QUALIFIERS as readonly string[]).includes(word)) return { qualifier: word as Qualifier, interlock: false };
  const base = word.slice(0, -1);
  if (word.endsWith('C') && (QUALIFIERS as readonly string[]).includes(base)) return { qualifier: base as Qualifier, interlock: true };
  return null;
}

/** Whether the event, qualifier and C suffix go together (GRA230, GRA231, GRA232). */
export function legalPair(event: Event | null, qualifier: Qualifier, interlock: boolean): boolean {
  if (interlock && !C_EVENTS.has(event)) return false;
  if (event !== null && WITHOUT_EVENT.has(qualifier)) return false;
  if (event === null && NEEDS_EVENT.has(qualifier)) return false;
  return true;
}

/** The qualifiers (with and without C) that go with `event`, in the order of the table. */
export function legalQualifiers(event: Event | null): string[] {
  const found: string[] = [];
  for (const qualifier of QUALIFIERS) {
    for (const interlock of [false, true]) {
      if (legalPair(event, qualifier, interlock)) found.push(qualifierText(qualifier, interlock));
    }
  }
  return found;
}

/** The events (null: none) that go with the qualifier and C suffix. */
export function legalEvents(qualifier: Qualifier, interlock: boolean): (Event | null)[] {
  return [null, ...EVENTS].filter((event) => legalPair(event, qualifier, interlock));
}

/** Whether the qualifier takes a value after the comma (D/L time, CS preset, TL/TD time), and an example. */
export function valueExample(qualifier: Qualifier): string | null {
  return VALUES[qualifier]?.example ?? null;
}

/** How the step is found by ON/OFF: by name first (any case), else `S<number>`. */
export function stepReference(steps: readonly Step[], text: string): Step | null {
  const wanted = text.trim().toUpperCase();
  const named = steps.find((step) => step.name.toUpperCase() === wanted);
  if (named) return named;
  const number = STEP_BY_NUMBER.exec(text.trim());
  return number ? (steps.find((step) => step.number === Number(number[1])) ?? null) : null;
}

/** Every step of the block, in chart order (the checker's `ctx.steps`). */
export function blockSteps(block: GraphBlock): Step[] {
  return block.sequencers.flatMap((sequencer) => sequencer.steps);
}

/**
 * The findings on one row of `step`'s table, in the checker's order. `steps`: every step of
 * the block (for ON/OFF). Python's `check_actions._row`, rule for rule.
 */
export function checkAction(action: Action, step: Step, steps: readonly Step[]): RowProblem[] {
  const found: RowProblem[] = [];
  const { qualifier, event } = action;
  const operand = action.operand.trim();
  const row = written(action);
  if (!operand) return [problem('GRA247', { action: row })];
  if (action.interlock && !C_EVENTS.has(event)) found.push(problem('GRA230', { action: row, event: String(event) }));
  if (event !== null && WITHOUT_EVENT.has(qualifier)) found.push(problem('GRA231', { action: row, qualifier, event }));
  if (event === null && NEEDS_EVENT.has(qualifier)) found.push(problem('GRA232', { action: row, qualifier }));
  if (action.interlock && step.interlock === null) found.push(problem('GRA243', { action: row, step: step.name }));
  const arithmetic = operand.includes(':=');
  if (arithmetic && qualifier !== 'N') found.push(problem('GRA242', { action: row, operand }));
  found.push(...checkValue(action, row));
  if (arithmetic) return found;
  if (qualifier === 'ON' || qualifier === 'OFF') found.push(...checkStepControl(action, row, steps));
  else if (qualifier === 'CALL') {
    if (!BLOCK.test(operand)) found.push(problem('GRA239', { action: row, operand }));
  } else if (COUNTERS.has(qualifier)) {
    if (!COUNTER.test(operand)) found.push(problem('GRA240', { action: row, operand }));
  } else if (TIMERS.has(qualifier)) {
    if (!TIMER.test(operand)) found.push(problem('GRA241', { action: row, operand }));
  } else if (BITS.has(qualifier) && NOT_A_BIT.test(operand)) found.push(problem('GRA246', { action: row, operand }));
  return found;
}

function checkStepControl(action: Action, row: string, steps: readonly Step[]): RowProblem[] {
  const operand = action.operand.trim();
  if (operand.toUpperCase() === 'S_ALL') {
    if (action.qualifier === 'ON') return [problem('GRA234', { action: row })];
    if (action.event !== null && !OFF_ALL_EVENTS.has(action.event)) return [problem('GRA233', { action: row, event: action.event })];
    return [];
  }
  if (stepReference(steps, operand) === null) return [problem('GRA235', { action: row, step: operand })];
  return [];
}

/** The value after the comma: present where needed, of the right kind, absent elsewhere. */
function checkValue(action: Action, row: string): RowProblem[] {
  const value = (action.time ?? '').trim();
  const expected = VALUES[action.qualifier];
  const operand = action.operand.trim();
  if (!expected) return value ? [problem('GRA237', { action: row, value })] : [];
  if (!value) return [problem('GRA236', { action: row, operand, example: expected.example })];
  const upper = value.toUpperCase().replace(/ /g, '');
  if (expected.refused.some((prefix) => upper.startsWith(prefix)) || NUMBER.test(upper)) {
    return [problem('GRA238', { action: row, value, operand, example: expected.example })];
  }
  return [];
}
