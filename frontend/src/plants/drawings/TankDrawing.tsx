import { useTranslation } from 'react-i18next';
import { Caption, Gauge, Lamp, Motor, PlantSvg, Pipe, SignalLabel, Valve, analog, bit, hasFault, stateNumber, word, type DrawingProps } from '../parts';

/** The level as 0..1: the model's own level in percent, else the analog word. */
export function tankLevel(plant: DrawingProps['plant']): number {
  const percent = stateNumber(plant, ['level'], Number.NaN);
  if (Number.isFinite(percent)) return Math.min(1.08, Math.max(0, percent / 100));
  return analog(word(plant, 'level'));
}

/** P03: a tank filled by a pump and a fill valve, emptied by a drain valve, with two level probes and an analog level. */
export function TankDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const level = tankLevel(plant);
  const top = 50;
  const bottom = 220;
  const waterTop = bottom - Math.min(1, level) * (bottom - top);
  const overflow = hasFault(plant, 'overflow');
  const pumping = bit(plant, 'pump');
  const filling = bit(plant, 'fill_valve');
  const draining = bit(plant, 'drain_valve') && level > 0;
  const broken = hasFault(plant, 'level_wire_break');
  return (
    <PlantSvg width={460} height={270} plant={plant}>
      {/* supply: pump from the well, fill valve from the mains */}
      <Pipe d="M 20 235 L 60 235 L 60 30 L 190 30 L 190 50" flowing={pumping} timeMs={time} />
      <Motor x={60} y={190} r={15} running={pumping} timeMs={time} testId="plant-pump" />
      <SignalLabel plant={plant} name="pump" x={60} y={190} r={18} at="left" />
      <Pipe d="M 120 12 L 250 12 L 250 50" flowing={filling} timeMs={time} />
      <Valve x={150} y={12} open={filling} vertical testId="plant-valve-fill_valve" />
      <SignalLabel plant={plant} name="fill_valve" x={256} y={26} at="right" />
      {/* the vessel and its water */}
      <rect x={150} y={waterTop} width={140} height={bottom - waterTop} className="plant-water" data-testid="plant-water" />
      {overflow ? <path d="M 150 50 q -10 20 -14 60 M 290 50 q 10 20 14 60" className="plant-spill" /> : null}
      <path d={`M 150 ${top - 8} L 150 ${bottom} L 290 ${bottom} L 290 ${top - 8}`} className="plant-vessel" />
      <Caption x={220} y={140} strong testId="plant-level-text">
        {`${Math.round(level * 100)} %`}
      </Caption>
      {/* probes: high near the top, low near the bottom */}
      <line x1={290} y1={70} x2={272} y2={70} className="plant-probe" />
      <line x1={290} y1={200} x2={272} y2={200} className="plant-probe" />
      <Lamp plant={plant} name="ls_high" x={320} y={70} colour="yellow" label="right" />
      <Lamp plant={plant} name="ls_low" x={320} y={200} colour="yellow" label="right" />
      {/* drain */}
      <Pipe d="M 270 220 L 270 245 L 440 245" flowing={draining} timeMs={time} />
      <Valve x={330} y={245} open={bit(plant, 'drain_valve')} testId="plant-valve-drain_valve" />
      <SignalLabel plant={plant} name="drain_valve" x={380} y={232} at="right" />
      {/* analog level transmitter */}
      <Gauge x={410} y={70} height={130} value={broken ? 1 : analog(word(plant, 'level'))} caption={plant.wiring.level ?? '—'} fault={broken} testId="plant-gauge-level" />
      <Caption x={417} y={60}>{broken ? t('plants.wireBroken') : String(word(plant, 'level'))}</Caption>
      <Lamp plant={plant} name="alarm" x={220} y={258} colour="red" r={6} label="right" />
    </PlantSvg>
  );
}
