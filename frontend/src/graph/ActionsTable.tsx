/**
 * The action table of one step, as in S7-Graph's single-step view: one row per action with its
 * event, qualifier (with the C suffix), operand, value and comment; rows added, deleted and
 * moved. Each row is checked as it is written ({@link checkAction}, the server checker's rules):
 * a finding marks its cell and is shown under the row with its GRA code; the row is kept as the
 * user wrote it (the FB does not compile until it is corrected, as in S7-Graph).
 *
 * The event and qualifier fields offer what goes with the other (the qualifiers legal after the
 * row's event, the events its qualifier takes); anything can be typed, and an illegal pair is
 * kept and marked. A word that is no event or qualifier at all stays in its field, marked, and
 * is not written to the model (it has no room for it) until corrected or dropped with Escape.
 */
import { useCallback, useMemo, useState, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { ElementStatus } from '../api/monitor';
import { OperandEditor, type Complete } from '../lad/OperandEditor';
import { listCompleter } from '../lad/operands';
import { checkAction, EVENTS, legalEvents, legalQualifiers, parseQualifier, qualifierText, valueExample, type Event, type RowProblem } from './actionRules';
import type { Action, Step } from './model';

export interface ActionsTableProps {
  step: Step;
  /** Every step of the block (ON/OFF name them). */
  steps: readonly Step[];
  editable: boolean;
  /** Replaces the step's rows (one undo step, labelled). */
  onChange: (actions: Action[], label: string) => void;
  /** Completion of operands (symbols, the FB's members, DB members). */
  complete: Complete;
  /** Online: the rows' elements (`S<n>/A<k>`), null offline. */
  values: ReadonlyMap<string, ElementStatus> | null;
  formatValue: (value: unknown) => string;
}

/** The smallest free id `a<n>` in the rows. */
export function newActionId(actions: readonly Action[]): string {
  const used = new Set(actions.map((action) => action.id));
  let n = actions.length + 1;
  for (let k = 1; k <= actions.length + 1; k += 1) {
    if (!used.has(`a${k}`)) {
      n = k;
      break;
    }
  }
  return `a${n}`;
}

/** The rows with row `k` (0-based) moved by `delta`; null when it cannot move. */
export function moveRow(actions: readonly Action[], k: number, delta: -1 | 1): Action[] | null {
  const to = k + delta;
  if (k < 0 || k >= actions.length || to < 0 || to >= actions.length) return null;
  const next = [...actions];
  const [row] = next.splice(k, 1);
  if (row) next.splice(to, 0, row);
  return next;
}

type Cell = 'event' | 'qualifier' | 'operand' | 'time';

export function ActionsTable({ step, steps, editable, onChange, complete, values, formatValue }: ActionsTableProps) {
  const { t } = useTranslation();
  /** Qualifiers typed that are none (kept in their field until corrected), by action id. */
  const [drafts, setDrafts] = useState<ReadonlyMap<string, string>>(new Map());
  /** Bumped to reset a field to the model (after a commit or Escape). */
  const [generation, setGeneration] = useState(0);
  const actions = step.actions;
  const problems = useMemo(() => actions.map((action) => checkAction(action, step, steps)), [actions, step, steps]);
  const message = useCallback((problem: RowProblem) => t(`problems.${problem.key}`, problem.params), [t]);

  const change = useCallback(
    (k: number, patch: Partial<Action>, label: string) => {
      const row = actions[k];
      if (!row) return;
      const next = { ...row, ...patch };
      if ((Object.keys(patch) as (keyof Action)[]).every((key) => row[key] === next[key])) return;
      onChange(
        actions.map((action, j) => (j === k ? next : action)),
        label,
      );
    },
    [actions, onChange],
  );

  const setDraft = (id: string, text: string | null) =>
    setDrafts((current) => {
      const next = new Map(current);
      if (text === null) next.delete(id);
      else next.set(id, text);
      return next;
    });

  const commitQualifier = (k: number, action: Action, typed: string) => {
    const parsed = parseQualifier(typed);
    if (!parsed) {
      if (typed.trim() === qualifierText(action.qualifier, action.interlock)) setDraft(action.id, null);
      else setDraft(action.id, typed);
      return;
    }
    setDraft(action.id, null);
    change(k, parsed, t('graphStep.undo.qualifier'));
  };

  const commitEvent = (k: number, action: Action, typed: string) => {
    const word = typed.trim().toUpperCase();
    const key = `${action.id}:event`;
    if (word !== '' && !(EVENTS as readonly string[]).includes(word)) {
      setDraft(key, typed);
      return;
    }
    setDraft(key, null);
    change(k, { event: word === '' ? null : (word as Event) }, t('graphStep.undo.event'));
  };

  const add = () => {
    const row: Action = { id: newActionId(actions), event: null, qualifier: 'N', interlock: false, operand: '', time: null, comment: '' };
    onChange([...actions, row], t('graphStep.undo.addAction'));
  };
  const remove = (k: number) => {
    const row = actions[k];
    if (row) setDraft(row.id, null);
    onChange(
      actions.filter((_, j) => j !== k),
      t('graphStep.undo.deleteAction'),
    );
  };
  const move = (k: number, delta: -1 | 1) => {
    const next = moveRow(actions, k, delta);
    if (next) onChange(next, t('graphStep.undo.moveAction'));
  };

  const onRowKey = (k: number, event: KeyboardEvent<HTMLTableRowElement>) => {
    if (!event.altKey || (event.key !== 'ArrowUp' && event.key !== 'ArrowDown')) return;
    event.preventDefault();
    move(k, event.key === 'ArrowUp' ? -1 : 1);
  };

  const stepOptions = useMemo(() => steps.flatMap((s) => [{ label: `${s.name}  (S${s.number})`, insert: s.name }]), [steps]);
  const completeFor = (action: Action): Complete => {
    if (action.qualifier === 'ON' || action.qualifier === 'OFF') {
      return listCompleter(action.qualifier === 'OFF' ? [...stepOptions, { label: 'S_ALL', insert: 'S_ALL' }] : stepOptions);
    }
    return complete;
  };

  return (
    <div className="graph-actions" data-testid="graph-actions">
      <table className="graph-actions__table" aria-label={t('graphStep.actions.label', { step: step.name })}>
        <thead>
          <tr>
            <th scope="col">#</th>
            <th scope="col">{t('graphStep.actions.event')}</th>
            <th scope="col">{t('graphStep.actions.qualifier')}</th>
            <th scope="col">{t('graphStep.actions.operand')}</th>
            <th scope="col">{t('graphStep.actions.time')}</th>
            <th scope="col">{t('graphStep.actions.comment')}</th>
            {values ? <th scope="col">{t('graphStep.actions.value')}</th> : null}
            <th scope="col">
              <span className="visually-hidden">{t('graphStep.actions.rowTools')}</span>
            </th>
          </tr>
        </thead>
        <tbody>
          {actions.length === 0 ? (
            <tr>
              <td colSpan={values ? 8 : 7} className="graph-actions__empty">
                {t('graphStep.actions.none')}
              </td>
            </tr>
          ) : null}
          {actions.map((action, k) => {
            const number = k + 1;
            const found = problems[k] ?? [];
            const draft = drafts.get(action.id);
            const eventDraft = drafts.get(`${action.id}:event`);
            const eventShown = eventDraft ?? action.event ?? '';
            const at = (cell: Cell) => found.filter((problem) => problem.cell === cell);
            const titleOf = (cell: Cell) => {
              const here = at(cell);
              return here.length > 0 ? here.map((problem) => `${problem.code}: ${message(problem)}`).join('\n') : undefined;
            };
            const invalid = (cell: Cell) => at(cell).some((problem) => problem.severity === 'error');
            const qualifierShown = draft ?? qualifierText(action.qualifier, action.interlock);
            const qualifierProblem = draft !== undefined ? t('graphStep.actions.unknownQualifier', { typed: draft }) : titleOf('qualifier');
            const events = legalEvents(action.qualifier, action.interlock);
            const value = values?.get(`S${step.number}/A${number}`);
            const example = valueExample(action.qualifier);
            return [
              <tr key={action.id} data-testid={`graph-action-${number}`} className={found.some((p) => p.severity === 'error') || draft !== undefined || eventDraft !== undefined ? 'graph-actions__row graph-actions__row--error' : 'graph-actions__row'} onKeyDown={(event) => onRowKey(k, event)}>
                <td className="graph-actions__number">{number}</td>
                <td aria-invalid={invalid('event') || eventDraft !== undefined ? true : undefined}>
                  <input
                    key={`e-${action.id}-${eventShown}-${generation}`}
                    className="input graph-actions__event"
                    aria-label={t('graphStep.actions.event')}
                    list={`graph-events-${step.number}-${number}`}
                    defaultValue={eventShown}
                    placeholder={t('graphStep.actions.noEvent')}
                    readOnly={!editable}
                    spellCheck={false}
                    autoComplete="off"
                    dir="ltr"
                    aria-invalid={invalid('event') || eventDraft !== undefined ? true : undefined}
                    title={eventDraft !== undefined ? t('graphStep.actions.unknownEvent', { typed: eventDraft }) : titleOf('event')}
                    onBlur={(event) => commitEvent(k, action, event.target.value)}
                    onKeyDown={(event) => {
                      if (event.key === 'Enter') commitEvent(k, action, event.currentTarget.value);
                      else if (event.key === 'Escape') {
                        setDraft(`${action.id}:event`, null);
                        setGeneration((g) => g + 1);
                      }
                    }}
                  />
                  <datalist id={`graph-events-${step.number}-${number}`}>
                    {events.filter((event): event is Event => event !== null).map((event) => (
                      <option key={event} value={event} />
                    ))}
                  </datalist>
                </td>
                <td aria-invalid={invalid('qualifier') || draft !== undefined ? true : undefined}>
                  <input
                    key={`q-${action.id}-${qualifierShown}-${generation}`}
                    className="input graph-actions__qualifier"
                    aria-label={t('graphStep.actions.qualifier')}
                    list={`graph-qualifiers-${step.number}-${number}`}
                    defaultValue={qualifierShown}
                    readOnly={!editable}
                    spellCheck={false}
                    autoComplete="off"
                    dir="ltr"
                    aria-invalid={invalid('qualifier') || draft !== undefined ? true : undefined}
                    title={qualifierProblem}
                    onBlur={(event) => commitQualifier(k, action, event.target.value)}
                    onKeyDown={(event) => {
                      if (event.key === 'Enter') commitQualifier(k, action, event.currentTarget.value);
                      else if (event.key === 'Escape') {
                        setDraft(action.id, null);
                        setGeneration((g) => g + 1);
                      }
                    }}
                  />
                  <datalist id={`graph-qualifiers-${step.number}-${number}`}>
                    {legalQualifiers(action.event).map((q) => (
                      <option key={q} value={q} />
                    ))}
                  </datalist>
                </td>
                <td aria-invalid={invalid('operand') ? true : undefined} className="graph-actions__operand">
                  {editable ? (
                    <OperandEditor
                      key={`o-${action.id}-${action.operand}-${generation}`}
                      initial={action.operand}
                      label={t('graphStep.actions.operand')}
                      complete={completeFor(action)}
                      autoFocus={false}
                      problem={titleOf('operand') ?? null}
                      onCommit={(text) => {
                        setGeneration((g) => g + 1);
                        change(k, { operand: text }, t('graphStep.undo.operand'));
                      }}
                      onCancel={() => setGeneration((g) => g + 1)}
                    />
                  ) : (
                    <input className="input" aria-label={t('graphStep.actions.operand')} value={action.operand} readOnly dir="ltr" aria-invalid={invalid('operand') ? true : undefined} title={titleOf('operand')} />
                  )}
                </td>
                <td aria-invalid={invalid('time') ? true : undefined}>
                  <input
                    key={`t-${action.id}-${action.time ?? ''}-${generation}`}
                    className="input graph-actions__time"
                    aria-label={t('graphStep.actions.time')}
                    defaultValue={action.time ?? ''}
                    placeholder={example ?? ''}
                    readOnly={!editable}
                    spellCheck={false}
                    dir="ltr"
                    aria-invalid={invalid('time') ? true : undefined}
                    title={titleOf('time')}
                    onBlur={(event) => change(k, { time: event.target.value.trim() || null }, t('graphStep.undo.time'))}
                    onKeyDown={(event) => {
                      if (event.key === 'Enter') change(k, { time: event.currentTarget.value.trim() || null }, t('graphStep.undo.time'));
                      else if (event.key === 'Escape') setGeneration((g) => g + 1);
                    }}
                  />
                </td>
                <td>
                  <input
                    key={`c-${action.id}-${action.comment}-${generation}`}
                    className="input graph-actions__comment"
                    aria-label={t('graphStep.actions.comment')}
                    defaultValue={action.comment}
                    readOnly={!editable}
                    dir="auto"
                    onBlur={(event) => change(k, { comment: event.target.value.replace(/\n/g, ' ') }, t('graphStep.undo.comment'))}
                    onKeyDown={(event) => {
                      if (event.key === 'Enter') change(k, { comment: event.currentTarget.value.replace(/\n/g, ' ') }, t('graphStep.undo.comment'));
                    }}
                  />
                </td>
                {values ? (
                  <td className="graph-actions__value" data-testid={`graph-action-value-${number}`} data-out={value?.out === undefined || value.out === null ? undefined : String(value.out)} dir="ltr">
                    {value ? formatValue(value.value) : '—'}
                  </td>
                ) : null}
                <td className="graph-actions__tools">
                  <button type="button" className="button button--small" disabled={!editable || k === 0} onClick={() => move(k, -1)} aria-label={t('graphStep.actions.up', { number })} title={t('graphStep.actions.up', { number })} data-testid={`graph-action-up-${number}`}>
                    ↑
                  </button>
                  <button type="button" className="button button--small" disabled={!editable || k === actions.length - 1} onClick={() => move(k, 1)} aria-label={t('graphStep.actions.down', { number })} title={t('graphStep.actions.down', { number })} data-testid={`graph-action-down-${number}`}>
                    ↓
                  </button>
                  <button type="button" className="button button--small" disabled={!editable} onClick={() => remove(k)} aria-label={t('graphStep.actions.delete', { number })} title={t('graphStep.actions.delete', { number })} data-testid={`graph-action-delete-${number}`}>
                    ✕
                  </button>
                </td>
              </tr>,
              found.length > 0 || draft !== undefined || eventDraft !== undefined ? (
                <tr key={`${action.id}-problems`} className="graph-actions__problems" data-testid={`graph-action-problems-${number}`}>
                  <td />
                  <td colSpan={values ? 7 : 6}>
                    <ul>
                      {eventDraft !== undefined ? <li className="graph-actions__problem graph-actions__problem--error">{t('graphStep.actions.unknownEvent', { typed: eventDraft })}</li> : null}
                      {draft !== undefined ? <li className="graph-actions__problem graph-actions__problem--error">{t('graphStep.actions.unknownQualifier', { typed: draft })}</li> : null}
                      {found.map((problem, j) => (
                        <li key={j} className={`graph-actions__problem graph-actions__problem--${problem.severity}`}>
                          <code className="error-code">{problem.code}</code> {message(problem)}
                        </li>
                      ))}
                    </ul>
                  </td>
                </tr>
              ) : null,
            ];
          })}
        </tbody>
      </table>
      <button type="button" className="button button--small" disabled={!editable} onClick={add} data-testid="graph-action-add">
        {t('graphStep.actions.add')}
      </button>
    </div>
  );
}
