/**
 * S7-Graph's permanent instructions: the networks the FB runs before its sequencers (pre) and
 * after them (post) in every call, drawn and edited in the LAD/FBD editor as whole networks
 * (coils and block calls included), written back with `setPermanent` in one edit each.
 * Online, their power flow comes from the Graph monitoring (`PRE<n>/<id>`, `POST<n>/<id>`).
 */
import { useMemo, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { LadEditor } from '../lad/LadEditor';
import type { ElementState } from '../lad/status';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { conditionProblems, conditionStates, externalStatus, usePermanentDoc } from './conditionDoc';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useProjectContents } from '../projects/projectContents';
import { setPermanent } from './edits';
import type { GraphMonitor } from './useGraphMonitoring';
import type { GraphDocument } from './useGraphDocument';
import './step.css';

export interface PermanentViewProps {
  doc: GraphDocument;
  block: number;
  monitor: GraphMonitor | null;
  projectId: number | null;
  file: string | null;
  active: boolean;
}

/** The element states of the permanent networks: network k of `pre` has the origins `PRE<k>/`. */
export function permanentStates(monitor: GraphMonitor | null, which: 'pre' | 'post', count: number): ReadonlyMap<string, ElementState>[] | null {
  if (!monitor?.status) return null;
  const prefix = which === 'pre' ? 'PRE' : 'POST';
  return conditionStates(
    monitor.elements,
    Array.from({ length: count }, (_, k) => ({ origin: `${prefix}${k + 1}/` })),
  );
}

export function PermanentView({ doc, block, monitor, projectId, file, active }: PermanentViewProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const [mode, setMode] = useState<'LAD' | 'FBD'>('LAD');
  const pre = usePermanentDoc(doc, block, 'pre', setPermanent);
  const post = usePermanentDoc(doc, block, 'post', setPermanent);
  const graphBlock = doc.blocks?.[block] ?? null;
  const preCount = graphBlock?.pre.length ?? 0;
  const postCount = graphBlock?.post.length ?? 0;
  const preStates = useMemo(() => externalStatus(permanentStates(monitor, 'pre', preCount)), [monitor, preCount]);
  const postStates = useMemo(() => externalStatus(permanentStates(monitor, 'post', postCount)), [monitor, postCount]);
  const editable = doc.state.status === 'ready' && !doc.pending;
  const contents = useProjectContents(projectId);
  const message = useDiagnosticMessage();
  const problems = useMemo(
    () => ({
      pre: conditionProblems(contents?.diagnostics ?? [], file, Array.from({ length: preCount }, (_, k) => ({ origin: `PRE${k + 1}/` })), message),
      post: conditionProblems(contents?.diagnostics ?? [], file, Array.from({ length: postCount }, (_, k) => ({ origin: `POST${k + 1}/` })), message),
    }),
    [contents?.diagnostics, file, preCount, postCount, message],
  );

  return (
    <div className="graph-permanent" hidden={!active} dir={dir} lang={language} data-testid="graph-permanent-view">
      <div className="graph-step__mode" role="group" aria-label={t('graphStep.mode')}>
        {(['LAD', 'FBD'] as const).map((m) => (
          <button key={m} type="button" className="button button--small" aria-pressed={mode === m} onClick={() => setMode(m)}>
            {m}
          </button>
        ))}
      </div>
      {(['pre', 'post'] as const).map((which) => (
        <section key={which} className="graph-permanent__section" data-testid={`graph-permanent-${which}`} aria-label={t(`graphStep.permanent.${which}`)}>
          <h3>{t(`graphStep.permanent.${which}`)}</h3>
          <p className="graph-step__hint">{t(`graphStep.permanent.${which}Hint`)}</p>
          <div className="graph-permanent__editor">
            {active ? (
            <LadEditor
              doc={which === 'pre' ? pre : post}
              text=""
              projectId={projectId}
              file={null}
              mode={mode}
              active={active}
              readOnly={!editable}
              monitoring={false}
              onMonitorProblem={() => undefined}
              embedded={{ fixedNetworks: false, status: which === 'pre' ? preStates : postStates, label: t(`graphStep.permanent.${which}`), problems: problems[which] }}
            />
            ) : null}
          </div>
        </section>
      ))}
    </div>
  );
}
