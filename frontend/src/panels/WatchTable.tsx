import { useId, useMemo, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { WatchValue } from '../api/monitor';
import type { WatchEntryReport } from '../api/monitorClient';
import { TrashIcon } from '../cpu/cpuIcons';
import { normaliseAddress, symbolsByAddress, symbolsOf, type SymbolEntry } from '../cpu/projectSymbols';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import { useActiveProject } from '../projects/ActiveProject';
import { PlusIcon } from '../ui/icons';
import { useStoredList } from './useStoredList';
import {
  FORMAT_NAMES,
  defaultFormat,
  formatValue,
  formatsFor,
  parseModifyValue,
  type DisplayFormat,
} from './watchFormat';

const COLUMNS = ['address', 'symbol', 'format', 'monitor', 'modify'] as const;
const FORMATS: readonly DisplayFormat[] = ['bool', 'bin', 'hex', 'dec', 'real', 'char', 'time'];

export interface WatchRow {
  entry: string;
  /** Chosen by the user; null: the default for the entry's type. */
  format: DisplayFormat | null;
}

function isRow(item: unknown): item is WatchRow {
  const row = item as WatchRow | null;
  return (
    typeof row === 'object' &&
    row !== null &&
    typeof row.entry === 'string' &&
    (row.format === null || FORMATS.includes(row.format))
  );
}

/** Where the watch table of a project is remembered. */
export const watchStorageKey = (projectId: number | null) => `nasaq.watch.${projectId ?? 'none'}`;

/** Inputs and outputs can be forced (PROTOCOL.md: force is for I and Q only). */
const FORCEABLE = /^P?[IEQA][BWD]?\d/;

interface Place {
  address: string;
  symbol: string;
}

/** The address and symbol columns of an entry: one is the entry, the other from the symbol table. */
function placeOf(entry: string, symbols: Map<string, SymbolEntry>, byName: Map<string, SymbolEntry>): Place {
  const trimmed = entry.trim();
  if (trimmed.startsWith('"')) {
    const name = trimmed.replace(/^"|"$/g, '');
    return { address: byName.get(name.toLowerCase())?.address ?? '', symbol: name };
  }
  const address = normaliseAddress(trimmed);
  return { address: trimmed, symbol: symbols.get(address)?.name ?? '' };
}

interface RowProps {
  row: WatchRow;
  place: Place;
  value: WatchValue | undefined;
  report: WatchEntryReport | undefined;
  online: boolean;
  onFormat: (format: DisplayFormat) => void;
  onRemove: () => void;
  send: (kind: 'modify' | 'force' | 'unforce', value: string) => void;
}

function WatchTableRow({ row, place, value, report, online, onFormat, onRemove, send }: RowProps) {
  const { t } = useTranslation();
  const id = useId();
  const [draft, setDraft] = useState('');
  const type = report?.type;
  const formats = formatsFor(type);
  const format = row.format && formats.includes(row.format) ? row.format : defaultFormat(type);
  const error = report?.error ?? value?.error ?? null;
  const shown = value && !error ? formatValue(value.value, type, format) : '';
  const forced = value?.forced === true;
  const canForce = FORCEABLE.test(normaliseAddress(place.address));
  const label = place.symbol ? `${row.entry} (${place.symbol})` : row.entry;

  const submit = (event: FormEvent) => {
    event.preventDefault();
    if (draft.trim() !== '') send('modify', draft);
  };

  return (
    <tr className={error ? 'watch-row watch-row--error' : 'watch-row'} data-testid="watch-row" data-entry={row.entry}>
      <td dir="ltr">
        <code>{place.address}</code>
      </td>
      <td>
        <bdi>{place.symbol}</bdi>
      </td>
      <td>
        {formats.length > 0 ? (
          <>
            <label htmlFor={`${id}-format`} className="visually-hidden">
              {t('watch.formatOf', { entry: label })}
            </label>
            <select
              id={`${id}-format`}
              className="select select--compact"
              data-testid="watch-format"
              value={format}
              onChange={(event) => onFormat(event.target.value as DisplayFormat)}
            >
              {formats.map((item) => (
                <option key={item} value={item}>
                  {FORMAT_NAMES[item]}
                </option>
              ))}
            </select>
          </>
        ) : (
          <span className="watch-type" dir="ltr">
            {type && type !== 'local' ? type : ''}
          </span>
        )}
      </td>
      <td className="watch-value-cell">
        {error ? (
          <span className="watch-error" data-testid="watch-error" role="note">
            {report?.code ? <code className="error-code">{report.code}</code> : null} {error}
          </span>
        ) : (
          <>
            <code className="watch-value" data-testid="watch-value" dir="ltr">
              {shown}
            </code>
            {forced ? (
              <span className="force-marker" data-testid="watch-forced" title={t('watch.forced')}>
                <span aria-hidden="true">F</span>
                <span className="visually-hidden">{t('watch.forced')}</span>
              </span>
            ) : null}
          </>
        )}
      </td>
      <td>
        <form className="watch-modify" onSubmit={submit}>
          <label htmlFor={`${id}-modify`} className="visually-hidden">
            {t('watch.modifyValueOf', { entry: label })}
          </label>
          <input
            id={`${id}-modify`}
            className="input input--compact"
            data-testid="watch-modify-value"
            dir="ltr"
            value={draft}
            placeholder={type === 'BOOL' ? 'TRUE' : ''}
            onChange={(event) => setDraft(event.target.value)}
          />
          <button
            type="submit"
            className="button button--small"
            data-testid="watch-modify"
            disabled={!online || draft.trim() === ''}
            aria-label={t('watch.modifyOf', { entry: label })}
            title={t('watch.modifyOf', { entry: label })}
          >
            {t('watch.modify')}
          </button>
          {canForce ? (
            forced ? (
              <button
                type="button"
                className="button button--small button--force"
                data-testid="watch-unforce"
                disabled={!online}
                aria-label={t('watch.unforceOf', { entry: label })}
                title={t('watch.unforceOf', { entry: label })}
                onClick={() => send('unforce', '')}
              >
                {t('watch.unforce')}
              </button>
            ) : (
              <button
                type="button"
                className="button button--small"
                data-testid="watch-force"
                disabled={!online || (draft.trim() === '' && (value?.value ?? null) === null)}
                aria-label={t('watch.forceOf', { entry: label })}
                title={t('watch.forceOf', { entry: label })}
                onClick={() => send('force', draft.trim() === '' ? String(value?.value ?? '') : draft)}
              >
                {t('watch.force')}
              </button>
            )
          ) : null}
        </form>
      </td>
      <td className="watch-actions">
        <button
          type="button"
          className="icon-button"
          data-testid="watch-remove"
          aria-label={t('watch.remove', { entry: label })}
          title={t('watch.remove', { entry: label })}
          onClick={onRemove}
        >
          <TrashIcon />
        </button>
      </td>
    </tr>
  );
}

/**
 * The watch table (STEP 7's "Monitor/Modify Variables"): one row per address or symbol, its
 * value from the frames in the row's display format, modify once, force and unforce inputs and
 * outputs. Each project keeps its own rows.
 */
export function WatchTable() {
  const { t } = useTranslation();
  const fieldId = useId();
  const { projectId } = useActiveProject();
  const { session, sources, command } = useSession();
  const [rows, setRows] = useStoredList(watchStorageKey(session?.projectId ?? projectId), isRow);
  const [entry, setEntry] = useState('');
  const connection = useMonitor((state) => state.connection);
  const watch = useMonitor((state) => state.watch);
  const reports = useMonitor((state) => state.watchReports);

  const entries = useMemo(() => rows.map((row) => row.entry), [rows]);
  useWatchEntries('watch-table', entries);
  const symbols = useMemo(() => symbolsOf(sources), [sources]);
  const byAddress = useMemo(() => symbolsByAddress(symbols), [symbols]);
  const byName = useMemo(() => new Map(symbols.map((symbol) => [symbol.name.toLowerCase(), symbol])), [symbols]);

  const add = (event: FormEvent) => {
    event.preventDefault();
    const text = entry.trim();
    if (text === '') return;
    setRows((items) => (items.some((row) => row.entry === text) ? items : [...items, { entry: text, format: null }]));
    setEntry('');
  };

  const online = connection === 'open';
  const send = (target: string) => (kind: 'modify' | 'force' | 'unforce', value: string) => {
    if (kind === 'modify') void command({ type: 'modify', target, value: parseModifyValue(value) });
    else if (kind === 'force') void command({ type: 'force', address: target, value: parseModifyValue(value) });
    else void command({ type: 'unforce', address: target });
  };

  return (
    <div className="watch">
      <table className="data-table" data-testid="watch-table">
        <caption className="visually-hidden">{t('watch.caption')}</caption>
        <thead>
          <tr>
            {COLUMNS.map((column) => (
              <th key={column} scope="col" className={`data-table__col--${column}`}>
                {t(`watch.columns.${column}`)}
              </th>
            ))}
            <th scope="col" className="data-table__col--actions">
              <span className="visually-hidden">{t('watch.columns.actions')}</span>
            </th>
          </tr>
        </thead>
        <tbody>
          {rows.length === 0 ? (
            <tr className="data-table__empty" data-testid="watch-empty">
              <td colSpan={COLUMNS.length + 1}>{t('watch.empty')}</td>
            </tr>
          ) : (
            rows.map((row) => (
              <WatchTableRow
                key={row.entry}
                row={row}
                place={placeOf(row.entry, byAddress, byName)}
                value={watch[row.entry]}
                report={reports[row.entry]}
                online={online}
                onFormat={(format) =>
                  setRows((items) => items.map((item) => (item.entry === row.entry ? { ...item, format } : item)))
                }
                onRemove={() => setRows((items) => items.filter((item) => item.entry !== row.entry))}
                send={send(row.entry)}
              />
            ))
          )}
        </tbody>
      </table>
      <form className="watch-add" onSubmit={add}>
        <label htmlFor={fieldId} className="visually-hidden">
          {t('watch.addLabel')}
        </label>
        <input
          id={fieldId}
          className="input input--compact"
          data-testid="watch-add-entry"
          dir="ltr"
          placeholder={t('watch.addPlaceholder')}
          value={entry}
          onChange={(event) => setEntry(event.target.value)}
        />
        <button type="submit" className="button button--small" data-testid="watch-add" disabled={entry.trim() === ''}>
          <PlusIcon />
          {t('watch.add')}
        </button>
        {!session ? <span className="watch-hint">{t('watch.noSession')}</span> : null}
      </form>
    </div>
  );
}
