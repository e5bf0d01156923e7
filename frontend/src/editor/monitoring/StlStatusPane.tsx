import { useEffect, useRef } from 'react';
import { useTranslation } from 'react-i18next';
import type { editor as MonacoEditor } from 'monaco-editor/editor/editor.api';
import type { BlockStatus } from '../../api/monitor';
import type { MonitorClient } from '../../api/monitorClient';
import { usePersistentFlag } from '../../ui/usePersistentState';
import { sameBlockName } from './blockAtLine';
import { StatusColumnPane } from './statusColumnPane';
import { STATUS_COLUMNS, statusRows, type AccuFormat } from './statusColumns';

interface StlStatusPaneProps {
  editor: MonacoEditor.IStandaloneCodeEditor;
  client: MonitorClient;
  /** The block monitoring opened; frames of another block are not shown. */
  block: string | null;
  lineHeight: number;
}

/** The register mnemonics stay as the CPU names them; the words are translated (full names in the titles). */
const HEADINGS: Partial<Record<(typeof STATUS_COLUMNS)[number]['id'], string>> = { rlo: 'RLO', sta: 'STA', accu2: 'ACCU 2' };

const statusOf = (state: { block: BlockStatus | null }, block: string | null) =>
  block !== null && state.block && sameBlockName(state.block.block, block) ? state.block : null;

/**
 * STEP 7's STL status columns to the right of the text: RLO, STA, STANDARD (ACCU1), ACCU2 and
 * the status word of each line that ran, aligned with the editor's lines. The frames and the
 * scrolling redraw the visible rows in place (see StatusColumnPane), outside React.
 */
export function StlStatusPane({ editor, client, block, lineHeight }: StlStatusPaneProps) {
  const { t } = useTranslation();
  const [hex, setHex] = usePersistentFlag('nasaq.debug.accuHex', false);
  const format: AccuFormat = hex ? 'hex' : 'dec';
  const bodyRef = useRef<HTMLDivElement>(null);
  const scanRef = useRef<HTMLSpanElement>(null);

  useEffect(() => {
    const body = bodyRef.current;
    if (!body) return;
    const pane = new StatusColumnPane(body, lineHeight);
    let shown = statusOf(client.getState(), block);
    let rows = statusRows(shown, format);
    let frame: number | null = null;
    const draw = () => {
      frame = null;
      const count = pane.render(rows, editor);
      body.dataset.rows = String(count);
      if (scanRef.current) scanRef.current.textContent = shown ? t('debug.status.scan', { scan: shown.scan }) : t('debug.status.waiting');
    };
    const schedule = () => {
      if (frame === null) frame = requestAnimationFrame(draw);
    };
    const unsubscribe = client.subscribe(() => {
      const next = statusOf(client.getState(), block);
      if (next === shown) return;
      shown = next;
      rows = statusRows(shown, format);
      schedule();
    });
    const subscriptions = [editor.onDidScrollChange(schedule), editor.onDidLayoutChange(schedule), editor.onDidChangeModelContent(schedule)];
    draw();
    return () => {
      if (frame !== null) cancelAnimationFrame(frame);
      unsubscribe();
      subscriptions.forEach((subscription) => subscription.dispose());
      pane.clear();
    };
  }, [editor, client, block, format, lineHeight, t]);

  return (
    <>
      <div className="stl-status__bar" dir="auto" data-testid="stl-status-bar">
        <span className="stl-status__block">{t('debug.status.title', { block: block ?? '–' })}</span>
        <span className="stl-status__scan" ref={scanRef} />
        <button
          type="button"
          className="stl-status__format"
          data-testid="stl-status-format"
          aria-label={t('debug.status.format')}
          title={t('debug.status.format')}
          aria-pressed={hex}
          onClick={() => setHex(!hex)}
        >
          {format === 'dec' ? t('debug.status.dec') : t('debug.status.hex')}
        </button>
      </div>
      <div className="stl-status" dir="ltr" data-testid="stl-status" aria-label={t('debug.status.label')} role="group">
        <div className="stl-status__header">
          {STATUS_COLUMNS.map((column) => (
            <span
              key={column.id}
              className={`stl-status__cell stl-status__cell--${column.id}`}
              title={t(`debug.columns.${column.id}`)}
              data-testid={`stl-status-head-${column.id}`}
            >
              {HEADINGS[column.id] ?? t(`debug.columns.short.${column.id}`)}
            </span>
          ))}
        </div>
        <div className="stl-status__body" ref={bodyRef} data-testid="stl-status-body" />
      </div>
    </>
  );
}
