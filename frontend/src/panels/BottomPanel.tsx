import { useState } from 'react';
import { useTranslation } from 'react-i18next';
import { Tabs, type TabDefinition } from '../ui/Tabs';
import { EyeIcon, ListIcon, TrendIcon } from '../ui/icons';
import { DiagnosticsList } from './DiagnosticsList';
import { useDiagnostics } from './diagnosticsStore';
import { TrendView } from './TrendView';
import { WatchTable } from './WatchTable';

type PanelId = 'diagnostics' | 'watch' | 'trend';

/** The panel under the editor: diagnostics, the watch table and the trend view. */
export function BottomPanel() {
  const { t } = useTranslation();
  const [selected, setSelected] = useState<PanelId>('diagnostics');
  const problemCount = useDiagnostics().length;

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
      panel: <DiagnosticsList />,
    },
    { id: 'watch', testId: 'panel-tab-watch', icon: <EyeIcon />, label: t('panels.watch'), panel: <WatchTable /> },
    { id: 'trend', testId: 'panel-tab-trend', icon: <TrendIcon />, label: t('panels.trend'), panel: <TrendView /> },
  ];

  return (
    <section className="bottom-panel" aria-label={t('panels.label')}>
      <Tabs tabs={tabs} selected={selected} onSelect={setSelected} label={t('panels.label')} />
    </section>
  );
}
