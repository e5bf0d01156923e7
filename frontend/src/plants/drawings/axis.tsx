import type { ReactNode } from 'react';
import { Lamp, clamp01, stateNumber, bit } from '../parts';
import type { PlantFrame } from '../types';

/**
 * Where a moving part is, 0..1 between its two ends: the model's position divided by `full`
 * (100 for a position in %, the travel for one in mm), else which end switch is made.
 */
export function axisPosition(plant: PlantFrame, names: readonly string[], startSwitch: string, endSwitch: string, full = 100): number {
  const value = stateNumber(plant, names, Number.NaN);
  if (Number.isFinite(value)) return clamp01(value / full);
  if (bit(plant, endSwitch)) return 1;
  if (bit(plant, startSwitch)) return 0;
  return 0.5;
}

interface RailProps {
  plant: PlantFrame;
  x: number;
  y: number;
  length: number;
  position: number;
  startSwitch?: string;
  endSwitch?: string;
  testId: string;
  children?: ReactNode;
}

/** A rail with a carriage at `position` and a limit switch at each end. */
export function Rail({ plant, x, y, length, position, startSwitch, endSwitch, testId, children }: RailProps) {
  const cx = x + position * length;
  return (
    <g>
      <line x1={x - 10} y1={y + 14} x2={x + length + 10} y2={y + 14} className="plant-rail" />
      <g data-testid={testId} data-position={position.toFixed(3)}>
        <rect x={cx - 20} y={y - 12} width={40} height={24} rx={4} className="plant-carriage" />
        {children}
      </g>
      {startSwitch ? <Lamp plant={plant} name={startSwitch} x={x - 20} y={y + 34} colour="yellow" r={6} /> : null}
      {endSwitch ? <Lamp plant={plant} name={endSwitch} x={x + length + 20} y={y + 34} colour="yellow" r={6} /> : null}
    </g>
  );
}

/** A pneumatic cylinder with its rod out by `position` (0 rest .. 1 end). */
export function Cylinder({ x, y, length = 120, position, testId }: { x: number; y: number; length?: number; position: number; testId: string }) {
  const rod = 10 + position * (length - 20);
  return (
    <g data-testid={testId} data-position={position.toFixed(3)}>
      <rect x={x} y={y - 12} width={length} height={24} rx={3} className="plant-cylinder" />
      <rect x={x + 6 + position * (length - 20)} y={y - 10} width={8} height={20} className="plant-piston" />
      <rect x={x + 14 + position * (length - 20)} y={y - 3} width={length - 4} height={6} className="plant-rod" />
      <rect x={x + length + rod - 4} y={y - 9} width={8} height={18} className="plant-piston" />
    </g>
  );
}
