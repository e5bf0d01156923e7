import type { Problem } from '../../api/monitorClient';

/**
 * The line MON604 ("no code here") names as the next one with code, or null: the server's
 * `next_line` param; the number at the end of its English `hint` for an older server.
 */
export function nextCodeLine(problem: Pick<Problem, 'code' | 'params'> | null | undefined): number | null {
  if (!problem || problem.code !== 'MON604') return null;
  const direct = problem.params.next_line;
  if (typeof direct === 'number' && Number.isInteger(direct) && direct > 0) return direct;
  const hint = problem.params.hint;
  if (typeof hint !== 'string') return null;
  const found = /(\d+)\D*$/.exec(hint);
  return found ? Number(found[1]) : null;
}
