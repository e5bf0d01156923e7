/**
 * Names and numbers of new steps, transitions and sequencers, as S7-Graph gives them: `Step<n>`
 * and `Trans<n>` with the smallest n that is free both as a number (step numbers and transition
 * numbers are unique in the FB: S_SEL/S_NO and `ON S<n>` name steps by number) and as a name
 * (steps and transitions share one name space, each becomes a member of the instance DB; names
 * compare without case, as the checker compares them).
 */
import type { GraphBlock, Step, Transition } from './model';

/** The format's words refused as names (text_words.NOT_NAMES). */
const NOT_NAMES = new Set([
  'FUNCTION_BLOCK', 'END_FUNCTION_BLOCK', 'SEQUENCER', 'END_SEQUENCER', 'PERMANENT_PRE', 'END_PERMANENT_PRE',
  'PERMANENT_POST', 'END_PERMANENT_POST', 'STEP', 'INITIAL_STEP', 'TRANSITION', 'COMMENT', 'INTERLOCK',
  'SUPERVISION', 'ACTIONS', 'CONDITION', 'END_STEP', 'END_TRANSITION', 'END_CONDITION', 'END_INTERLOCK',
  'END_SUPERVISION', 'END_ACTIONS', 'SETTINGS', 'END_SETTINGS', 'BEGIN',
]);

const IDENTIFIER = /^[A-Za-z_]\w*$/;

/** Whether `name` can name a step, transition or sequencer in the text format (and the DB). */
export function isValidName(name: string): boolean {
  return IDENTIFIER.test(name) && !NOT_NAMES.has(name.toUpperCase()) && !name.toUpperCase().startsWith('G7_');
}

export function allSteps(block: GraphBlock): Step[] {
  return block.sequencers.flatMap((sequencer) => sequencer.steps);
}

export function allTransitions(block: GraphBlock): Transition[] {
  return block.sequencers.flatMap((sequencer) => sequencer.transitions);
}

/** The names of the block's steps and transitions, upper case. */
export function usedNames(block: GraphBlock): Set<string> {
  return new Set([...allSteps(block), ...allTransitions(block)].map((item) => item.name.toUpperCase()));
}

function fresh(prefix: string, numbers: ReadonlySet<number>, names: ReadonlySet<string>): { name: string; number: number } {
  for (let n = 1; ; n += 1) {
    if (!numbers.has(n) && !names.has(`${prefix}${n}`.toUpperCase())) return { name: `${prefix}${n}`, number: n };
  }
}

export function newStepName(block: GraphBlock): { name: string; number: number } {
  return fresh('Step', new Set(allSteps(block).map((step) => step.number)), usedNames(block));
}

export function newTransitionName(block: GraphBlock): { name: string; number: number } {
  return fresh('Trans', new Set(allTransitions(block).map((t) => t.number)), usedNames(block));
}

export function newSequencerName(block: GraphBlock): string {
  const taken = new Set(block.sequencers.map((sequencer) => sequencer.name.toUpperCase()));
  for (let n = block.sequencers.length + 1; ; n += 1) if (!taken.has(`SEQ${n}`)) return `Seq${n}`;
}

export function sameName(a: string, b: string): boolean {
  return a === b || (a.length === b.length && a.toUpperCase() === b.toUpperCase());
}
