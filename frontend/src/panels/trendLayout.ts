/**
 * How the trend lays its entries out, as a logic analyser and a recorder together: every BOOL
 * gets a lane of its own (0/1, stacked under each other with its name, sharing the time axis),
 * and the other entries share one y-axis per unit (integer words, REAL, times), so a counter
 * and a level in % never squeeze each other flat. Values are written as the watch table writes
 * them (its display formats, REAL to seven significant digits).
 */
import type uPlot from 'uplot';
import type { TrendSample } from '../api/monitor';
import { defaultFormat, formatValue, numericValue, type DisplayFormat } from './watchFormat';

export type TrendUnit = 'int' | 'real' | 'time';

export interface TrendAxis {
  unit: TrendUnit;
  /** The entries (indices) drawn against this axis. */
  series: number[];
}

export interface TrendLayout {
  /** The BOOL entries (indices), the first one in the top lane. */
  lanes: number[];
  /** One axis per unit, in the order the units first appear. */
  axes: TrendAxis[];
}

const TIME_TYPES = new Set(['TIME', 'S5TIME', 'TIME_OF_DAY', 'TOD']);

/** The unit a type is plotted in; `bool` gets a lane. */
export function unitOf(type: string | undefined): 'bool' | TrendUnit {
  const kind = (type ?? '').toUpperCase();
  if (kind === 'BOOL') return 'bool';
  if (kind === 'REAL') return 'real';
  if (TIME_TYPES.has(kind)) return 'time';
  return 'int';
}

export function trendLayout(types: readonly string[]): TrendLayout {
  const lanes: number[] = [];
  const axes: TrendAxis[] = [];
  types.forEach((type, index) => {
    const unit = unitOf(type);
    if (unit === 'bool') {
      lanes.push(index);
      return;
    }
    const axis = axes.find((item) => item.unit === unit);
    if (axis) axis.series.push(index);
    else axes.push({ unit, series: [index] });
  });
  return { lanes, axes };
}

/** A lane's height in value units: 1 for the signal, the rest a gap to the next lane. */
export const LANE_STEP = 1.5;
/** Pixels a lane gets when the plot also has axes for words or REALs. */
export const LANE_PX = 30;

/** The lanes' scale value of a BOOL `value` in lane `lane` of `count` (lane 0 at the top). */
export function laneValue(value: number | null, lane: number, count: number): number | null {
  return value === null ? null : (count - 1 - lane) * LANE_STEP + value;
}

/** Where lane `lane`'s name sits on the lanes' scale: the middle of its 0…1. */
export function laneCentre(lane: number, count: number): number {
  return (count - 1 - lane) * LANE_STEP + 0.5;
}

/** The share of the plot's height the lanes take: all of it without axes, else ~30 px each. */
export function lanesShare(laneCount: number, plotHeight: number, axisCount: number): number {
  if (laneCount === 0) return 0;
  if (axisCount === 0) return 1;
  return Math.min(0.65, Math.max(0.2, (laneCount * LANE_PX) / Math.max(1, plotHeight)));
}

/** The lanes' scale: the lanes fill the bottom `share` of the plot (the axes' data the rest). */
export function lanesRange(count: number, share: number): [number, number] {
  const bottom = -0.25;
  const top = (count - 1) * LANE_STEP + 1.25;
  if (share >= 1) return [bottom, top];
  return [bottom, bottom + (top - bottom) / share];
}

/**
 * An axis' scale for data from `min` to `max` drawn above lanes that take the bottom `share`:
 * padded by a tenth, then stretched downwards so that the data stay clear of the lanes.
 * Returns the scale's range and the lowest value the axis labels (about the data's lowest).
 */
export function axisRange(min: number | null, max: number | null, share: number): { range: [number, number]; floor: number } {
  // Without data (or with none in view) uPlot gives ±Infinity: a range of 0…1 then.
  const known = min !== null && max !== null && Number.isFinite(min) && Number.isFinite(max) && min <= max;
  let low = known ? min : 0;
  let high = known ? max : 1;
  if (high - low < 1e-9) {
    const pad = Math.max(1, Math.abs(high) * 0.1);
    low -= pad;
    high += pad;
  } else {
    const pad = (high - low) * 0.1;
    low -= pad;
    high += pad;
  }
  // The axis labels the data's span only, not the room stretched down for the lanes.
  const floor = known ? Math.min(min, low + (high - low) * 0.05) : low;
  if (share <= 0) return { range: [low, high], floor: low };
  const gap = Math.min(0.9, share + 0.04);
  return { range: [low - ((high - low) * gap) / (1 - gap), high], floor };
}

/** uPlot's columns: the simulated time in seconds, then one column per entry (BOOLs in lanes). */
export function trendColumns(samples: readonly TrendSample[], types: readonly string[], layout: TrendLayout): uPlot.AlignedData {
  const laneOf = new Map(layout.lanes.map((entry, lane) => [entry, lane]));
  const count = layout.lanes.length;
  const x = samples.map((sample) => sample.time_ms / 1000);
  const ys = types.map((_, index) => {
    const lane = laneOf.get(index);
    return samples.map((sample) => {
      const value = numericValue(sample.values[index]);
      return lane === undefined ? value : laneValue(value, lane, count);
    });
  });
  return [x, ...ys];
}

/** A sampled value as the watch table shows it (its format; REAL rounded to 7 digits). */
export function trendValueText(
  value: boolean | number | string | null | undefined,
  type: string | undefined,
  format: DisplayFormat = defaultFormat(type),
): string {
  if (value === null || value === undefined) return '';
  return formatValue(value, type, format);
}

/** An axis tick: integers without decimals, REALs to 7 significant digits, times in ms. */
export function tickText(value: number, unit: TrendUnit): string {
  if (unit === 'real') return String(Number(value.toPrecision(7)));
  return String(Math.round(value));
}
