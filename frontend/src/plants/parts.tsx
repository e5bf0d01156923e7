/**
 * The drawing primitives every plant drawing is built from: lamps, sensors with their address,
 * motors, valves, pipes, photo-eyes, belts and gauges. Everything is driven by the frame alone
 * (no wall clock): what moves (a rotor, a belt, water in a pipe) moves by the plant's virtual
 * time, so a paused CPU shows a still picture and two browsers show the same one.
 */
import type { ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import type { PlantFrame } from './types';

export interface DrawingProps {
  plant: PlantFrame;
  /** The plant's parameters (the catalogue's defaults with the project's own values over them). */
  params?: Readonly<Record<string, number>> | undefined;
}

/** A parameter of the drawn plant (its size, a switch's place), or `fallback` when unknown. */
export function param(params: DrawingProps['params'], name: string, fallback: number): number {
  const value = params?.[name];
  return typeof value === 'number' && Number.isFinite(value) ? value : fallback;
}

/** A bool signal's value (0 when the frame does not carry it). */
export function bit(plant: PlantFrame, name: string): boolean {
  return (plant.signals[name] ?? 0) !== 0;
}

/** A word signal's value as a number (0 when absent). */
export function word(plant: PlantFrame, name: string): number {
  return Number(plant.signals[name] ?? 0);
}

/** The first of `names` the plant's state holds as a number, else `fallback`. */
export function stateNumber(plant: PlantFrame, names: readonly string[], fallback = 0): number {
  for (const name of names) {
    const value = plant.state[name];
    if (typeof value === 'number' && Number.isFinite(value)) return value;
    if (typeof value === 'boolean') return value ? 1 : 0;
  }
  return fallback;
}

/** The first of `names` the plant's state holds as a boolean (a number counts as 0/1). */
export function stateFlag(plant: PlantFrame, names: readonly string[], fallback = false): boolean {
  for (const name of names) {
    const value = plant.state[name];
    if (typeof value === 'boolean') return value;
    if (typeof value === 'number') return value !== 0;
  }
  return fallback;
}

export const clamp01 = (value: number) => (Number.isFinite(value) ? Math.min(1, Math.max(0, value)) : 0);

/** 0..27648 (an S7 analog channel's rated range) as 0..1. */
export const analog = (value: number) => clamp01(value / 27648);

export function hasFault(plant: PlantFrame, code: string): boolean {
  return plant.faults.includes(code);
}

/** The translated name of a signal (its own name when no text exists). */
export function useSignalName(): (name: string) => string {
  const { t } = useTranslation();
  // Push buttons and lamps named like S1 or H3 on the wiring diagram keep that name in every language.
  return (name) => (/^[a-z]\d$/.test(name) ? name.toUpperCase() : t(`plants.signal.${name}`, { defaultValue: name.replace(/_/g, ' ') }));
}

/** A fault's message: the plant's own wording where the shared one would not fit, else the shared one. */
export function useFaultText(): (kind: string, code: string, fallback?: string) => string {
  const { t } = useTranslation();
  return (kind, code, fallback) => t([`plants.faultOf.${kind}.${code}`, `plants.fault.${code}`], { defaultValue: fallback || code });
}

/** The address a signal is wired to, or a dash when it is not connected. */
export function addressOf(plant: PlantFrame, name: string): string {
  return plant.wiring[name] ?? '—';
}

interface SvgProps {
  width: number;
  height: number;
  plant: PlantFrame;
  children: ReactNode;
}

/** The drawing's canvas: always left to right, named for screen readers, red-framed on a fault. */
export function PlantSvg({ width, height, plant, children }: SvgProps) {
  const { t } = useTranslation();
  const faulted = plant.faults.length > 0;
  return (
    <svg
      className={faulted ? 'plant-svg plant-svg--fault' : 'plant-svg'}
      viewBox={`0 0 ${width} ${height}`}
      role="img"
      aria-label={t(`plants.kind.${plant.kind}`, { defaultValue: plant.kind })}
      direction="ltr"
      data-testid={`plant-drawing-${plant.kind}`}
    >
      <rect className="plant-svg__frame" x={1} y={1} width={width - 2} height={height - 2} rx={6} />
      {children}
    </svg>
  );
}

export type LampColour = 'green' | 'red' | 'yellow' | 'white' | 'blue';

interface LampProps {
  plant: PlantFrame;
  /** The signal this lamp shows. */
  name: string;
  x: number;
  y: number;
  colour?: LampColour;
  /** Lit or not; by default the signal's value. */
  on?: boolean;
  r?: number;
  /** Where the name and address go. */
  label?: 'below' | 'right' | 'left' | 'above' | 'none';
}

/** A pilot lamp (or a sensor's LED) with the signal's name and address. */
export function Lamp({ plant, name, x, y, colour = 'green', on, r = 8, label = 'below' }: LampProps) {
  const lit = on ?? bit(plant, name);
  return (
    <g className="plant-lamp" data-testid={`plant-lamp-${name}`} data-on={lit ? '1' : '0'}>
      <circle className={lit ? `plant-lamp__glass plant-lamp--${colour}` : 'plant-lamp__glass'} cx={x} cy={y} r={r} />
      {lit ? <circle className={`plant-lamp__halo plant-lamp--${colour}`} cx={x} cy={y} r={r + 4} /> : null}
      {label === 'none' ? null : <SignalLabel plant={plant} name={name} x={x} y={y} r={r} at={label} />}
    </g>
  );
}

interface SignalLabelProps {
  plant: PlantFrame;
  name: string;
  x: number;
  y: number;
  r?: number;
  at?: 'below' | 'right' | 'left' | 'above';
}

/** A signal's name and, under it, its address (monospace). */
export function SignalLabel({ plant, name, x, y, r = 0, at = 'below' }: SignalLabelProps) {
  const signalName = useSignalName();
  const anchor = at === 'right' ? 'start' : at === 'left' ? 'end' : 'middle';
  const tx = at === 'right' ? x + r + 5 : at === 'left' ? x - r - 5 : x;
  const ty = at === 'below' ? y + r + 11 : at === 'above' ? y - r - 16 : y - 1;
  return (
    <g className="plant-label">
      <text x={tx} y={ty} textAnchor={anchor} className="plant-label__name">
        {signalName(name)}
      </text>
      <text x={tx} y={ty + 10} textAnchor={anchor} className="plant-label__address" data-testid={`plant-address-${name}`}>
        {addressOf(plant, name)}
      </text>
    </g>
  );
}

interface MotorProps {
  x: number;
  y: number;
  r?: number;
  running: boolean;
  /** Rotor turns per second at full speed (0..1 scales it). */
  speed?: number;
  timeMs: number;
  faulted?: boolean;
  testId?: string;
}

/** A motor: a circle with an "M" and a rotor whose angle follows the plant's time and speed. */
export function Motor({ x, y, r = 18, running, speed = 1, timeMs, faulted = false, testId }: MotorProps) {
  const angle = running ? ((timeMs / 1000) * 360 * 1.5 * clamp01(speed)) % 360 : 0;
  const className = `plant-motor${running ? ' plant-motor--on' : ''}${faulted ? ' plant-motor--fault' : ''}`;
  return (
    <g className={className} data-testid={testId} data-running={running ? '1' : '0'}>
      <circle cx={x} cy={y} r={r} className="plant-motor__body" />
      <g transform={`rotate(${angle.toFixed(1)} ${x} ${y})`} className="plant-motor__rotor">
        <line x1={x - r + 4} y1={y} x2={x + r - 4} y2={y} />
        <line x1={x} y1={y - r + 4} x2={x} y2={y + r - 4} />
      </g>
      <text x={x} y={y + 4} textAnchor="middle" className="plant-motor__m">
        M
      </text>
    </g>
  );
}

/** A solenoid valve: two triangles point to point, filled when open. */
export function Valve({ x, y, open, vertical = false, testId }: { x: number; y: number; open: boolean; vertical?: boolean; testId?: string }) {
  const s = 8;
  const points = vertical
    ? `${x - s},${y - s} ${x + s},${y - s} ${x - s},${y + s} ${x + s},${y + s}`
    : `${x - s},${y - s} ${x - s},${y + s} ${x + s},${y - s} ${x + s},${y + s}`;
  return (
    <g className={open ? 'plant-valve plant-valve--open' : 'plant-valve'} data-testid={testId} data-open={open ? '1' : '0'}>
      <polygon points={points} />
      <line x1={x} y1={y} x2={vertical ? x + 14 : x} y2={vertical ? y : y - 14} />
      <rect x={vertical ? x + 14 : x - 5} y={vertical ? y - 5 : y - 22} width={10} height={10} />
    </g>
  );
}

/** A pipe; liquid in it moves along by the plant's time while it flows. */
export function Pipe({ d, flowing, timeMs }: { d: string; flowing: boolean; timeMs: number }) {
  return (
    <g className="plant-pipe">
      <path d={d} className="plant-pipe__wall" />
      {flowing ? <path d={d} className="plant-pipe__flow" strokeDashoffset={-((timeMs / 25) % 24)} /> : null}
    </g>
  );
}

/** A photo-eye across a path: emitter, beam, receiver; the beam turns red while interrupted. */
export function PhotoEye({ plant, name, x, y1, y2 }: { plant: PlantFrame; name: string; x: number; y1: number; y2: number }) {
  const sees = bit(plant, name);
  return (
    <g className={sees ? 'plant-eye plant-eye--on' : 'plant-eye'} data-testid={`plant-eye-${name}`} data-on={sees ? '1' : '0'}>
      <rect x={x - 5} y={y1 - 10} width={10} height={8} className="plant-eye__box" />
      <line x1={x} y1={y1 - 2} x2={x} y2={y2} className="plant-eye__beam" />
      <rect x={x - 5} y={y2} width={10} height={8} className="plant-eye__box" />
      <Lamp plant={plant} name={name} x={x} y={y1 - 22} r={5} colour="yellow" label="above" />
    </g>
  );
}

/** A conveyor belt: rollers and cleats that move by the plant's time while it runs. */
export function Belt({ x, y, width, running, timeMs, testId }: { x: number; y: number; width: number; running: boolean; timeMs: number; testId?: string }) {
  const shift = running ? (timeMs / 40) % 20 : 0;
  const cleats: number[] = [];
  for (let cx = x + 10 + shift; cx < x + width - 6; cx += 20) cleats.push(cx);
  return (
    <g className={running ? 'plant-belt plant-belt--on' : 'plant-belt'} data-testid={testId} data-running={running ? '1' : '0'}>
      <rect x={x} y={y} width={width} height={12} rx={6} className="plant-belt__band" />
      {cleats.map((cx) => (
        <line key={cx.toFixed(1)} x1={cx} y1={y + 2} x2={cx} y2={y + 10} className="plant-belt__cleat" />
      ))}
      <circle cx={x + 6} cy={y + 6} r={4} className="plant-belt__roller" />
      <circle cx={x + width - 6} cy={y + 6} r={4} className="plant-belt__roller" />
    </g>
  );
}

/** A bar gauge (0..1 of its height) with a caption. */
export function Gauge({ x, y, width = 14, height, value, caption, fault = false, testId }: { x: number; y: number; width?: number; height: number; value: number; caption: string; fault?: boolean; testId?: string }) {
  const filled = clamp01(value) * height;
  return (
    <g className={fault ? 'plant-gauge plant-gauge--fault' : 'plant-gauge'} data-testid={testId} data-value={value.toFixed(3)}>
      <rect x={x} y={y} width={width} height={height} className="plant-gauge__frame" />
      <rect x={x} y={y + height - filled} width={width} height={filled} className="plant-gauge__fill" />
      <text x={x + width / 2} y={y + height + 12} textAnchor="middle" className="plant-label__address">
        {caption}
      </text>
    </g>
  );
}

/** A caption in the drawing (a count, a temperature), in the drawing's own font. */
export function Caption({ x, y, children, anchor = 'middle', strong = false, testId }: { x: number; y: number; children: ReactNode; anchor?: 'start' | 'middle' | 'end'; strong?: boolean; testId?: string }) {
  return (
    <text x={x} y={y} textAnchor={anchor} className={strong ? 'plant-caption plant-caption--strong' : 'plant-caption'} data-testid={testId}>
      {children}
    </text>
  );
}

/** A red cross over a part that failed (a burnt motor, a broken bit). */
export function FaultMark({ x, y, size = 14 }: { x: number; y: number; size?: number }) {
  return (
    <g className="plant-fault-mark">
      <line x1={x - size} y1={y - size} x2={x + size} y2={y + size} />
      <line x1={x - size} y1={y + size} x2={x + size} y2={y - size} />
    </g>
  );
}
