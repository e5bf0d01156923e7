import { useTranslation } from 'react-i18next';
import { Caption, Gauge, Lamp, PlantSvg, SignalLabel, analog, bit, word, type DrawingProps } from '../parts';
import type { PlantInfo, SignalDirection } from '../types';

interface Row {
  name: string;
  direction: SignalDirection | 'unknown';
  isWord: boolean;
}

/** The plant's signals grouped by direction: from the catalogue, else guessed from the frame. */
export function signalRows(plant: DrawingProps['plant'], info: PlantInfo | undefined): Row[] {
  if (info) return info.signals.map((s) => ({ name: s.name, direction: s.direction, isWord: s.kind === 'word' }));
  return Object.keys(plant.signals).map((name) => {
    const address = (plant.wiring[name] ?? '').toUpperCase();
    const direction = /^(Q|A|PQ|PA|M)/.test(address) ? 'actuator' : /^(I|E|PI|PE)/.test(address) ? 'sensor' : 'unknown';
    return { name, direction, isWord: /^P?[IEQA]W|^MW/.test(address) || Math.abs(word(plant, name)) > 1 };
  });
}

const GROUPS: Array<SignalDirection | 'unknown'> = ['control', 'sensor', 'actuator', 'unknown'];

/**
 * Any plant without its own drawing: its signals as lamps (bits) and bars (words) in rows by
 * direction, so nothing is ever blank.
 */
export function GenericDrawing({ plant, info }: DrawingProps & { info?: PlantInfo }) {
  const { t } = useTranslation();
  const rows = signalRows(plant, info);
  const groups = GROUPS.map((direction) => rows.filter((row) => row.direction === direction)).filter((group) => group.length > 0);
  const perRow = 6;
  const lines = groups.reduce((sum, group) => sum + Math.ceil(group.length / perRow), 0);
  const height = Math.max(80, 30 + lines * 70 + groups.length * 18);
  let y = 12;
  return (
    <PlantSvg width={460} height={height} plant={plant}>
      {groups.map((group) => {
        const direction = group[0]?.direction ?? 'unknown';
        const top = y;
        y += 18 + Math.ceil(group.length / perRow) * 70;
        return (
          <g key={direction}>
            <Caption x={14} y={top + 12} anchor="start" strong>
              {t(`plants.direction.${direction}`)}
            </Caption>
            {group.map((row, index) => {
              const x = 45 + (index % perRow) * 72;
              const cy = top + 38 + Math.floor(index / perRow) * 70;
              if (row.isWord) {
                return (
                  <g key={row.name}>
                    <Gauge x={x - 22} y={cy - 8} width={44} height={10} value={analog(word(plant, row.name))} caption="" testId={`plant-gauge-${row.name}`} />
                    <SignalLabel plant={plant} name={row.name} x={x} y={cy + 6} />
                  </g>
                );
              }
              return <Lamp key={row.name} plant={plant} name={row.name} x={x} y={cy} on={bit(plant, row.name)} colour={direction === 'actuator' ? 'green' : 'yellow'} />;
            })}
          </g>
        );
      })}
    </PlantSvg>
  );
}
