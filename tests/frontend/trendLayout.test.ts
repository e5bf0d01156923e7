import { describe, expect, it } from 'vitest';
import {
  axisRange,
  laneCentre,
  lanesRange,
  lanesShare,
  laneValue,
  tickText,
  trendColumns,
  trendLayout,
  trendValueText,
  unitOf,
} from '../../frontend/src/panels/trendLayout';
import { formatValue } from '../../frontend/src/panels/watchFormat';

describe('trend layout', () => {
  it('gives every BOOL a lane and the other entries one axis per unit', () => {
    const layout = trendLayout(['BOOL', 'INT', 'REAL', 'BOOL', 'WORD', 'TIME', 'S5TIME', 'DINT', 'REAL']);
    expect(layout.lanes).toEqual([0, 3]);
    expect(layout.axes).toEqual([
      { unit: 'int', series: [1, 4, 7] },
      { unit: 'real', series: [2, 8] },
      { unit: 'time', series: [5, 6] },
    ]);
  });

  it('sorts the types into units as the watch table types them', () => {
    expect(['BOOL', 'bool', 'BYTE', 'CHAR', 'DWORD', 'REAL', 'TOD', 'TIME_OF_DAY', 'S5TIME', 'DATE'].map(unitOf)).toEqual([
      'bool',
      'bool',
      'int',
      'int',
      'int',
      'real',
      'time',
      'time',
      'time',
      'int',
    ]);
  });

  it('has only lanes for BOOLs alone and only axes without BOOLs', () => {
    expect(trendLayout(['BOOL', 'BOOL'])).toEqual({ lanes: [0, 1], axes: [] });
    expect(trendLayout(['INT', 'INT'])).toEqual({ lanes: [], axes: [{ unit: 'int', series: [0, 1] }] });
  });

  it('stacks the lanes top down in entry order, apart from each other', () => {
    const layout = trendLayout(['BOOL', 'INT', 'BOOL']);
    const data = trendColumns(
      [
        { scan: 1, time_ms: 10, values: [true, 5, false] },
        { scan: 2, time_ms: 20, values: [false, -3, true] },
        { scan: 3, time_ms: 30, values: [null, null, true] },
      ],
      ['BOOL', 'INT', 'BOOL'],
      layout,
    );
    expect(data[0]).toEqual([0.01, 0.02, 0.03]);
    // The first BOOL in the upper lane (base 1.5), the second in the lower one (base 0).
    expect(data[1]).toEqual([2.5, 1.5, null]);
    expect(data[2]).toEqual([5, -3, null]);
    expect(data[3]).toEqual([0, 1, 1]);
    expect(laneValue(1, 0, 2)).toBe(2.5);
    expect(laneCentre(0, 2)).toBe(2);
    expect(laneCentre(1, 2)).toBe(0.5);
  });

  it('keeps the lanes under the axes’ data, the whole plot when there are no axes', () => {
    expect(lanesShare(2, 300, 0)).toBe(1);
    expect(lanesShare(0, 300, 1)).toBe(0);
    expect(lanesShare(2, 300, 1)).toBeCloseTo(0.2);
    expect(lanesShare(20, 300, 1)).toBe(0.65);
    expect(lanesRange(2, 1)).toEqual([-0.25, 2.75]);
    const [low, high] = lanesRange(2, 0.5);
    // The lanes (−0.25 … 2.75) take the bottom half of the scale.
    expect((2.75 - low) / (high - low)).toBeCloseTo(0.5);
    const { range, floor } = axisRange(0, 100, 0.5);
    // Labels from the data's lowest value up; no labels in the lanes' part.
    expect(floor).toBe(-4);
    expect(range[1]).toBe(110);
    // The data (with their padding) take the top part above the lanes and a small gap.
    expect((range[1] - -10) / (range[1] - range[0])).toBeCloseTo(1 - 0.54);
    expect(axisRange(0, 100, 0)).toEqual({ range: [-10, 110], floor: -10 });
    expect(axisRange(7, 7, 0).range).toEqual([6, 8]);
    expect(axisRange(null, null, 0).range).toEqual([-0.1, 1.1]);
    expect(axisRange(Infinity, -Infinity, 0.3).range.every(Number.isFinite)).toBe(true);
  });

  it('writes values as the watch table does: REALs rounded to 7 digits, BOOLs, words, times', () => {
    expect(trendValueText(42.400001525878906, 'REAL')).toBe('42.4');
    expect(trendValueText(0.30000001192092896, 'REAL')).toBe('0.3');
    expect(trendValueText(true, 'BOOL')).toBe('TRUE');
    expect(trendValueText(-5, 'INT')).toBe('-5');
    expect(trendValueText(255, 'WORD')).toBe('W#16#00FF');
    // Times exactly as the watch table writes them (its module owns the notation).
    expect(trendValueText(1850, 'S5TIME')).toBe(formatValue(1850, 'S5TIME', 'time'));
    expect(trendValueText(1850, 'S5TIME')).toMatch(/^S5T#1S_?850MS$/);
    expect(trendValueText(2500, 'TIME')).toBe(formatValue(2500, 'TIME', 'time'));
    expect(trendValueText(255, 'WORD', 'dec')).toBe('255');
    expect(trendValueText(null, 'REAL')).toBe('');
    expect(tickText(0.1 + 0.2, 'real')).toBe('0.3');
    expect(tickText(2.0000001, 'int')).toBe('2');
  });
});
