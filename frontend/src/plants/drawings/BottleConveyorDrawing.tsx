import { useTranslation } from 'react-i18next';
import { Belt, Caption, Lamp, PhotoEye, PlantSvg, Pipe, SignalLabel, Valve, bit, hasFault, param, stateNumber, type DrawingProps } from '../parts';
import { itemsOf } from './moving';

/** P04: bottles on a conveyor, a photo-eye at the filler, a counting eye and an exit eye, a pusher. */
export function BottleConveyorDrawing({ plant, params }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const running = bit(plant, 'conveyor');
  const filling = bit(plant, 'fill_valve');
  const length = param(params, 'length', 1100);
  const beltX = 20;
  const beltW = 420;
  const toX = (mm: number) => beltX + (mm / length) * beltW;
  const fillX = toX(param(params, 'fill_at', 600));
  const faulty = hasFault(plant, 'overfill') || hasFault(plant, 'underfill');
  return (
    <PlantSvg width={460} height={240} plant={plant}>
      <Belt x={beltX} y={170} width={beltW} running={running} timeMs={time} testId="plant-belt" />
      <SignalLabel plant={plant} name="conveyor" x={beltX} y={195} at="right" />
      {itemsOf(plant, 'bottle_list').map((bottle, index) => {
        const x = toX(bottle.at);
        const fill = Math.max(0, bottle.fill) / 100;
        if (x < beltX - 10 || x > beltX + beltW + 10) return null;
        return (
          <g key={index} className="plant-bottle" data-testid="plant-bottle" data-fill={bottle.fill.toFixed(0)}>
            <rect x={x - 9} y={170 - 46 * Math.min(1, fill)} width={18} height={46 * Math.min(1, fill)} className={fill > 1.001 ? 'plant-water plant-water--over' : 'plant-water'} />
            <path d={`M ${x - 9} 170 L ${x - 9} 130 Q ${x - 9} 120 ${x - 4} 116 L ${x - 4} 106 L ${x + 4} 106 L ${x + 4} 116 Q ${x + 9} 120 ${x + 9} 130 L ${x + 9} 170 Z`} className="plant-bottle__glass" />
          </g>
        );
      })}
      {/* filling station */}
      <Pipe d={`M ${fillX} 20 L ${fillX} 100`} flowing={filling} timeMs={time} />
      <Valve x={fillX} y={60} open={filling} vertical testId="plant-valve-fill_valve" />
      <SignalLabel plant={plant} name="fill_valve" x={fillX + 30} y={40} at="right" />
      <PhotoEye plant={plant} name="count_eye" x={toX(param(params, 'count_at', 150))} y1={112} y2={160} />
      <PhotoEye plant={plant} name="bottle_eye" x={fillX + 14} y1={112} y2={160} />
      <PhotoEye plant={plant} name="exit_eye" x={toX(param(params, 'exit_at', 1000))} y1={112} y2={160} />
      <g data-testid="plant-pusher" data-on={bit(plant, 'pusher') ? '1' : '0'}>
        <rect x={bit(plant, 'pusher') ? 384 : 370} y={214} width={18} height={10} className={faulty ? 'plant-actuator plant-actuator--fault' : 'plant-actuator'} />
        <SignalLabel plant={plant} name="pusher" x={410} y={214} at="right" />
      </g>
      <Lamp plant={plant} name="lamp" x={40} y={40} colour="green" />
      <Caption x={beltX} y={232} anchor="start" testId="plant-count">
        {t('plants.bottles', { ok: stateNumber(plant, ['filled_ok']), rejected: stateNumber(plant, ['rejected']) })}
      </Caption>
    </PlantSvg>
  );
}
