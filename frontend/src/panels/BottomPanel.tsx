import { useEffect } from 'react';
import { useTranslation } from 'react-i18next';
import { Tabs, type TabDefinition } from '../ui/Tabs';
import { EyeIcon, ListIcon, StepIcon, TrendIcon } from '../ui/icons';
import { IoIcon } from '../cpu/cpuIcons';
import { useMonitor } from '../cpu/SessionContext';
import { DebugPanel } from './DebugPanel';
import { WorkbenchDiagnostics, useProblemCount } from './DiagnosticsList';
import { IoPanel } from './IoPanel';
import { TrendView } from './TrendView';
import { WatchTable } from './WatchTable';
import { usePanelTab } from './panelTab';
import { AssignmentPanel } from '../xref/AssignmentPanel';
import { CrossReferencesPanel } from '../xref/CrossReferencesPanel';
import { RenameHost } from '../xref/RenameDialog';
import { PlantPanel } from '../plants/PlantPanel';

import '../styles/monitor.css';

type PanelId = 'diagnostics' | 'watch' | 'trend' | 'io' | 'plant' | 'debug' | 'xref' | 'assignments';

/** The panel under the editor: diagnostics, the watch table, the trend view and the I/O panel. */
export function BottomPanel() {
  const { t } = useTranslation();
  const [selected, setSelected] = usePanelTab<PanelId>('diagnostics');
  const problemCount = useProblemCount();
  // A hold brings the call stack to the front (a step from one hold to the next does not).
  const holding = useMonitor((state) => state.hold !== null);
  useEffect(() => {
    if (holding) setSelected('debug');
  }, [holding, setSelected]);

  const tabs: TabDefinition<PanelId>[] = [
    {
      id: 'diagnostics',
      testId: 'panel-tab-diagnostics',
      icon: <ListIcon />,
      label: (
        <>
          {t('panels.diagnostics')}
          <span className="count-badge" aria-hidden="true">
            {problemCount}
          </span>
          <span className="visually-hidden">{t('panels.problemCount', { count: problemCount })}</span>
        </>
      ),
      panel: <WorkbenchDiagnostics />,
    },
    { id: 'watch', testId: 'panel-tab-watch', icon: <EyeIcon />, label: t('panels.watch'), panel: <WatchTable /> },
    { id: 'trend', testId: 'panel-tab-trend', icon: <TrendIcon />, label: t('panels.trend'), panel: <TrendView /> },
    { id: 'io', testId: 'panel-tab-io', icon: <IoIcon />, label: t('panels.io'), panel: <IoPanel /> },
    { id: 'plant', testId: 'panel-tab-plant', icon: <IoIcon />, label: t('plants.tab'), panel: <PlantPanel /> },
    { id: 'debug', testId: 'panel-tab-debug', icon: <StepIcon />, label: t('debug.panel.tab'), panel: <DebugPanel /> },
    { id: 'xref', testId: 'panel-tab-xref', icon: <ListIcon />, label: t('xref.panel.tab'), panel: <CrossReferencesPanel /> },
    { id: 'assignments', testId: 'panel-tab-assignments', icon: <ListIcon />, label: t('xref.assignments.tab'), panel: <AssignmentPanel shown={selected === 'assignments'} /> },
  ];

  return (
    <section className={selected === 'plant' ? 'bottom-panel bottom-panel--plant' : 'bottom-panel'} aria-label={t('panels.label')}>
      <Tabs tabs={tabs} selected={selected} onSelect={setSelected} label={t('panels.label')} />
      <RenameHost />
    </section>
  );
}
