import { useTranslation } from 'react-i18next';
import { DRAWINGS } from './drawings';
import { GenericDrawing } from './drawings/GenericDrawing';
import { useFaultText } from './parts';
import type { PlantFrame, PlantInfo } from './types';

interface PlantDrawingProps {
  plant: PlantFrame;
  info?: PlantInfo | undefined;
  /** The plant's own parameters (a file's `params`); the catalogue's defaults fill the rest. */
  params?: Readonly<Record<string, number>> | undefined;
}

/** The plant's drawing (its own, or the generic one) and its active faults in words. */
export function PlantDrawing({ plant, info, params }: PlantDrawingProps) {
  const { t } = useTranslation();
  const faultText = useFaultText();
  const Drawing = DRAWINGS[plant.kind];
  const values = { ...info?.defaults, ...params };
  return (
    <figure className="plant-drawing" dir="ltr" data-kind={plant.kind}>
      {plant.faults.length > 0 ? (
        <figcaption className="plant-drawing__faults" dir="auto" role="alert">
          <ul aria-label={t('plants.faultsActive')}>
            {plant.faults.map((code) => (
              <li key={code} className="plant-fault" data-testid={`plant-fault-${code}`} dir="auto">
                <span aria-hidden="true">⚠ </span>
                {faultText(plant.kind, code, info?.faults.find((fault) => fault.code === code)?.description)}
              </li>
            ))}
          </ul>
        </figcaption>
      ) : null}
      {Drawing ? <Drawing plant={plant} params={values} /> : <GenericDrawing plant={plant} info={info} />}
    </figure>
  );
}

/** A plant at rest, as its file describes it, for the drawing before any session runs it. */
export function stillFrame(kind: string, wiring: Record<string, string>, info: PlantInfo | undefined): PlantFrame {
  const signals: Record<string, number> = {};
  for (const signal of info?.signals ?? []) signals[signal.name] = signal.normally_closed ? 1 : 0;
  return { kind, time_ms: 0, state: {}, signals, faults: [], wiring };
}
