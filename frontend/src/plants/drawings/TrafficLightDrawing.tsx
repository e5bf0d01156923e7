import { Lamp, PlantSvg, SignalLabel, type DrawingProps } from '../parts';
import type { PlantFrame } from '../types';

function Head({ plant, x, lamps }: { plant: PlantFrame; x: number; lamps: Array<[string, 'red' | 'yellow' | 'green']> }) {
  return (
    <g>
      <rect x={x - 16} y={22} width={32} height={lamps.length * 40 + 8} rx={6} className="plant-head" />
      {lamps.map(([name, colour], index) => (
        <Lamp key={name} plant={plant} name={name} x={x} y={46 + index * 40} colour={colour} r={12} label="right" />
      ))}
    </g>
  );
}

/** P06: a crossing with two directions and a pedestrian light with its request button. */
export function TrafficLightDrawing({ plant }: DrawingProps) {
  return (
    <PlantSvg width={460} height={200} plant={plant}>
      <Head plant={plant} x={40} lamps={[['red1', 'red'], ['yellow1', 'yellow'], ['green1', 'green']]} />
      <Head plant={plant} x={190} lamps={[['red2', 'red'], ['yellow2', 'yellow'], ['green2', 'green']]} />
      <Head plant={plant} x={340} lamps={[['ped_red', 'red'], ['ped_green', 'green']]} />
      <Lamp plant={plant} name="ped" x={340} y={150} colour="white" r={7} label="right" />
      <SignalLabel plant={plant} name="run" x={40} y={178} at="right" />
    </PlantSvg>
  );
}
