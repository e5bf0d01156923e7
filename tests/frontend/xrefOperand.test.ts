import { describe, expect, it } from 'vitest';
import { operandAt } from '../../frontend/src/xref/operandAt';

/** The column (1-based) of the first character of `part` in `line`, plus `offset`. */
function at(line: string, part: string, offset = 1): number {
  return line.indexOf(part) + 1 + offset;
}

describe('operand under the caret (Shift+F12, F2)', () => {
  it('takes a quoted symbol, not the comment after it', () => {
    const line = '      O     "Motor";             // ... or "Start"';
    expect(operandAt(line, at(line, '"Motor"'))).toBe('"Motor"');
    expect(operandAt(line, at(line, '"Start"'))).toBeNull();
  });

  it('takes a DB member on the member, the DB on its name', () => {
    const line = '  LowLevel := "TankSettings".LowLevel,';
    expect(operandAt(line, at(line, '.LowLevel', 3))).toBe('"TankSettings".LowLevel');
    expect(operandAt(line, at(line, '"TankSettings"', 2))).toBe('"TankSettings"');
    expect(operandAt('  L DB1.Speed', 8)).toBe('DB1.Speed');
  });

  it('takes absolute addresses, timers and blocks with their spacing normalised', () => {
    expect(operandAt('      A     I      0.0;', 20)).toBe('I 0.0');
    expect(operandAt('      T     MW    10;', 14)).toBe('MW 10');
    expect(operandAt('      SD    T      1;', 14)).toBe('T 1');
    expect(operandAt('      CALL  FB 10 , DB 10', 15)).toBe('FB 10');
    expect(operandAt('      L     DB1.DBW 2', 16)).toBe('DB1.DBW 2');
  });

  it('does not take a load constant, a local or an instruction for an address', () => {
    expect(operandAt('      L     10;', 13)).toBeNull();
    expect(operandAt('      A     #Start;', 14)).toBeNull();
  });
});
