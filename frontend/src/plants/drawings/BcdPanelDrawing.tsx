import { useTranslation } from 'react-i18next';
import { Caption, PlantSvg, SignalLabel, word, type DrawingProps } from '../parts';

/** Segments a..g of a digit 0..9 (bit 0 = a). */
const SEGMENTS = [0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f];
/** The "E" a BCD display shows for a nibble A..F. */
const ERROR = 0x79;

export function bcdDigits(value: number): number[] {
  const bits = value & 0xffff;
  return [12, 8, 4, 0].map((shift) => (bits >> shift) & 0xf);
}

function Digit({ x, y, nibble, testId }: { x: number; y: number; nibble: number; testId: string }) {
  const mask = nibble <= 9 ? (SEGMENTS[nibble] ?? 0) : ERROR;
  const w = 26;
  const h = 24;
  const segs: Array<[number, number, number, number]> = [
    [x, y, x + w, y],
    [x + w, y, x + w, y + h],
    [x + w, y + h, x + w, y + 2 * h],
    [x, y + 2 * h, x + w, y + 2 * h],
    [x, y + h, x, y + 2 * h],
    [x, y, x, y + h],
    [x, y + h, x + w, y + h],
  ];
  return (
    <g data-testid={testId} data-digit={nibble <= 9 ? String(nibble) : 'E'}>
      {segs.map(([x1, y1, x2, y2], index) => (
        <line key={index} x1={x1} y1={y1} x2={x2} y2={y2} className={mask & (1 << index) ? 'plant-seg plant-seg--on' : 'plant-seg'} />
      ))}
    </g>
  );
}

/** P26: BCD thumbwheels into a word, a seven-segment display from a word. */
export function BcdPanelDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const wheels = bcdDigits(word(plant, 'thumbwheel'));
  const shown = bcdDigits(word(plant, 'display'));
  return (
    <PlantSvg width={460} height={200} plant={plant}>
      <rect x={10} y={10} width={440} height={180} rx={8} className="plant-panel" />
      {wheels.map((digit, index) => (
        <g key={index} data-testid={`plant-wheel-${index}`}>
          <rect x={30 + index * 40} y={40} width={30} height={50} rx={4} className="plant-wheel" />
          <Caption x={45 + index * 40} y={72} strong>{digit <= 9 ? String(digit) : '?'}</Caption>
        </g>
      ))}
      <SignalLabel plant={plant} name="thumbwheel" x={100} y={110} />
      <rect x={240} y={30} width={200} height={80} rx={4} className="plant-display" />
      {shown.map((nibble, index) => (
        <Digit key={index} x={256 + index * 46} y={45} nibble={nibble} testId={`plant-digit-${index}`} />
      ))}
      <SignalLabel plant={plant} name="display" x={340} y={130} />
      {shown.some((nibble) => nibble > 9) ? <Caption x={340} y={170} testId="plant-bcd-error">{t('plants.notBcd')}</Caption> : null}
    </PlantSvg>
  );
}
