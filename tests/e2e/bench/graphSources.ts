/**
 * The S7-Graph source of the chart bench, generated: FB 1 with one sequencer of `steps` steps, a
 * chain with what a real sequence has along it: an alternative branch every 20 steps (a skip),
 * a simultaneous branch and its join every 50, an action on every step, a jump back to the start
 * at the end. Every transition is true while M 10.0 is (OB 1 sets it), so the sequence moves on
 * by one step per call: while monitored, the active step changes at every sample.
 */
export function graphChain(steps: number): string {
  const lines = ['FUNCTION_BLOCK FB 1', 'TITLE = Chart bench', 'BEGIN', 'SEQUENCER Chain', ''];
  const condition = 'CONDITION Contact(M 10.0) END_CONDITION';
  let transition = 0;
  const add = (from: string, to: string) => {
    transition += 1;
    lines.push(`TRANSITION Trans${transition} (${transition}) FROM ${from} ${to}`, condition, 'END_TRANSITION', '');
  };
  for (let k = 1; k <= steps; k += 1) {
    lines.push(`${k === 1 ? 'INITIAL_STEP' : 'STEP'} Step${k} (${k})`, 'ACTIONS', `  N Q ${Math.floor(k / 8) % 16}.${k % 8};`, 'END_ACTIONS', 'END_STEP', '');
    if (k === steps) add(`Step${k}`, 'JUMP Step1');
    else if (k % 50 === 10 && k + 3 <= steps) add(`Step${k}`, `TO (Step${k + 1}, Step${k + 2})`);
    else if (k % 50 === 11 && k > 11 - 1 && (k - 1) % 50 === 10) continue;
    else if (k % 50 === 12 && (k - 2) % 50 === 10) add(`(Step${k - 1}, Step${k})`, `TO Step${k + 1}`);
    else if (k % 20 === 5 && k + 2 <= steps) {
      add(`Step${k}`, `TO Step${k + 1}`);
      add(`Step${k}`, `TO Step${k + 2}`);
    } else add(`Step${k}`, `TO Step${k + 1}`);
  }
  lines.push('END_SEQUENCER', 'END_FUNCTION_BLOCK', '');
  return lines.join('\n');
}

export const CHART_OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Calls the bench sequencer; all its transitions hold
BEGIN
NETWORK
TITLE = Every transition true
      SET   ;
      =     M 10.0;
NETWORK
TITLE = The sequencer
      CALL FB 1, DB 1;
END_ORGANIZATION_BLOCK
`;
