/** Display formats of the watch table, the values typed to modify, and the sources' symbols and I/O bytes. */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import {
  normaliseAddress,
  parseSymbolTable,
  shownIoBytes,
  usedIoBytes,
} from '../../frontend/src/cpu/projectSymbols';
import {
  defaultFormat,
  formatTime,
  formatValue,
  formatsFor,
  numericValue,
  parseModifyValue,
} from '../../frontend/src/panels/watchFormat';

describe('watch display formats', () => {
  it('offers the formats that fit each type, starting from the usual one', () => {
    expect(formatsFor('BOOL')).toEqual(['bool', 'bin']);
    expect(formatsFor('BYTE')).toEqual(['bin', 'hex', 'dec', 'char']);
    expect(formatsFor('DWORD')).toEqual(['bin', 'hex', 'dec', 'real', 'char', 'time']);
    expect(formatsFor('local')).toEqual([]);
    expect(['BOOL', 'WORD', 'INT', 'REAL', 'CHAR', 'TIME', 'S5TIME'].map(defaultFormat)).toEqual([
      'bool',
      'hex',
      'dec',
      'real',
      'char',
      'time',
      'time',
    ]);
  });

  it('shows integers in binary, hex, decimal and as characters, by width', () => {
    expect(formatValue(5, 'BYTE', 'bin')).toBe('2#0000_0101');
    expect(formatValue(255, 'BYTE', 'hex')).toBe('B#16#FF');
    expect(formatValue(-2, 'INT', 'hex')).toBe('W#16#FFFE');
    expect(formatValue(-2, 'INT', 'dec')).toBe('-2');
    expect(formatValue(0xfffe, 'WORD', 'dec')).toBe('65534');
    expect(formatValue(0x4142, 'WORD', 'char')).toBe("'AB'");
    expect(formatValue(-1, 'DINT', 'hex')).toBe('DW#16#FFFFFFFF');
    expect(formatValue(0x3fc00000, 'DWORD', 'real')).toBe('1.5');
  });

  it('shows REAL, BOOL, CHAR and times as STEP 7 writes them', () => {
    expect(formatValue(1.5, 'REAL', 'real')).toBe('1.5');
    expect(formatValue(1.5, 'REAL', 'hex')).toBe('DW#16#3FC00000');
    expect(formatValue('NaN', 'REAL', 'real')).toBe('NaN');
    expect(formatValue(true, 'BOOL', 'bool')).toBe('TRUE');
    expect(formatValue(false, 'BOOL', 'bin')).toBe('2#0');
    expect(formatValue('A', 'CHAR', 'char')).toBe("'A'");
    expect(formatValue('A', 'CHAR', 'hex')).toBe('B#16#41');
    expect(formatValue(90_500, 'TIME', 'time')).toBe('T#1M_30S_500MS');
    expect(formatValue(-500, 'TIME', 'time')).toBe('T#-500MS');
    expect(formatValue(2000, 'S5TIME', 'time')).toBe('S5T#2S');
    expect(formatValue(null, 'INT', 'dec')).toBe('');
    expect(formatTime(0)).toBe('T#0MS');
    expect(formatTime(90_061_001)).toBe('T#1D_1H_1M_1S_1MS');
  });

  it('sends what the user typed as the value the protocol takes', () => {
    expect(parseModifyValue(' TRUE ')).toBe(true);
    expect(parseModifyValue('-3')).toBe(-3);
    expect(parseModifyValue('1.5')).toBe(1.5);
    expect(parseModifyValue('16#FF')).toBe('16#FF');
    expect(parseModifyValue('T#2S')).toBe('T#2S');
    expect(numericValue(true)).toBe(1);
    expect(numericValue('NaN')).toBeNull();
  });
});

describe('symbols and I/O bytes of the sources', () => {
  const motor = path.resolve(__dirname, '../../examples/projects/motor-start-stop');
  const read = (name: string) => ({ name, text: fs.readFileSync(path.join(motor, name), 'utf8') });

  it('reads the symbol table formats with either mnemonic set', () => {
    expect(parseSymbolTable('symbols.sdf', '"Motor","Q 4.0","BOOL","coil"\n')).toEqual([
      { name: 'Motor', address: 'Q4.0', type: 'BOOL', comment: 'coil' },
    ]);
    const asc = `126,${'Start'.padEnd(24)}${'E 0.0'.padEnd(12)}${'BOOL'.padEnd(10)}push button`;
    expect(parseSymbolTable('s.asc', asc)).toEqual([{ name: 'Start', address: 'I0.0', type: 'BOOL', comment: 'push button' }]);
    expect(parseSymbolTable('s.csv', 'name;address;type;comment\nLevel;MW 10;INT;in %')).toEqual([
      { name: 'Level', address: 'MW10', type: 'INT', comment: 'in %' },
    ]);
    expect(parseSymbolTable('OB1.awl', '"x","Q 4.0"')).toEqual([]);
    expect(['A 4.0', 'EB 1', 'PEW 256', 'mw 10'].map(normaliseAddress)).toEqual(['Q4.0', 'IB1', 'PIW256', 'MW10']);
  });

  it('finds the I/O bytes the program uses, the digital ones only', () => {
    const used = usedIoBytes([read('OB1.awl'), read('symbols.sdf')]);
    expect(used).toEqual({ inputs: [0], outputs: [4] });
    expect(shownIoBytes(used)).toEqual({ inputs: [0, 1, 2, 3], outputs: [0, 1, 2, 3, 4] });
    const german = { name: 'FC1.awl', text: 'U E 6.1\n= A 5.0\nL PEW 256\nT AW 8\nA I 0.0\nE001: NOP 0' };
    expect(usedIoBytes([german])).toEqual({ inputs: [0, 6], outputs: [5, 8, 9] });
    expect(usedIoBytes([{ name: 'FC2.scl', text: '%Q7.1 := %I12.0 AND x; y := 1.5E 3;' }])).toEqual({ inputs: [12], outputs: [7] });
    const ladder = 'RUNG\n  Contact(I 3.0)\n  ContactNC("Stop")\n  Coil(Q 6.1)\nEND_RUNG';
    expect(usedIoBytes([{ name: 'Latch.lad', text: ladder }])).toEqual({ inputs: [3], outputs: [6] });
    expect(usedIoBytes([{ name: 'Gates.fbd', text: ladder }])).toEqual({ inputs: [3], outputs: [6] });
  });
});
