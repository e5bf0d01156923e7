/**
 * The views of a `.graph` file, as S7-Graph offers them: the sequencer chart, the single step
 * (actions, interlock, supervision, its transitions), the permanent pre/post instructions, the
 * generated interface and STL (read-only), and the file's text. All views edit one document
 * (`useGraphDocument`), share one selection and, while the tab monitors, one online status.
 *
 * A file that does not read (syntax errors) cannot be drawn: it opens in the text view with its
 * markers, and the drawn views say why, listing the errors with their lines, as the LAD/FBD
 * views do.
 */
import { useCallback, useEffect, useRef, useState, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import type { Problem } from '../api/monitorClient';
import { useEditorTabs, type SourceTab } from '../editor/EditorTabsContext';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { ControlSequencer } from './ControlSequencer';
import { GeneratedView } from './GeneratedView';
import { GraphChart } from './GraphChart';
import { PermanentView } from './PermanentView';
import { StepView } from './StepView';
import { setSettings } from './edits';
import type { GraphSelection } from './selection';
import { SettingsDialog } from './SettingsDialog';
import { useGraphDocument, type GraphDocument } from './useGraphDocument';
import { useGraphMonitoring } from './useGraphMonitoring';
import { warmUpCharts } from './warmUp';
import { CannotDraw } from '../lad/DiagramViews';
import '../lad/lad.css';

export type GraphView = 'chart' | 'step' | 'permanent' | 'stl' | 'text';

const VIEWS: readonly GraphView[] = ['chart', 'step', 'permanent', 'stl', 'text'];

/** Each tab's view and selection, while the page lives (a tab's views may remount). */
const remembered = new Map<string, { view: GraphView; selection: GraphSelection }>();

export interface GraphSourceViewsProps {
  tab: SourceTab;
  active: boolean;
  monitoring: boolean;
  onMonitorProblem: (problem: Problem | null) => void;
  /** The file's text editor (Monaco with the file's markers), shown in the text view. */
  textEditor: ReactNode;
  onViewChange?: (view: GraphView) => void;
}

/** Whether a view draws the block (and so monitors it online). */
export function drawsBlock(view: GraphView | null): boolean {
  return view === 'chart' || view === 'step' || view === 'permanent';
}

function ViewBar({ view, onView }: { view: GraphView; onView: (view: GraphView) => void }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  return (
    <div className="view-bar" dir={dir} lang={language}>
      <div className="view-bar__choices" role="group" aria-label={t('graphChart.views.label')}>
        {VIEWS.map((choice) => (
          <button key={choice} type="button" className="view-bar__choice" aria-pressed={view === choice} data-testid={`graph-view-${choice}`} onClick={() => onView(choice)}>
            {t(`graphChart.views.${choice}`)}
          </button>
        ))}
      </div>
    </div>
  );
}


function DrawnOrReason({ doc, onText, children }: { doc: GraphDocument; onText: () => void; children: ReactNode }) {
  const { t } = useTranslation();
  if (doc.state.status === 'unreadable') return <CannotDraw kind="graph" problems={doc.state.problems} error={null} onText={onText} onRetry={doc.retry} />;
  if (doc.state.status === 'failed' && !doc.blocks) return <CannotDraw kind="graph" problems={[]} error={doc.state.error} onText={onText} onRetry={doc.retry} />;
  if (!doc.blocks) return <p className="diagram-views__loading">{t('graphChart.reading')}</p>;
  return <>{children}</>;
}

/** The views of a `.graph` file. */
export function GraphSourceViews({ tab, active, monitoring, onMonitorProblem, textEditor, onViewChange }: GraphSourceViewsProps) {
  const { t } = useTranslation();
  const { updateSource } = useEditorTabs();
  useEffect(warmUpCharts, []);
  const [view, setView] = useState<GraphView>(() => remembered.get(tab.id)?.view ?? 'chart');
  const [selection, setSelection] = useState<GraphSelection>(() => remembered.get(tab.id)?.selection ?? { block: 0, sequencer: 0, item: null });
  const [textShown, setTextShown] = useState(view === 'text');
  const [settingsOpen, setSettingsOpen] = useState(false);
  const [controlOpen, setControlOpen] = useState(false);
  const setText = useCallback((text: string) => updateSource(tab.id, text), [updateSource, tab.id]);
  const doc = useGraphDocument(tab.name, tab.text, setText, view !== 'text');
  const initialView = useRef(remembered.has(tab.id));
  const file = tab.file;
  const blocks = doc.blocks ?? [];
  const blockIndex = blocks[selection.block] ? selection.block : 0;
  const block = blocks[blockIndex] ?? null;

  const choose = useCallback((next: GraphView) => {
    if (next === 'text') setTextShown(true);
    setView(next);
  }, []);

  useEffect(() => {
    remembered.set(tab.id, { view, selection });
  }, [tab.id, view, selection]);
  useEffect(() => onViewChange?.(view), [view, onViewChange]);

  // A file that cannot be drawn opens in its text view (the drawn views say why).
  useEffect(() => {
    if (initialView.current) return;
    if (doc.state.status === 'unreadable') {
      initialView.current = true;
      choose('text');
    } else if (doc.state.status === 'ready') initialView.current = true;
  }, [doc.state.status, choose]);

  const drawn = drawsBlock(view);
  const monitor = useGraphMonitoring({
    enabled: monitoring && active && drawn && block !== null,
    projectId: file?.projectId ?? null,
    file: file?.path ?? null,
    block: block?.name ?? '',
  });
  const online = monitoring && active && drawn ? monitor : null;
  const problem = online ? monitor.problem : null;
  useEffect(() => onMonitorProblem(problem), [problem, onMonitorProblem]);

  const openStep = useCallback((step: string) => {
    setSelection((current) => ({ ...current, item: { kind: 'step', name: step } }));
    setView('step');
  }, []);

  return (
    <div className="diagram-views graph-views">
      <ViewBar view={view} onView={choose} />
      <div className="diagram-views__content" hidden={view !== 'chart'}>
        {view === 'chart' ? (
          <DrawnOrReason doc={doc} onText={() => choose('text')}>
            <GraphChart
              doc={doc}
              selection={selection}
              onSelect={setSelection}
              onOpenStep={openStep}
              monitor={online}
              readOnly={false}
              onSettings={() => setSettingsOpen(true)}
              onControl={() => setControlOpen(true)}
            />
          </DrawnOrReason>
        ) : null}
      </div>
      {view === 'step' ? (
        <div className="diagram-views__content">
          <DrawnOrReason doc={doc} onText={() => choose('text')}>
            <StepView doc={doc} selection={selection} onSelect={setSelection} monitor={online} projectId={file?.projectId ?? null} file={file?.path ?? null} active={active} />
          </DrawnOrReason>
        </div>
      ) : null}
      {view === 'permanent' ? (
        <div className="diagram-views__content">
          <DrawnOrReason doc={doc} onText={() => choose('text')}>
            <PermanentView doc={doc} block={blockIndex} monitor={online} projectId={file?.projectId ?? null} file={file?.path ?? null} active={active} />
          </DrawnOrReason>
        </div>
      ) : null}
      {view === 'stl' ? (
        <div className="diagram-views__content">
          <GeneratedView name={tab.name} text={tab.text} active={active} />
        </div>
      ) : null}
      <div className="diagram-views__content" hidden={view !== 'text'}>
        {textShown || view === 'text' ? textEditor : null}
      </div>
      {block ? (
        <SettingsDialog
          open={settingsOpen}
          settings={block.settings}
          onApply={(settings) => {
            const at = blockIndex;
            doc.edit((all) => all.map((b, k) => (k === at ? setSettings(b, settings) : b)), t('graphChart.undo.settings'));
            setSettingsOpen(false);
          }}
          onClose={() => setSettingsOpen(false)}
        />
      ) : null}
      {block ? <ControlSequencer open={controlOpen} onClose={() => setControlOpen(false)} monitor={monitor} selection={selection} block={block} /> : null}
    </div>
  );
}
