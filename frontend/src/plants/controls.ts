/**
 * How the operator panel shows each control. A control is a push button (momentary: pressed
 * while the pointer or the Space key holds it, as on a real panel) unless it is listed here as
 * a switch (it stays where it was turned) or a thumbwheel (a BCD word set digit by digit).
 * The model itself only keeps the value it was given (backend/nasaq/plants/base.py).
 */
import type { PlantInfo, PlantSignalInfo } from './types';

const SWITCHES: Readonly<Record<string, readonly string[]>> = {
  tank: ['auto'],
  traffic_light: ['run'],
  door: ['outside', 'inside'],
};

export type ControlStyle = 'button' | 'switch' | 'thumbwheel' | 'number';

export function controlStyle(kind: string, signal: PlantSignalInfo): ControlStyle {
  if (signal.kind === 'word') return kind === 'bcd_panel' ? 'thumbwheel' : 'number';
  return SWITCHES[kind]?.includes(signal.name) ? 'switch' : 'button';
}

/** The value a control has while nobody touches it (an NC contact reads 1). */
export function restValue(signal: PlantSignalInfo): number {
  return signal.normally_closed ? 1 : 0;
}

/** The value a push button sends while it is pressed (an NC stop button opens: 0). */
export function pressedValue(signal: PlantSignalInfo): number {
  return signal.normally_closed ? 0 : 1;
}

export function controlsOf(info: PlantInfo): PlantSignalInfo[] {
  return info.signals.filter((signal) => signal.direction === 'control');
}

/** A BCD word from four decimal digits, thousands first. */
export function bcdWord(digits: readonly number[]): number {
  return digits.reduce((value, digit) => (value << 4) | (Math.min(9, Math.max(0, digit)) & 0xf), 0);
}

/** The four BCD digits of a word (a nibble above 9 shows as 0 on the wheels). */
export function bcdWheels(value: number): number[] {
  return [12, 8, 4, 0].map((shift) => {
    const nibble = ((value & 0xffff) >> shift) & 0xf;
    return nibble > 9 ? 0 : nibble;
  });
}
