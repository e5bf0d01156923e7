import { useId, useState, type FormEvent } from 'react';
import './watchTables.css';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import type { FileInfo } from '../api/types';
import type { SaveState } from '../editor/EditorTabsContext';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { nameTaken } from '../projects/fileNames';
import { WATCH_TABLE_SUFFIX, tableTitle } from './format';
import { selectWatchTable } from './selection';
import { createTable, deleteTable, freeTableName, isTableName, renameTable } from './tableFiles';

interface BarProps {
  projectId: number;
  tables: readonly FileInfo[];
  files: readonly FileInfo[];
  selected: string | null;
  save: SaveState | null;
  /** The text of the shown table, for the export. */
  exportText: () => string | null;
}

type Mode = { kind: 'new' | 'rename'; name: string } | { kind: 'delete' } | null;

function download(name: string, text: string): void {
  const url = URL.createObjectURL(new Blob([text], { type: 'text/plain;charset=utf-8' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/**
 * The row above the watch table: which of the project's tables is shown (STEP 7 keeps several
 * VATs per program), and new, rename, delete and export of a table, with its save state.
 */
export function WatchTablesBar({ projectId, tables, files, selected, save, exportText }: BarProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const id = useId();
  const [mode, setMode] = useState<Mode>(null);
  const [problem, setProblem] = useState<string | null>(null);
  const [busy, setBusy] = useState(false);

  const run = async (action: () => Promise<void>) => {
    setBusy(true);
    setProblem(null);
    try {
      await action();
      setMode(null);
    } catch (caught) {
      setProblem(errorText(asApiError(caught) as ApiError));
    } finally {
      setBusy(false);
    }
  };

  const submitName = (event: FormEvent) => {
    event.preventDefault();
    if (!mode || mode.kind === 'delete') return;
    const title = mode.name.trim();
    if (!isTableName(title)) {
      setProblem(t('watchTables.badName'));
      return;
    }
    const fileName = `${title}${WATCH_TABLE_SUFFIX}`;
    if (nameTaken(files, fileName, mode.kind === 'rename' ? (selected ?? undefined) : undefined)) {
      setProblem(t('watchTables.nameTaken', { name: title }));
      return;
    }
    void run(async () => {
      const info =
        mode.kind === 'new' || selected === null
          ? await createTable(projectId, title)
          : await renameTable(projectId, selected, title);
      selectWatchTable(projectId, info.name);
    });
  };

  const remove = () =>
    void run(async () => {
      if (selected === null) return;
      await deleteTable(projectId, selected);
      const next = tables.find((table) => table.name !== selected);
      selectWatchTable(projectId, next?.name ?? null);
    });

  const exportTable = () => {
    const text = exportText();
    if (selected !== null && text !== null) download(selected, text);
  };

  const status = save?.status ?? null;

  return (
    <div className="watch-tables-bar" role="toolbar" aria-label={t('watchTables.toolbar')}>
      {tables.length > 0 ? (
        <>
          <label htmlFor={`${id}-table`}>{t('watchTables.table')}</label>
          <select
            id={`${id}-table`}
            className="select select--compact"
            data-testid="watch-table-select"
            value={selected ?? ''}
            onChange={(event) => selectWatchTable(projectId, event.target.value)}
          >
            {tables.map((table) => (
              <option key={table.name} value={table.name}>
                {tableTitle(table.name)}
              </option>
            ))}
          </select>
        </>
      ) : (
        <span className="watch-hint">{t('watchTables.none')}</span>
      )}
      <button
        type="button"
        className="button button--small"
        data-testid="watch-table-new"
        onClick={() => {
          setProblem(null);
          setMode({ kind: 'new', name: freeTableName(files) });
        }}
      >
        {t('watchTables.new')}
      </button>
      {selected !== null ? (
        <>
          <button
            type="button"
            className="button button--small"
            data-testid="watch-table-rename"
            onClick={() => {
              setProblem(null);
              setMode({ kind: 'rename', name: tableTitle(selected) });
            }}
          >
            {t('watchTables.rename')}
          </button>
          <button
            type="button"
            className="button button--small"
            data-testid="watch-table-delete"
            onClick={() => {
              setProblem(null);
              setMode({ kind: 'delete' });
            }}
          >
            {t('watchTables.delete')}
          </button>
          <button
            type="button"
            className="button button--small"
            data-testid="watch-table-export"
            title={t('watchTables.exportTitle')}
            onClick={exportTable}
          >
            {t('watchTables.export')}
          </button>
        </>
      ) : null}
      {status ? (
        <span className={`watch-save watch-save--${status}`} data-testid="watch-table-save" data-status={status}>
          {t(`watchTables.status.${status}`)}
        </span>
      ) : null}
      {mode && mode.kind !== 'delete' ? (
        <form className="watch-tables-name" onSubmit={submitName}>
          <label htmlFor={`${id}-name`} className="visually-hidden">
            {t('watchTables.nameLabel')}
          </label>
          <input
            id={`${id}-name`}
            className="input input--compact"
            data-testid="watch-table-name"
            autoFocus
            value={mode.name}
            onChange={(event) => setMode({ ...mode, name: event.target.value })}
          />
          <button type="submit" className="button button--small button--primary" disabled={busy} data-testid="watch-table-name-ok">
            {mode.kind === 'new' ? t('watchTables.create') : t('watchTables.apply')}
          </button>
          <button type="button" className="button button--small" onClick={() => setMode(null)}>
            {t('watchTables.cancel')}
          </button>
        </form>
      ) : null}
      {mode?.kind === 'delete' && selected !== null ? (
        <span className="watch-tables-confirm" role="alertdialog" aria-label={t('watchTables.delete')}>
          <span>{t('watchTables.confirmDelete', { name: tableTitle(selected) })}</span>
          <button
            type="button"
            className="button button--small button--danger"
            data-testid="watch-table-delete-ok"
            disabled={busy}
            onClick={remove}
          >
            {t('watchTables.confirm')}
          </button>
          <button type="button" className="button button--small" onClick={() => setMode(null)}>
            {t('watchTables.cancel')}
          </button>
        </span>
      ) : null}
      {problem ? (
        <span className="watch-error" role="alert" data-testid="watch-table-problem">
          {problem}
        </span>
      ) : null}
    </div>
  );
}
