/** The watch table's formats of the S7-1200/1500 types: 64-bit values exact in every format. */
import { describe, expect, it } from 'vitest';
import {
  defaultFormat,
  formatLongTime,
  formatValue,
  formatsFor,
  numericValue,
  parseModifyValue,
} from '../../frontend/src/panels/watchFormat';

describe('64-bit watch values', () => {
  it('shows an LINT beyond 2**53 exactly in DEC, HEX and BIN', () => {
    expect(formatValue('-9000000000000000000', 'LINT', 'dec')).toBe('-9000000000000000000');
    expect(formatValue('-1', 'LINT', 'hex')).toBe('LW#16#FFFF_FFFF_FFFF_FFFF');
    expect(formatValue(-1, 'LINT', 'dec')).toBe('-1');
    expect(formatValue(40000000000, 'LINT', 'hex')).toBe('LW#16#0000_0009_502F_9000');
    expect(formatValue(5, 'LINT', 'bin')).toBe(`2#${'0000_'.repeat(15)}0101`);
  });

  it('shows ULINT and LWORD unsigned', () => {
    expect(formatValue('18446744073709551615', 'ULINT', 'dec')).toBe('18446744073709551615');
    expect(formatValue('81985529216486895', 'LWORD', 'hex')).toBe('LW#16#0123_4567_89AB_CDEF');
    expect(defaultFormat('LWORD')).toBe('hex');
    expect(defaultFormat('ULINT')).toBe('dec');
  });

  it('shows an LREAL with 15 digits and its IEEE 754 double pattern', () => {
    expect(defaultFormat('LREAL')).toBe('real');
    expect(formatValue(0.1, 'LREAL', 'real')).toBe('0.1');
    expect(formatValue(1 / 3, 'LREAL', 'real')).toBe('0.333333333333333');
    expect(formatValue(-2.25e300, 'LREAL', 'real')).toBe('-2.25e+300');
    expect(formatValue(1.5, 'LREAL', 'hex')).toBe('LW#16#3FF8_0000_0000_0000');
    expect(formatValue('NaN', 'LREAL', 'real')).toBe('NaN');
    expect(formatValue('-Inf', 'LREAL', 'hex')).toBe('LW#16#FFF0_0000_0000_0000');
    expect(formatsFor('LREAL')).toEqual(['real', 'hex', 'bin']);
  });

  it('shows an LTIME as LT# down to nanoseconds', () => {
    expect(defaultFormat('LTIME')).toBe('time');
    expect(formatValue(93_784_005_006_007, 'LTIME', 'time')).toBe('LT#1D_2H_3M_4S_5MS_6US_7NS');
    expect(formatValue(-500_000_000, 'LTIME', 'time')).toBe('LT#-500MS');
    expect(formatValue(0, 'LTIME', 'time')).toBe('LT#0NS');
    expect(formatValue(7, 'LTIME', 'dec')).toBe('7');
    expect(formatLongTime(-(2n ** 63n))).toBe('LT#-106751D_23H_47M_16S_854MS_775US_808NS');
    expect(formatValue('-9223372036854775808', 'LTIME', 'time')).toBe('LT#-106751D_23H_47M_16S_854MS_775US_808NS');
  });

  it('shows SINT signed and USINT, UINT, UDINT unsigned', () => {
    expect(formatValue(-5, 'SINT', 'dec')).toBe('-5');
    expect(formatValue(-5, 'SINT', 'hex')).toBe('B#16#FB');
    expect(formatValue(200, 'USINT', 'dec')).toBe('200');
    expect(formatValue(65535, 'UINT', 'dec')).toBe('65535');
    expect(formatValue(4000000000, 'UDINT', 'dec')).toBe('4000000000');
    expect(formatValue(4000000000, 'UDINT', 'hex')).toBe('DW#16#EE6B2800');
    expect(defaultFormat('UDINT')).toBe('dec');
  });

  it('shows WCHAR and strings as characters', () => {
    expect(formatValue('ش', 'WCHAR', 'char')).toBe("WCHAR#'ش'");
    expect(formatValue('ش', 'WCHAR', 'hex')).toBe('W#16#0634');
    expect(formatValue("it's", 'STRING[8]', 'hex')).toBe("'it''s'");
    expect(formatValue('سلام', 'WSTRING[6]', 'hex')).toBe("'سلام'");
    expect(formatsFor('STRING[8]')).toEqual([]);
  });

  it('sends big integers typed to modify as text, so none is rounded', () => {
    expect(parseModifyValue('9000000000000000001')).toBe('9000000000000000001');
    expect(parseModifyValue('LT#1D2H')).toBe('LT#1D2H');
    expect(parseModifyValue('-2.5e300')).toBe(-2.5e300);
  });

  it('trends a 64-bit integer sent as digits', () => {
    expect(numericValue('9007199254740993')).toBe(9007199254740992);
    expect(numericValue('-12')).toBe(-12);
  });
});
