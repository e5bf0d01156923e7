import { useEffect, useId, useMemo, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError } from '../api/client';
import type { WatchValue } from '../api/monitor';
import type { WatchEntryReport } from '../api/monitorClient';
import { TrashIcon } from '../cpu/cpuIcons';
import { normaliseAddress, symbolsByAddress, symbolsOf, type SymbolEntry } from '../cpu/projectSymbols';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useActiveProject } from '../projects/ActiveProject';
import { useProjectContents } from '../projects/projectContents';
import { PlusIcon } from '../ui/icons';
import { isOperand, printWatchTable, type WatchLine, type WatchRow } from '../watchtables/format';
import { selectWatchTable, useSelectedWatchTable } from '../watchtables/selection';
import { createTable, freeTableName, migrateLegacyTable, watchTableFiles } from '../watchtables/tableFiles';
import { useWatchTableFile } from '../watchtables/useWatchTableFile';
import { WatchTablesBar } from '../watchtables/WatchTablesBar';
import {
  FORMAT_NAMES,
  defaultFormat,
  exampleOf,
  formatValue,
  formatsFor,
  modifyValueFor,
  type DisplayFormat,
} from './watchFormat';

const COLUMNS = ['address', 'symbol', 'format', 'monitor', 'modify'] as const;

/** What the user typed, set apart inside a translated sentence (an RTL one keeps it whole). */
const isolated = (text: string) => `\u2068${text}\u2069`;

/** Inputs and outputs can be forced (PROTOCOL.md: force is for I and Q only). */
const FORCEABLE = /^P?[IEQA][BWD]?\d/;

interface Place {
  address: string;
  symbol: string;
}

/** The address and symbol columns of an entry: one is the entry, the other from the symbol table. */
function placeOf(entry: string, symbols: Map<string, SymbolEntry>, byName: Map<string, SymbolEntry>): Place {
  const trimmed = entry.trim();
  if (/^"[^"]*"$/.test(trimmed)) {
    const name = trimmed.slice(1, -1);
    return { address: byName.get(name.toLowerCase())?.address ?? '', symbol: name };
  }
  // a variable of a symbolic DB ("Data".x): its path is the symbol, it has no one address
  if (trimmed.startsWith('"')) return { address: '', symbol: trimmed };
  const address = normaliseAddress(trimmed);
  return { address: trimmed, symbol: symbols.get(address)?.name ?? '' };
}

/** A problem of a row as the interface shows it: a catalogue code and translated text. */
interface RowProblem {
  code: string;
  text: string;
}

interface RowProps {
  row: WatchRow;
  place: Place;
  value: WatchValue | undefined;
  report: WatchEntryReport | undefined;
  /** A problem found without the CPU (an unknown symbol). */
  local: RowProblem | null;
  online: boolean;
  onChange: (patch: Partial<WatchRow>) => void;
  onRemove: () => void;
  send: (kind: 'modify' | 'force' | 'unforce', value: boolean | number | string) => void;
}

function WatchTableRow({ row, place, value, report, local, online, onChange, onRemove, send }: RowProps) {
  const { t, i18n } = useTranslation();
  const id = useId();
  const [valueProblem, setValueProblem] = useState<RowProblem | null>(null);
  const type = report?.type;
  const formats = formatsFor(type);
  const format = row.format && formats.includes(row.format) ? row.format : defaultFormat(type);
  const serverError = report?.error ?? value?.error ?? null;
  // The server explains in English; other languages show the catalogue's text for the entry.
  const problem: RowProblem | null =
    local ??
    (serverError
      ? {
          code: report?.code ?? 'WAT807',
          text: i18n.language === 'en' ? serverError : t('problems.watch_not_in_program', { entry: isolated(row.operand) }),
        }
      : valueProblem);
  const shown = value && !serverError ? formatValue(value.value, type, format) : '';
  const forced = value?.forced === true;
  const canForce = FORCEABLE.test(normaliseAddress(place.address));
  const label = place.symbol ? `${row.operand} (${place.symbol})` : row.operand;
  const draft = row.modify;

  const typed = (text: string) => {
    const parsed = modifyValueFor(text, type, format);
    if (parsed === null) {
      setValueProblem({
        code: 'WAT808',
        text: t('problems.watch_bad_value', { value: isolated(text.trim()), example: isolated(exampleOf(format)) }),
      });
    } else setValueProblem(null);
    return parsed;
  };

  const submit = (event: FormEvent) => {
    event.preventDefault();
    if (draft.trim() === '') return;
    const parsed = typed(draft);
    if (parsed !== null) send('modify', parsed);
  };

  const force = () => {
    const text = draft.trim() === '' ? String(value?.value ?? '') : draft;
    const parsed = typed(text);
    if (parsed === null) return;
    onChange({ force: text.trim() });
    send('force', parsed);
  };

  return (
    <tr
      className={problem ? 'watch-row watch-row--error' : 'watch-row'}
      data-testid="watch-row"
      data-entry={row.operand}
    >
      <td dir="ltr">
        <code>{place.address}</code>
      </td>
      <td>
        <bdi dir={place.symbol.startsWith('"') ? 'ltr' : undefined}>{place.symbol}</bdi>
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
              onChange={(event) => onChange({ format: event.target.value as DisplayFormat })}
            >
              {formats.map((item) => (
                <option key={item} value={item}>
                  {FORMAT_NAMES[item]}
                </option>
              ))}
            </select>
          </>
        ) : (
          <span className="watch-type" dir="ltr" data-testid="watch-stored-format">
            {row.format ? FORMAT_NAMES[row.format] : type && type !== 'local' ? type : ''}
          </span>
        )}
      </td>
      <td className="watch-value-cell">
        {problem ? (
          <span className="watch-error" data-testid="watch-error" role="note">
            <code className="error-code">{problem.code}</code> {problem.text}
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
        {row.comment ? (
          <span className="watch-comment" data-testid="watch-comment">
            <bdi>{row.comment}</bdi>
          </span>
        ) : null}
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
            onChange={(event) => {
              setValueProblem(null);
              onChange({ modify: event.target.value });
            }}
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
                onClick={force}
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

/** A line of the file that is no row: a comment line, or a broken line kept as written. */
function OtherLine({ line, onRemove }: { line: Exclude<WatchLine, { kind: 'row' }> | { kind: 'comment'; text: string }; onRemove: () => void }) {
  const { t } = useTranslation();
  const removeLabel = t('watch.remove', { entry: line.text });
  return (
    <tr
      className={line.kind === 'broken' ? 'watch-row watch-row--broken' : 'watch-row watch-row--comment'}
      data-testid={line.kind === 'broken' ? 'watch-broken-line' : 'watch-comment-row'}
    >
      <td colSpan={COLUMNS.length}>
        {line.kind === 'broken' ? (
          <span className="watch-error" role="note" data-testid="watch-line-error">
            {t('watchTables.brokenLine', { line: line.problem.line })}{' '}
            <code className="error-code">{line.problem.code}</code>{' '}
            {t(`problems.${line.problem.key}`, {
              ...Object.fromEntries(Object.entries(line.problem.params).map(([key, value]) => [key, isolated(String(value))])),
            })}{' '}
            <code className="watch-broken-text" dir="ltr">
              {line.text}
            </code>
          </span>
        ) : (
          <span className="watch-comment">
            <span className="visually-hidden">{t('watchTables.commentRow')}: </span>
            <bdi>{line.text}</bdi>
          </span>
        )}
      </td>
      <td className="watch-actions">
        <button type="button" className="icon-button" aria-label={removeLabel} title={removeLabel} onClick={onRemove}>
          <TrashIcon />
        </button>
      </td>
    </tr>
  );
}

/**
 * The watch table (STEP 7's "Monitor/Modify Variables"): one row per address or symbol, its
 * value from the frames in the row's display format, modify once, force and unforce inputs and
 * outputs. The rows are a watch table file of the project (`.vat`, see watchtables/format.ts):
 * several per project, chosen above the table and saved as they change.
 */
export function WatchTable() {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const fieldId = useId();
  const { projectId: activeProject } = useActiveProject();
  const { session, sources, command } = useSession();
  const projectId = session?.projectId ?? activeProject;
  const contents = useProjectContents(projectId);
  const tables = useMemo(() => watchTableFiles(contents?.files ?? []), [contents?.files]);
  const chosen = useSelectedWatchTable(projectId);
  const selected = tables.some((table) => table.name === chosen) ? chosen : (tables[0]?.name ?? null);
  const file = useWatchTableFile(projectId, selected);
  const [entry, setEntry] = useState('');
  const [addProblem, setAddProblem] = useState<RowProblem | null>(null);
  const [creating, setCreating] = useState(false);
  const [pending, setPending] = useState<readonly WatchLine[]>([]);
  const connection = useMonitor((state) => state.connection);
  const watch = useMonitor((state) => state.watch);
  const reports = useMonitor((state) => state.watchReports);

  // The rows a browser kept before tables were files move into a table file, once.
  const ready = contents?.status === 'ready';
  useEffect(() => {
    if (projectId === null || !ready) return;
    migrateLegacyTable(projectId, contents?.files ?? [])
      .then((info) => {
        if (info) selectWatchTable(projectId, info.name);
      })
      .catch(() => undefined); // kept in the browser; tried again next time
    // eslint-disable-next-line react-hooks/exhaustive-deps -- once per loaded project
  }, [projectId, ready]);

  const { table: loaded, update } = file;
  useEffect(() => {
    if (!loaded || creating || pending.length === 0) return;
    update((items) => [...items, ...pending]);
    setPending([]);
  }, [loaded, creating, pending, update]);

  const lines = useMemo(() => file.table?.lines ?? [], [file.table]);
  const entries = useMemo(
    () => [...new Set(lines.flatMap((line) => (line.kind === 'row' && line.row.operand ? [line.row.operand] : [])))],
    [lines],
  );
  useWatchEntries('watch-table', entries);
  const symbols = useMemo(() => symbolsOf(sources), [sources]);
  const byAddress = useMemo(() => symbolsByAddress(symbols), [symbols]);
  const byName = useMemo(() => new Map(symbols.map((symbol) => [symbol.name.toLowerCase(), symbol])), [symbols]);

  /** An unknown "Symbol" is found from the sources' symbol table, before any download. */
  const localProblem = (operand: string): RowProblem | null => {
    const symbol = /^"([^"]+)"$/.exec(operand.trim());
    if (!symbol || symbols.length === 0 || byName.has(symbol[1]!.toLowerCase())) return null;
    return { code: 'WAT806', text: t('problems.watch_unknown_symbol', { symbol: isolated(operand.trim()) }) };
  };

  const add = (event: FormEvent) => {
    event.preventDefault();
    const text = entry.trim();
    if (text === '' || projectId === null) return;
    if (!isOperand(text)) {
      setAddProblem({ code: 'WAT801', text: t('problems.watch_bad_operand', { operand: isolated(text) }) });
      return;
    }
    setAddProblem(null);
    const line: WatchLine = { kind: 'row', row: { operand: text, format: null, modify: '', force: '', comment: '' } };
    if (selected === null && !creating) {
      // The first row of a project without a table makes its first table, as STEP 7's VAT_1.
      setCreating(true);
      createTable(projectId, freeTableName(contents?.files ?? []), [line])
        .then(
          (info) => selectWatchTable(projectId, info.name),
          (caught: unknown) => setAddProblem({ code: asApiError(caught).code, text: errorText(asApiError(caught)) }),
        )
        .finally(() => setCreating(false));
    } else if (file.table && !creating) file.update((items) => [...items, line]);
    else setPending((items) => [...items, line]); // the table is being made or read: added then
    setEntry('');
  };

  const online = connection === 'open';
  const send = (target: string) => (kind: 'modify' | 'force' | 'unforce', value: boolean | number | string) => {
    if (kind === 'modify') void command({ type: 'modify', target, value });
    else if (kind === 'force') void command({ type: 'force', address: target, value });
    else void command({ type: 'unforce', address: target });
  };

  const patchLine = (index: number, patch: Partial<WatchRow>) =>
    file.update((items) =>
      items.map((item, at) => (at === index && item.kind === 'row' ? { kind: 'row', row: { ...item.row, ...patch } } : item)),
    );
  const removeLine = (index: number) => file.update((items) => items.filter((_, at) => at !== index));

  const modifyAll = () => {
    for (const line of lines) {
      if (line.kind !== 'row' || !line.row.operand || line.row.modify.trim() === '') continue;
      const type = reports[line.row.operand]?.type;
      const formats = formatsFor(type);
      const format = line.row.format && formats.includes(line.row.format) ? line.row.format : defaultFormat(type);
      const value = modifyValueFor(line.row.modify, type, format);
      if (value !== null) send(line.row.operand)('modify', value);
    }
  };

  if (projectId === null) {
    return (
      <div className="watch">
        <p className="watch-hint watch-empty-note">{t('watchTables.noProject')}</p>
      </div>
    );
  }

  const table = file.table;
  return (
    <div className="watch">
      <WatchTablesBar
        projectId={projectId}
        tables={tables}
        files={contents?.files ?? []}
        selected={selected}
        save={selected !== null && file.status === 'ready' ? file.save : null}
        exportText={() => (table ? printWatchTable(table) : null)}
      />
      {file.save.status === 'conflict' ? (
        <div className="watch-conflict" role="alert">
          <span>{t('watchTables.conflict')}</span>
          <button type="button" className="button button--small" onClick={file.reload}>
            {t('watchTables.takeTheirs')}
          </button>
          <button type="button" className="button button--small" onClick={file.overwrite}>
            {t('watchTables.keepMine')}
          </button>
        </div>
      ) : null}
      {selected !== null && file.status === 'error' && file.error ? (
        <p className="watch-error" role="alert">
          <code className="error-code">{file.error.code}</code> {errorText(file.error)}
        </p>
      ) : null}
      {selected !== null && file.status === 'loading' ? <p className="watch-hint">{t('watchTables.loading')}</p> : null}
      {file.status !== 'error' || selected === null ? (
        <>
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
              {lines.length === 0 ? (
                <tr className="data-table__empty" data-testid="watch-empty">
                  <td colSpan={COLUMNS.length + 1}>{t('watch.empty')}</td>
                </tr>
              ) : (
                lines.map((line, index) =>
                  line.kind === 'broken' ? (
                    <OtherLine key={`${index}:broken`} line={line} onRemove={() => removeLine(index)} />
                  ) : !line.row.operand ? (
                    <OtherLine
                      key={`${index}:comment`}
                      line={{ kind: 'comment', text: line.row.comment }}
                      onRemove={() => removeLine(index)}
                    />
                  ) : (
                    <WatchTableRow
                      key={`${index}:${line.row.operand}`}
                      row={line.row}
                      place={placeOf(line.row.operand, byAddress, byName)}
                      value={watch[line.row.operand]}
                      report={reports[line.row.operand]}
                      local={localProblem(line.row.operand)}
                      online={online}
                      onChange={(patch) => patchLine(index, patch)}
                      onRemove={() => removeLine(index)}
                      send={send(line.row.operand)}
                    />
                  ),
                )
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
              onChange={(event) => {
                setAddProblem(null);
                setEntry(event.target.value);
              }}
            />
            <button type="submit" className="button button--small" data-testid="watch-add" disabled={entry.trim() === ''}>
              <PlusIcon />
              {t('watch.add')}
            </button>
            <button
              type="button"
              className="button button--small"
              data-testid="watch-modify-all"
              disabled={!online}
              title={t('watchTables.modifyAllTitle')}
              onClick={modifyAll}
            >
              {t('watchTables.modifyAll')}
            </button>
            {addProblem ? (
              <span className="watch-error" role="alert" data-testid="watch-add-error">
                <code className="error-code">{addProblem.code}</code> {addProblem.text}
              </span>
            ) : !session ? (
              <span className="watch-hint">{t('watch.noSession')}</span>
            ) : null}
          </form>
        </>
      ) : null}
    </div>
  );
}
