import { useEffect, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, convertSource, type ApiError } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { FbdView } from '../lad/FbdView';
import { LadRung, type RungProblem } from '../lad/LadRung';
import { layoutOf } from '../lad/layoutCache';
import type { LadBlock } from '../lad/model';
import '../lad/lad.css';

const NONE = new Map<string, readonly RungProblem[]>();
const nothing = () => undefined;

/**
 * A ```` ```lad-view ```` / ```` ```fbd-view ```` fence of a lesson text: its STL drawn with the
 * editors' own LAD rung / FBD view (converted by the server's conversion, as "View: LAD" of an
 * STL source), read-only and always left to right. A network without LAD shape stays STL.
 */
export function LessonDiagram({ stl, mode }: { stl: string; mode: 'LAD' | 'FBD' }) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const [blocks, setBlocks] = useState<LadBlock[] | null>(null);
  const [error, setError] = useState<ApiError | null>(null);

  useEffect(() => {
    // A late answer for a drawing no longer shown is dropped (the request is small; it runs out).
    let alive = true;
    setBlocks(null);
    setError(null);
    convertSource('lesson-view.awl', stl, mode === 'FBD' ? 'fbd' : 'lad').then(
      (converted) => alive && setBlocks(converted.blocks ?? []),
      (caught: unknown) => alive && setError(asApiError(caught)),
    );
    return () => {
      alive = false;
    };
  }, [stl, mode]);

  const networks = blocks?.flatMap((block) => block.networks) ?? [];
  return (
    <figure className="lesson-diagram" dir="ltr" data-testid="lesson-diagram" data-mode={mode}>
      {error ? (
        <>
          <pre className="lesson-diagram__stl">{stl}</pre>
          <figcaption className="lesson-diagram__problem" role="alert">
            <code className="error-code">{error.code}</code> {errorText(error)}
          </figcaption>
        </>
      ) : blocks === null ? (
        <p className="lesson-diagram__loading">{t('lessonPane.diagram.drawing')}</p>
      ) : networks.length === 0 ? (
        <pre className="lesson-diagram__stl">{stl}</pre>
      ) : (
        networks.map((network, k) => (
          <div key={k} className="lesson-diagram__network" role="group" aria-label={t('lessonPane.diagram.network', { number: k + 1, mode })}>
            {network.stl !== null ? (
              <pre className="lesson-diagram__stl">{network.stl}</pre>
            ) : mode === 'FBD' ? (
              <div className="lad-rung-frame">
                <FbdView network={network} prefix={`lesson-fbd-${k}`} selectedId={null} onSelect={nothing} onEdit={nothing} onContextMenu={nothing} problems={NONE} flows={undefined} />
              </div>
            ) : (
              <div className="lad-rung-frame">
                <LadRung
                  network={network}
                  layout={layoutOf(network)}
                  prefix={`lesson-lad-${k}`}
                  selectedId={null}
                  insertAt={null}
                  label={(operand) => ({ main: operand })}
                  problems={NONE}
                  dragging={false}
                  onSelect={nothing}
                  onSelectPoint={nothing}
                  onEdit={nothing}
                  onContextMenu={nothing}
                  onDrop={nothing}
                  onMoveStart={nothing}
                  onMoveTo={nothing}
                />
              </div>
            )}
          </div>
        ))
      )}
    </figure>
  );
}
