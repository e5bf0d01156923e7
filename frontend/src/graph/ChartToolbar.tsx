/**
 * The chart's toolbar, S7-Graph's Insert menu as buttons: step + transition, alternative and
 * simultaneous branch, jump, sequence end; delete, move a branch, renumber; undo and redo; the
 * block settings and the Control Sequencer; and, online, the FB's mode and error flags. Each
 * button says its key; it follows the interface language's direction, its symbols stay LTR.
 */
import { useTranslation } from 'react-i18next';
import type { GraphStatus } from '../api/monitor';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import type { ChartCommand } from './chartKeys';

export interface ChartToolbarProps {
  /** Which commands apply now (the selection's kind, read-only, undo history). */
  enabled: ReadonlySet<ChartCommand | 'addSequencer'>;
  onCommand: (command: ChartCommand | 'addSequencer') => void;
  onSettings: (() => void) | null;
  onControl: (() => void) | null;
  /** Online: the status of the FB's last sampled call (null: not sampled yet); undefined offline. */
  status: GraphStatus | null | undefined;
  notice: string | null;
}

interface Tool {
  command: ChartCommand | 'addSequencer';
  testId: string;
  keys?: string;
  shortcut?: string;
}

const GROUPS: readonly (readonly Tool[])[] = [
  [
    { command: 'undo', testId: 'graph-undo', keys: 'Control+Z', shortcut: 'Ctrl+Z' },
    { command: 'redo', testId: 'graph-redo', keys: 'Control+Y', shortcut: 'Ctrl+Y' },
  ],
  [
    { command: 'insertStep', testId: 'graph-insert-step', keys: 'Insert', shortcut: 'Ins' },
    { command: 'alternative', testId: 'graph-insert-alternative', keys: 'Alt+A', shortcut: 'Alt+A' },
    { command: 'simultaneous', testId: 'graph-insert-simultaneous', keys: 'Alt+S', shortcut: 'Alt+S' },
    { command: 'jump', testId: 'graph-insert-jump', keys: 'Alt+J', shortcut: 'Alt+J' },
    { command: 'end', testId: 'graph-insert-end', keys: 'Alt+E', shortcut: 'Alt+E' },
  ],
  [
    { command: 'delete', testId: 'graph-delete', keys: 'Delete', shortcut: 'Del' },
    { command: 'moveLeft', testId: 'graph-move-left', keys: 'Alt+ArrowLeft', shortcut: 'Alt+←' },
    { command: 'moveRight', testId: 'graph-move-right', keys: 'Alt+ArrowRight', shortcut: 'Alt+→' },
    { command: 'rename', testId: 'graph-rename', keys: 'F2', shortcut: 'F2' },
    { command: 'renumber', testId: 'graph-renumber' },
    { command: 'addSequencer', testId: 'graph-add-sequencer' },
  ],
];

/** The FB's mode and error flags as the chart shows them online. */
export function ModeFlags({ status }: { status: GraphStatus | null }) {
  const { t } = useTranslation();
  const interlock = status?.steps.some((step) => step.interlock_error) ?? false;
  const supervision = status?.steps.some((step) => step.supervision_error) ?? false;
  const mode = status?.mode ?? null;
  return (
    <span
      className="graph-toolbar__mode"
      role="status"
      data-testid="graph-monitor-mode"
      data-mode={mode ?? ''}
      data-interlock-error={interlock}
      data-supervision-error={supervision}
    >
      {status === null ? t('graphChart.mode.waiting') : t('graphChart.mode.label', { mode: mode ?? '—' })}
      {interlock ? <span className="graph-toolbar__flag">{t('graphChart.mode.interlock')}</span> : null}
      {supervision ? <span className="graph-toolbar__flag">{t('graphChart.mode.supervision')}</span> : null}
    </span>
  );
}

export function ChartToolbar({ enabled, onCommand, onSettings, onControl, status, notice }: ChartToolbarProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  return (
    <div className="lad-toolbar graph-toolbar" role="toolbar" aria-label={t('graphChart.toolbar.label')} dir={dir} lang={language}>
      {GROUPS.map((group, k) => (
        <span key={k} className="graph-toolbar__group">
          {group.map((tool) => {
            const label = t(`graphChart.toolbar.${tool.command}`);
            return (
              <button
                key={tool.command}
                type="button"
                className="lad-tool"
                disabled={!enabled.has(tool.command)}
                onClick={() => onCommand(tool.command)}
                data-testid={tool.testId}
                aria-keyshortcuts={tool.keys}
                title={tool.shortcut ? `${label} (${tool.shortcut})` : label}
              >
                {label}
              </button>
            );
          })}
        </span>
      ))}
      <span className="graph-toolbar__group">
        <button type="button" className="lad-tool" disabled={!onSettings} onClick={() => onSettings?.()} data-testid="graph-settings">
          {t('graphChart.toolbar.settings')}
        </button>
        <button type="button" className="lad-tool" disabled={!onControl} onClick={() => onControl?.()} data-testid="graph-control">
          {t('graphChart.toolbar.control')}
        </button>
      </span>
      {status !== undefined ? <ModeFlags status={status} /> : null}
      {notice ? (
        <span className="lad-toolbar__notice" role="status">
          {notice}
        </span>
      ) : null}
    </div>
  );
}
