import { useId } from 'react';
import { Caption, FaultMark, Gauge, Lamp, PlantSvg, SignalLabel, analog, bit, clamp01, hasFault, param, stateNumber, word, type DrawingProps } from '../parts';
import { Cylinder, Rail, axisPosition } from './axis';

/** P14: a shuttle between two limit switches, driven right or left. */
export function ShuttleDrawing({ plant, params }: DrawingProps) {
  const position = axisPosition(plant, ['position'], 'ls1', 'ls2', param(params, 'travel', 1000));
  return (
    <PlantSvg width={460} height={170} plant={plant}>
      <Rail plant={plant} x={60} y={60} length={340} position={position} startSwitch="ls1" endSwitch="ls2" testId="plant-shuttle" />
      {hasFault(plant, 'overtravel') ? <FaultMark x={60 + position * 340} y={60} /> : null}
      <Lamp plant={plant} name="left" x={160} y={140} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="right" x={300} y={140} colour="blue" r={6} label="right" />
    </PlantSvg>
  );
}

/** P11: a hangar door driven open and closed between its limit switches, with truck sensors outside and inside. */
export function DoorDrawing({ plant }: DrawingProps) {
  const open = axisPosition(plant, ['position'], 'ls_closed', 'ls_open');
  const doorTop = 30;
  const height = 120 * (1 - open);
  return (
    <PlantSvg width={460} height={220} plant={plant}>
      <rect x={150} y={20} width={160} height={10} className="plant-post" />
      <rect x={150} y={30} width={8} height={130} className="plant-post" />
      <rect x={302} y={30} width={8} height={130} className="plant-post" />
      <rect x={158} y={doorTop} width={144} height={height} className="plant-door" data-testid="plant-door" data-position={open.toFixed(3)} />
      {hasFault(plant, 'crush') ? <FaultMark x={230} y={doorTop + height} /> : null}
      <line x1={20} y1={160} x2={440} y2={160} className="plant-rail" />
      <Lamp plant={plant} name="ls_open" x={340} y={30} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="ls_closed" x={340} y={150} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="outside" x={60} y={140} colour="white" r={6} />
      <Lamp plant={plant} name="inside" x={410} y={110} colour="white" r={6} />
      <Lamp plant={plant} name="pressure_ok" x={60} y={40} colour="green" r={6} />
      <Lamp plant={plant} name="open" x={180} y={190} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="close" x={270} y={190} colour="blue" r={6} label="right" />
    </PlantSvg>
  );
}

/** P12: a double-acting cylinder with rest and end switches and a pressure switch. */
export function CylinderDrawing({ plant }: DrawingProps) {
  const position = axisPosition(plant, ['position'], 'rest', 'end');
  return (
    <PlantSvg width={460} height={190} plant={plant}>
      <Cylinder x={60} y={70} length={160} position={position} testId="plant-cylinder" />
      <Lamp plant={plant} name="rest" x={80} y={110} colour="yellow" r={6} />
      <Lamp plant={plant} name="end" x={380} y={110} colour="yellow" r={6} />
      <Lamp plant={plant} name="pressure_ok" x={40} y={30} colour="green" r={6} label="right" />
      <Lamp plant={plant} name="extend" x={120} y={160} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="retract" x={230} y={160} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="lamp" x={350} y={160} colour="green" r={8} label="right" />
    </PlantSvg>
  );
}

/** P22: up to three single-solenoid cylinders with spring return, each with home and end switches. */
export function CylindersDrawing({ plant }: DrawingProps) {
  return (
    <PlantSvg width={460} height={230} plant={plant}>
      {[1, 2, 3].map((n, index) => {
        const y = 40 + index * 65;
        const position = axisPosition(plant, [`c${n}_position`], `c${n}_home`, `c${n}_end`);
        return (
          <g key={n}>
            <Cylinder x={70} y={y} length={130} position={position} testId={`plant-cylinder-${n}`} />
            <Lamp plant={plant} name={`v${n}`} x={30} y={y} colour="blue" r={6} />
            <Lamp plant={plant} name={`c${n}_home`} x={350} y={y - 10} colour="yellow" r={5} label="right" />
            <Lamp plant={plant} name={`c${n}_end`} x={350} y={y + 18} colour="yellow" r={5} label="right" />
          </g>
        );
      })}
    </PlantSvg>
  );
}

/** P16: a servo piston: an analog speed set-point in, an analog position out. */
export function ServoPistonDrawing({ plant, params }: DrawingProps) {
  const position = clamp01(stateNumber(plant, ['position'], analog(word(plant, 'position')) * param(params, 'stroke', 500)) / param(params, 'stroke', 500));
  return (
    <PlantSvg width={460} height={190} plant={plant}>
      <Cylinder x={40} y={70} length={180} position={position} testId="plant-servo" />
      {hasFault(plant, 'end_stop') ? <FaultMark x={420} y={70} /> : null}
      <Gauge x={60} y={120} width={140} height={14} value={position} caption="" testId="plant-gauge-position" />
      <SignalLabel plant={plant} name="position" x={130} y={150} />
      <Caption x={320} y={140}>{`${Math.round(analog(word(plant, 'speed')) * 100)} %`}</Caption>
      <SignalLabel plant={plant} name="speed" x={320} y={150} />
    </PlantSvg>
  );
}

/** P15: a weighing hopper with a discharge gate. */
export function HopperDrawing({ plant, params }: DrawingProps) {
  const kg = stateNumber(plant, ['weight_kg'], (word(plant, 'weight') / 26460) * 100);
  const fill = clamp01(stateNumber(plant, ['flour'], kg) / param(params, 'capacity', 40));
  const clip = `hopper${useId().replace(/[^a-zA-Z0-9_-]/g, '')}`;
  return (
    <PlantSvg width={460} height={230} plant={plant}>
      <clipPath id={clip}>
        <path d="M 150 30 L 310 30 L 310 120 L 250 180 L 210 180 L 150 120 Z" />
      </clipPath>
      <rect x={150} y={180 - fill * 150} width={160} height={fill * 150} className="plant-grain" clipPath={`url(#${clip})`} data-testid="plant-grain" />
      <path d="M 150 20 L 150 120 L 210 180 L 250 180 L 310 120 L 310 20" className={hasFault(plant, 'overflow') ? 'plant-vessel plant-vessel--fault' : 'plant-vessel'} />
      <Caption x={230} y={100} strong testId="plant-weight">{`${kg.toFixed(1)} kg`}</Caption>
      <Lamp plant={plant} name="discharge" x={230} y={205} colour="blue" r={7} label="right" />
      <SignalLabel plant={plant} name="weight" x={380} y={100} />
      {bit(plant, 'discharge') && fill > 0 ? <path d="M 230 185 L 230 220" className="plant-grain-flow" /> : null}
    </PlantSvg>
  );
}
