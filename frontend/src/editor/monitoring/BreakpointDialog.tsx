import { useEffect, useId, useRef, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { BreakpointReport } from '../../api/monitorClient';
import { useMonitor } from '../../cpu/SessionContext';
import { useProblemText } from '../../cpu/useProblemText';
import { Dialog } from '../../ui/Dialog';
import { breakpoints as defaultStore, breakpointKey, type BreakpointStore } from './breakpointStore';
import { nextCodeLine } from './nextCodeLine';

interface BreakpointDialogProps {
  projectId: number;
  file: string;
  /** The source line, or with `block` the network number in that LAD/FBD block. */
  line: number;
  block?: string;
  onClose: () => void;
  store?: BreakpointStore;
}

/**
 * Sets, changes or removes the breakpoint of a line and its condition. After saving it waits for
 * the server's answer: a refused condition (MON612) or a line without code (MON604) is shown in
 * the interface language, the latter with the offer to move the breakpoint to the next line with
 * code. Without a session it just saves.
 */
export function BreakpointDialog({ projectId, file, line, block, onClose, store = defaultStore }: BreakpointDialogProps) {
  const { t } = useTranslation();
  const problemText = useProblemText();
  const inputId = useId();
  const [at, setAt] = useState(line);
  const existing = store.find(projectId, file, at, block);
  const [condition, setCondition] = useState(existing?.condition ?? '');
  const [enabled, setEnabled] = useState(existing?.enabled ?? true);
  const key = breakpointKey(projectId, file, at, block);
  const report = useMonitor((state) => state.breakpoints[key]);
  const online = useMonitor((state) => state.connection === 'open');
  /** The report there was when the user saved: the answer to the save is a newer one. */
  const [waitingSince, setWaitingSince] = useState<BreakpointReport | undefined | null>(null);
  const inputRef = useRef<HTMLInputElement>(null);

  const answered = waitingSince !== null && report !== waitingSince && report?.state !== 'pending';
  useEffect(() => {
    if (answered && report?.state === 'set') onClose();
  }, [answered, report, onClose]);

  const shownProblem = report?.state === 'refused' && (waitingSince === null || answered) ? report.problem : null;
  const moveTo = block ? null : nextCodeLine(shownProblem);

  function save(event?: FormEvent) {
    event?.preventDefault();
    const text = condition.trim() || null;
    const unchanged = existing && existing.condition === text && existing.enabled === enabled && report?.state !== 'refused';
    store.put(projectId, file, at, { condition: text, enabled }, block);
    if (!online || !enabled || unchanged) {
      onClose();
      return;
    }
    setWaitingSince(report);
  }

  function move() {
    if (moveTo === null) return;
    if (!store.find(projectId, file, at)) store.put(projectId, file, at, { condition: condition.trim() || null, enabled });
    store.move(projectId, file, at, moveTo);
    setAt(moveTo);
    setWaitingSince(undefined);
  }

  return (
    <Dialog
      title={block ? t('lad.breakpointTitle', { block, network: at }) : t('debug.dialog.title', { line: at })}
      onClose={onClose}
      testId="breakpoint-dialog"
      initialFocus={inputRef}
      footer={
        <>
          {existing ? (
            <button
              type="button"
              className="button"
              data-testid="breakpoint-remove"
              onClick={() => {
                store.remove(projectId, file, at, block);
                onClose();
              }}
            >
              {t('debug.dialog.remove')}
            </button>
          ) : null}
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button type="submit" form={`${inputId}-form`} className="button button--primary" data-testid="breakpoint-save">
            {t('debug.dialog.save')}
          </button>
        </>
      }
    >
      <form id={`${inputId}-form`} className="breakpoint-dialog" onSubmit={save}>
        <p className="breakpoint-dialog__where" dir="ltr">
          <code>{block ? `${file}: ${block}, ${t('lad.network.name', { number: at })}` : `${file}:${at}`}</code>
        </p>
        <label htmlFor={inputId}>{t('debug.dialog.condition')}</label>
        <input
          id={inputId}
          ref={inputRef}
          className="input breakpoint-dialog__input"
          dir="ltr"
          spellCheck={false}
          autoComplete="off"
          placeholder="#count > 10"
          value={condition}
          onChange={(event) => setCondition(event.target.value)}
          data-testid="breakpoint-condition"
        />
        <p className="breakpoint-dialog__hint">{t('debug.dialog.hint')}</p>
        <label className="breakpoint-dialog__enabled">
          <input type="checkbox" checked={enabled} onChange={(event) => setEnabled(event.target.checked)} data-testid="breakpoint-enabled" />
          {t('debug.dialog.enabled')}
        </label>
        {waitingSince !== null && !answered ? (
          <p role="status" className="breakpoint-dialog__pending">
            {t('debug.dialog.pending')}
          </p>
        ) : null}
        {shownProblem ? (
          <div role="alert" className="breakpoint-dialog__error" data-testid="breakpoint-error">
            <p>
              <code className="error-code">{shownProblem.code}</code> <span>{problemText(shownProblem)}</span>
            </p>
            {moveTo !== null ? (
              <button type="button" className="button button--small" data-testid="breakpoint-move" onClick={move}>
                {t('debug.dialog.move', { line: moveTo })}
              </button>
            ) : null}
          </div>
        ) : null}
      </form>
    </Dialog>
  );
}
