import { Lamp, PlantSvg, SignalLabel, bit, stateFlag, type DrawingProps } from '../parts';

/** P01: the training panel: push buttons S1..S5, contactor K1 with its auxiliary contact, lamps H1..H4. */
export function PanelDrawing({ plant }: DrawingProps) {
  const buttons = ['s1', 's2', 's3', 's4', 's5'];
  const k1 = bit(plant, 'k1');
  return (
    <PlantSvg width={460} height={200} plant={plant}>
      <rect x={10} y={10} width={440} height={180} rx={8} className="plant-panel" />
      {buttons.map((name, index) => {
        const pressed = stateFlag(plant, [`${name}_pressed`], bit(plant, name));
        return (
          <g key={name} data-testid={`plant-button-${name}`} data-on={pressed ? '1' : '0'}>
            <circle cx={50 + index * 80} cy={50} r={14} className={pressed ? 'plant-button plant-button--pressed' : 'plant-button'} />
            <SignalLabel plant={plant} name={name} x={50 + index * 80} y={50} r={14} />
          </g>
        );
      })}
      <g data-testid="plant-contactor" data-on={k1 ? '1' : '0'}>
        <rect x={30} y={120} width={50} height={34} rx={3} className={k1 ? 'plant-coil plant-coil--on' : 'plant-coil'} />
        <SignalLabel plant={plant} name="k1" x={55} y={137} r={26} at="right" />
      </g>
      <Lamp plant={plant} name="k1_aux" x={170} y={137} colour="yellow" r={6} />
      <Lamp plant={plant} name="h1" x={250} y={137} colour="green" r={11} />
      <Lamp plant={plant} name="h2" x={310} y={137} colour="red" r={11} />
      <Lamp plant={plant} name="h3" x={370} y={137} colour="yellow" r={11} />
      <Lamp plant={plant} name="h4" x={430} y={137} colour="white" r={11} />
    </PlantSvg>
  );
}
