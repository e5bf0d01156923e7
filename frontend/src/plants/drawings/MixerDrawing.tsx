import { Caption, Gauge, Lamp, Motor, PlantSvg, Pipe, SignalLabel, Valve, analog, bit, clamp01, hasFault, stateNumber, word, type DrawingProps } from '../parts';

/** P08+P17: a mixing vessel with a stirrer, a heater and its temperature, filled and drained by valves. */
export function MixerDrawing({ plant }: DrawingProps) {
  const time = plant.time_ms;
  const level = clamp01(stateNumber(plant, ['volume'], bit(plant, 'full') ? 100 : bit(plant, 'empty') ? 0 : 50) / 100);
  const celsius = stateNumber(plant, ['temperature'], (word(plant, 'temperature') / 27648) * 100);
  const heating = bit(plant, 'heater') && !hasFault(plant, 'heater_broken');
  const top = 50;
  const bottom = 200;
  const waterTop = bottom - level * (bottom - top);
  const hot = clamp01(celsius / 100);
  return (
    <PlantSvg width={460} height={250} plant={plant}>
      <Pipe d="M 20 25 L 170 25 L 170 50" flowing={bit(plant, 'fill_valve')} timeMs={time} />
      <Valve x={90} y={25} open={bit(plant, 'fill_valve')} testId="plant-valve-fill_valve" />
      <SignalLabel plant={plant} name="fill_valve" x={90} y={40} />
      <rect x={140} y={waterTop} width={160} height={bottom - waterTop} className="plant-water" style={{ fillOpacity: 0.45 + hot * 0.4 }} data-testid="plant-water" />
      <path d={`M 140 ${top - 6} L 140 ${bottom} L 300 ${bottom} L 300 ${top - 6}`} className="plant-vessel" />
      {/* stirrer */}
      <Motor x={220} y={28} r={14} running={bit(plant, 'stirrer')} timeMs={time} testId="plant-stirrer" />
      <SignalLabel plant={plant} name="stirrer" x={240} y={24} at="right" />
      <line x1={220} y1={42} x2={220} y2={170} className="plant-shaft" />
      <g transform={`translate(220 170) scale(${bit(plant, 'stirrer') ? Math.cos((time / 1000) * 6) : 1} 1)`}>
        <line x1={-30} y1={0} x2={30} y2={0} className="plant-shaft" />
      </g>
      {/* heater coil */}
      <path d="M 150 190 q 10 -12 20 0 t 20 0 t 20 0 t 20 0 t 20 0 t 20 0 t 20 0" className={heating ? 'plant-heater plant-heater--on' : 'plant-heater'} data-testid="plant-heater" data-on={heating ? '1' : '0'} />
      <SignalLabel plant={plant} name="heater" x={310} y={190} at="right" />
      <Caption x={220} y={120} strong testId="plant-temperature">{`${celsius.toFixed(1)} °C`}</Caption>
      <Lamp plant={plant} name="full" x={320} y={60} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="empty" x={320} y={160} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="hot" x={320} y={110} colour="red" r={6} label="right" />
      <Gauge x={420} y={50} height={140} value={analog(word(plant, 'temperature'))} caption={plant.wiring.temperature ?? '—'} fault={hasFault(plant, 'overheat')} testId="plant-gauge-temperature" />
      <Pipe d="M 220 200 L 220 230 L 440 230" flowing={bit(plant, 'drain_valve') && level > 0} timeMs={time} />
      <Valve x={300} y={230} open={bit(plant, 'drain_valve')} testId="plant-valve-drain_valve" />
      <SignalLabel plant={plant} name="drain_valve" x={330} y={215} at="right" />
    </PlantSvg>
  );
}
