/** Display formats of the watch table, the values typed to modify, and the sources' symbols. */
import { describe, expect, it } from 'vitest';
import { normaliseAddress, parseSymbolTable } from '../../frontend/src/cpu/projectSymbols';
import {
  countOfWord,
  defaultFormat,
  formatS5Time,
  formatTime,
  modifyValueFor,
  parseCount,
  parseS5Time,
  s5TimeOfWord,
  wordOfCount,
  wordOfS5Time,
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
    expect(['BOOL', 'WORD', 'INT', 'REAL', 'CHAR', 'TIME', 'S5TIME', 'TIMER', 'COUNTER'].map(defaultFormat)).toEqual([
      'bool',
      'hex',
      'dec',
      'real',
      'char',
      'time',
      's5time',
      's5time',
      'counter',
    ]);
    expect(formatsFor('WORD')).toEqual(['bin', 'hex', 'dec', 'char', 's5time', 'counter']);
    expect(formatsFor('TIMER')).toEqual(['s5time', 'dec']);
    expect(formatsFor('COUNTER')).toEqual(['counter', 'dec']);
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
    expect(formatValue(2000, 'S5TIME', 's5time')).toBe('S5T#2S');
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

describe('symbols of the sources', () => {
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
});

describe('S5TIME and counters, as STEP 7 shows timer and counter words', () => {
  it('shows a timer as S5T# and a counter as C#', () => {
    expect(formatValue(1850, 'TIMER', 's5time')).toBe('S5T#1S850MS');
    expect(formatValue(0, 'TIMER', 's5time')).toBe('S5T#0MS');
    expect(formatValue(9_990_000, 'TIMER', 's5time')).toBe('S5T#2H46M30S');
    expect(formatValue(1850, 'TIMER', 'dec')).toBe('1850');
    expect(formatValue(5, 'COUNTER', 'counter')).toBe('C#5');
    expect(formatValue(999, 'COUNTER', 'dec')).toBe('999');
    expect(formatS5Time(61_010)).toBe('S5T#1M1S10MS');
  });

  it('reads a timer word as time base and three BCD digits, a counter word as BCD', () => {
    // base 00 (10 ms) x 185 = 1.85 s; base 10 (1 s) x 123; base 11 (10 s) x 999
    expect(formatValue(0x0185, 'WORD', 's5time')).toBe('S5T#1S850MS');
    expect(formatValue(0x2123, 'WORD', 's5time')).toBe('S5T#2M3S');
    expect(formatValue(0x3999, 'WORD', 's5time')).toBe('S5T#2H46M30S');
    expect(s5TimeOfWord(0x1010)).toBe(1000);
    expect(formatValue(0x001a, 'WORD', 's5time')).toBe('W#16#001A'); // no BCD: shown raw
    expect(formatValue(0x0025, 'WORD', 'counter')).toBe('C#25');
    expect(formatValue(0x1025, 'WORD', 'counter')).toBe('W#16#1025');
    expect(countOfWord(0x0999)).toBe(999);
  });

  it('parses modify values typed in those formats into the words the CPU stores', () => {
    expect(parseS5Time('S5T#1S850MS')).toBe(1850);
    expect(parseS5Time('s5time#1s_850ms')).toBe(1850);
    expect(parseS5Time('S5T#2H46M30S')).toBe(9_990_000);
    expect(parseS5Time('S5T#2H46M31S')).toBeNull(); // longer than 999 x 10 s
    expect(parseS5Time('S5T#1X')).toBeNull();
    expect(parseCount('C#5')).toBe(5);
    expect(parseCount('C#1000')).toBeNull();
    expect(wordOfS5Time(1850)).toBe(0x0185);
    expect(wordOfS5Time(12_340)).toBe(0x1123); // 100 ms base: 12.3 s, the 40 ms dropped
    expect(wordOfS5Time(9_990_000)).toBe(0x3999);
    expect(wordOfCount(25)).toBe(0x0025);
    expect(modifyValueFor('S5T#1S850MS', 'WORD', 's5time')).toBe(0x0185);
    expect(modifyValueFor('C#25', 'WORD', 'counter')).toBe(0x0025);
    expect(modifyValueFor('S5T#2S', 'S5TIME', 's5time')).toBe('S5T#2S'); // the server encodes it
    expect(modifyValueFor('C#1000', 'WORD', 'counter')).toBeNull();
    expect(modifyValueFor('S5T#9H', 'WORD', 's5time')).toBeNull();
    expect(modifyValueFor('12', 'WORD', 'counter')).toBe(12);
    for (const word of [0x0000, 0x0185, 0x1999, 0x2123, 0x3999]) { // each in its smallest base
      expect(wordOfS5Time(parseS5Time(formatValue(word, 'WORD', 's5time'))!)).toBe(word);
    }
  });
});
