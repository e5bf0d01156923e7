import { useTranslation } from 'react-i18next';
import { Caption, FaultMark, Lamp, Motor, PlantSvg, SignalLabel, bit, clamp01, hasFault, stateNumber, type DrawingProps } from '../parts';

/** P02: a motor behind a contactor and a thermal overload relay, with run and fault lamps. */
export function MotorDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const closed = bit(plant, 'contactor');
  const burnt = hasFault(plant, 'burnt');
  const tripped = !bit(plant, 'overload');
  const speed = clamp01(stateNumber(plant, ['speed'], closed && !burnt ? 100 : 0) / 100);
  const running = speed > 0 && !burnt;
  return (
    <PlantSvg width={440} height={230} plant={plant}>
      {/* supply line -> contactor K1 -> overload F1 -> motor */}
      <line x1={40} y1={30} x2={40} y2={60} className="plant-wire" />
      <g className={closed ? 'plant-contact plant-contact--closed' : 'plant-contact'} data-testid="plant-contactor" data-on={closed ? '1' : '0'}>
        <line x1={40} y1={60} x2={closed ? 40 : 54} y2={88} />
        <rect x={70} y={64} width={26} height={20} className="plant-coil" />
        <Caption x={83} y={78}>K1</Caption>
      </g>
      <SignalLabel plant={plant} name="contactor" x={110} y={68} at="right" />
      <line x1={40} y1={88} x2={40} y2={110} className="plant-wire" />
      <g className={tripped ? 'plant-relay plant-relay--tripped' : 'plant-relay'} data-testid="plant-overload" data-on={tripped ? '1' : '0'}>
        <rect x={28} y={110} width={24} height={22} className="plant-coil" />
        <path d="M 32 121 h 4 v -5 h 6 v 10 h 6" className="plant-wire" />
      </g>
      <Lamp plant={plant} name="overload" x={110} y={121} colour={tripped ? 'red' : 'green'} on label="right" />
      <line x1={40} y1={132} x2={40} y2={160} className="plant-wire" />
      <Motor x={40} y={185} r={24} running={running} speed={speed} timeMs={plant.time_ms} faulted={burnt} testId="plant-motor" />
      {burnt ? <FaultMark x={40} y={185} size={18} /> : null}
      <Caption x={80} y={190} anchor="start" testId="plant-motor-speed">
        {t('plants.speed', { value: Math.round(speed * 100) })}
      </Caption>
      {/* the panel's lamps */}
      <rect x={250} y={30} width={170} height={150} rx={6} className="plant-panel" />
      <Lamp plant={plant} name="run_lamp" x={290} y={70} colour="green" r={10} />
      <Lamp plant={plant} name="fault_lamp" x={370} y={70} colour="red" r={10} />
      <Lamp plant={plant} name="running" x={330} y={140} colour="yellow" r={6} />
    </PlantSvg>
  );
}
