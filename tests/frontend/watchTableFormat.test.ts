/** The watch table file (`.vat`) as the browser reads and prints it; the backend's tests read the same text. */
import { describe, expect, it } from 'vitest';
import { HEADER, isOperand, parseWatchTable, printWatchTable } from '../../frontend/src/watchtables/format';

describe('watch table files', () => {
  it('reads rows with formats, values and comments and prints them back alike', () => {
    const text = `${HEADER}
MW10         | DEC     | 5  // set point
"Motor"      | BOOL
T1           | simatic_time | S5T#1S850MS
"a | b"      | CHAR    | '|'  // quotes keep | and //
// a comment line
`;
    const table = parseWatchTable(text);
    expect(table.lines.map((line) => line.kind)).toEqual(['row', 'row', 'row', 'row', 'row']);
    const rows = table.lines.flatMap((line) => (line.kind === 'row' ? [line.row] : []));
    expect(rows[0]).toEqual({ operand: 'MW10', format: 'dec', modify: '5', force: '', comment: 'set point' });
    expect(rows[2]).toMatchObject({ operand: 'T1', format: 's5time', modify: 'S5T#1S850MS' });
    expect(rows[3]).toMatchObject({ operand: '"a | b"', modify: "'|'", comment: 'quotes keep | and //' });
    expect(rows[4]).toMatchObject({ operand: '', comment: 'a comment line' });
    const printed = printWatchTable(table);
    expect(printed).toContain('T1           | S5TIME  | S5T#1S850MS');
    expect(printWatchTable(parseWatchTable(printed))).toBe(printed);
  });

  it('keeps broken lines verbatim with their line, column and code, and loads the good ones', () => {
    const text = [HEADER, 'MW10 | DEC', 'MW12 | DECIMALS', '"Motor | BOOL', 'M 0.0 0.1', 'MW14 | DEC | 1 | 2 | 3', ' | HEX', 'QW4'].join('\n');
    const table = parseWatchTable(text);
    const broken = table.lines.flatMap((line) => (line.kind === 'broken' ? [line.problem] : []));
    expect(broken.map((problem) => [problem.code, problem.line])).toEqual([
      ['WAT802', 3],
      ['WAT803', 4],
      ['WAT801', 5],
      ['WAT804', 6],
      ['WAT805', 7],
    ]);
    expect(broken[0]).toMatchObject({ key: 'watch_unknown_format', params: { format: 'DECIMALS' }, column: 8 });
    const printed = printWatchTable(table).split('\n');
    for (const line of text.split('\n').slice(2, 7)) expect(printed).toContain(line);
  });

  it('knows the shapes of operands', () => {
    for (const good of ['MW10', 'I 0.0', 'PIW256', 'T1', 'DB1.DBX0.1', '"Motor"', '"Line".cells[2].speed', 'DB1.level']) {
      expect(isOperand(good)).toBe(true);
    }
    for (const bad of ['M 0.0 0.1', 'MW10)', '"Motor', '12', '']) expect(isOperand(bad)).toBe(false);
  });
});
