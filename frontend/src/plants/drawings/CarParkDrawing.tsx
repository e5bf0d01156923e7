import { useTranslation } from 'react-i18next';
import { Caption, Lamp, PlantSvg, SignalLabel, bit, stateNumber, type DrawingProps } from '../parts';

/** P09: a car park with an entry and an exit sensor, a gate, a counter and a "full" sign. */
export function CarParkDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const cars = stateNumber(plant, ['cars']);
  const capacity = stateNumber(plant, ['capacity'], Number.NaN);
  const gateOpen = bit(plant, 'gate');
  const gateAngle = gateOpen ? -75 : 0;
  const shown = Math.min(cars, 12);
  return (
    <PlantSvg width={460} height={230} plant={plant}>
      <rect x={20} y={130} width={420} height={50} className="plant-road" />
      <g transform={`rotate(${gateAngle} 120 128)`} data-testid="plant-gate" data-on={gateOpen ? '1' : '0'}>
        <rect x={120} y={124} width={110} height={8} className="plant-barrier" />
      </g>
      <rect x={112} y={120} width={14} height={60} className="plant-post" />
      <SignalLabel plant={plant} name="gate" x={112} y={200} at="right" />
      <Lamp plant={plant} name="entry" x={70} y={155} colour="yellow" label="none" />
      <SignalLabel plant={plant} name="entry" x={70} y={185} />
      <Lamp plant={plant} name="exit" x={300} y={155} colour="yellow" label="none" />
      <SignalLabel plant={plant} name="exit" x={300} y={185} />
      {/* the lot, one box per parked car */}
      <rect x={250} y={20} width={190} height={90} rx={4} className="plant-lot" />
      {Array.from({ length: shown }, (_, index) => (
        <rect key={index} x={258 + (index % 6) * 30} y={30 + Math.floor(index / 6) * 38} width={22} height={30} rx={4} className="plant-car" />
      ))}
      <Caption x={345} y={125} strong testId="plant-cars">
        {Number.isFinite(capacity) ? t('plants.carsOf', { value: cars, capacity }) : t('plants.cars', { value: cars })}
      </Caption>
      <rect x={40} y={30} width={120} height={36} rx={4} className={bit(plant, 'full_sign') ? 'plant-sign plant-sign--on' : 'plant-sign'} data-testid="plant-lamp-full_sign" data-on={bit(plant, 'full_sign') ? '1' : '0'} />
      <Caption x={100} y={53} strong>{t('plants.fullSign')}</Caption>
      <SignalLabel plant={plant} name="full_sign" x={100} y={70} />
    </PlantSvg>
  );
}
