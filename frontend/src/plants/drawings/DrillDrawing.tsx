import { Caption, FaultMark, Lamp, Motor, PlantSvg, SignalLabel, bit, clamp01, hasFault, stateNumber, type DrawingProps } from '../parts';

/** P07: a drilling unit: the spindle feeds down to the depth limit and back to home, with a clamp and coolant. */
export function DrillDrawing({ plant }: DrawingProps) {
  const position = clamp01(stateNumber(plant, ['depth_pct'], bit(plant, 'depth') ? 100 : 0) / 100);
  const head = 40 + position * 90;
  const spinning = bit(plant, 'motor');
  const broken = hasFault(plant, 'broken_bit');
  return (
    <PlantSvg width={460} height={240} plant={plant}>
      <rect x={40} y={20} width={14} height={200} className="plant-post" />
      <g data-testid="plant-spindle" data-position={position.toFixed(3)}>
        <rect x={54} y={head} width={110} height={40} rx={4} className="plant-head" />
        <Motor x={109} y={head + 20} r={14} running={spinning} timeMs={plant.time_ms} testId="plant-drill-motor" />
        <line x1={150} y1={head + 40} x2={150} y2={head + 76} className={broken ? 'plant-bit plant-bit--broken' : 'plant-bit'} />
        {broken ? <FaultMark x={150} y={head + 60} size={8} /> : null}
      </g>
      <rect x={110} y={190} width={90} height={20} className={bit(plant, 'clamp') ? 'plant-work plant-work--clamped' : 'plant-work'} data-testid="plant-workpiece" />
      <SignalLabel plant={plant} name="motor" x={170} y={head + 14} at="right" />
      <SignalLabel plant={plant} name="feed_down" x={250} y={30} at="right" />
      <Lamp plant={plant} name="feed_down" x={240} y={30} colour="blue" r={5} label="none" />
      <SignalLabel plant={plant} name="feed_up" x={250} y={62} at="right" />
      <Lamp plant={plant} name="feed_up" x={240} y={62} colour="blue" r={5} label="none" />
      <Lamp plant={plant} name="home" x={20} y={45} colour="yellow" r={6} label="none" />
      <Lamp plant={plant} name="depth" x={20} y={170} colour="yellow" r={6} label="none" />
      <SignalLabel plant={plant} name="home" x={60} y={26} at="right" />
      <SignalLabel plant={plant} name="depth" x={60} y={226} at="right" />
      <Lamp plant={plant} name="clamp" x={250} y={110} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="clamp_ok" x={250} y={145} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="coolant" x={360} y={110} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="coolant_ok" x={360} y={145} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="motor_running" x={250} y={185} colour="yellow" r={6} label="right" />
      {bit(plant, 'coolant') ? <path d={`M 160 ${head + 40} q 0 20 -6 36`} className="plant-coolant" /> : null}
      <Caption x={360} y={200} testId="plant-holes">{`⊙ ${stateNumber(plant, ['holes'])}`}</Caption>
    </PlantSvg>
  );
}
