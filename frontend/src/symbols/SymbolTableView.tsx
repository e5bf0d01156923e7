import { useCallback, useEffect, useMemo, useRef, useState, type ChangeEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import {
  SYMBOL_FORMATS,
  getSymbols,
  importSymbols,
  saveSymbols,
  symbolsExportUrl,
  type ImportMode,
  type SymbolField,
  type SymbolTableOut,
} from '../api/symbols';
import type { FileInfo } from '../api/types';
import { Autosaver, registerAutosaver } from '../editor/autosave';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useEditorTabs, type SaveState, type SourceFileRef } from '../editor/EditorTabsContext';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { projectContents, type ProjectContentsStore } from '../projects/projectContents';
import { ErrorIcon, WarningIcon } from '../ui/icons';
import { SymbolGrid } from './SymbolGrid';
import { useSymbolRowRequest } from './symbolSelection';
import {
  emptyRow,
  filterRows,
  problemsById,
  rowsText,
  sortRows,
  updateCell,
  withIds,
  type GridRow,
  type ProblemsById,
  type SortDirection,
} from './symbolRows';
import './symbols.css';

function ProblemLine({ error }: { error: ApiError }) {
  const text = useApiErrorText();
  return (
    <>
      <code className="error-code">{error.code}</code> <span>{text(error)}</span>
    </>
  );
}

export interface SymbolTableViewProps {
  tabId: string;
  file: SourceFileRef;
  active: boolean;
  store?: ProjectContentsStore;
}

/**
 * The symbol table editor: the file's rows as a grid (name, address, type, comment) with the
 * server's problems beside each cell, saved through `/symbols` with the same version check and
 * conflict choice as a text tab, import of a STEP 7 file and downloads in its formats.
 */
export function SymbolTableView({ tabId, file, active, store = projectContents }: SymbolTableViewProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { setSaveState } = useEditorTabs();
  const message = useDiagnosticMessage();
  const [rows, setRows] = useState<GridRow[] | null>(null);
  const [problems, setProblems] = useState<ProblemsById>(new Map());
  const [loadError, setLoadError] = useState<ApiError | null>(null);
  const [save, setSave] = useState<SaveState>({ status: 'saved', error: null });
  const [filter, setFilter] = useState('');
  const [pinned, setPinned] = useState<ReadonlySet<number>>(new Set());
  const [sort, setSort] = useState<{ field: SymbolField; direction: SortDirection } | null>(null);
  const [selected, setSelected] = useState<ReadonlySet<number>>(new Set());
  const [activeRow, setActiveRow] = useState<number | null>(null);
  const [mode, setMode] = useState<ImportMode>('replace');
  const [notice, setNotice] = useState<string | null>(null);
  const [actionError, setActionError] = useState<ApiError | null>(null);
  const saverRef = useRef<Autosaver | null>(null);
  const fileRef = useRef(file);
  fileRef.current = file;
  // The rows each saved text was made of: the server's problems come by row index.
  const sentRows = useRef(new Map<string, GridRow[]>());
  const importInput = useRef<HTMLInputElement>(null);

  const adopt = useCallback(
    (out: SymbolTableOut) => {
      const loaded = withIds(out.rows);
      setRows(loaded);
      setProblems(problemsById(out.problems, loaded));
      setSelected(new Set());
      setPinned(new Set());
      saverRef.current?.reloaded(rowsText(loaded), out.version);
      return loaded;
    },
    [],
  );

  const load = useCallback(async () => {
    setLoadError(null);
    try {
      const out = await getSymbols(fileRef.current.projectId, fileRef.current.path);
      const loaded = adopt(out);
      if (!saverRef.current) {
        const text = rowsText(loaded);
        const saver = new Autosaver({
          text,
          version: out.version,
          save: async (sent, baseVersion, options) => {
            const target = fileRef.current;
            const answer = await saveSymbols(target.projectId, target.path, JSON.parse(sent), baseVersion, options);
            const checked = sentRows.current.get(sent);
            if (checked) setProblems(problemsById(answer.problems, checked));
            const info: FileInfo = {
              name: target.path,
              language: 'symbols',
              size: sent.length,
              version: answer.version,
              created_at: '',
              updated_at: '',
            };
            return info;
          },
          onState: (state) => {
            setSave(state);
            setSaveState(tabId, state);
          },
          onSaved: (_info, sent) => {
            sentRows.current.delete(sent);
            store.reloadSoon(fileRef.current.projectId);
          },
        });
        saverRef.current = saver;
      }
    } catch (caught) {
      setLoadError(asApiError(caught));
    }
  }, [adopt, setSaveState, store, tabId]);

  useEffect(() => {
    void load();
    return () => {
      const saver = saverRef.current;
      saverRef.current = null;
      void saver?.dispose();
    };
  }, [load]);

  useEffect(() => {
    const saver = saverRef.current;
    if (!saver) return;
    return registerAutosaver(`${tabId}:table`, () => fileRef.current, saver);
  }, [tabId, rows === null]);

  /** Every change of the rows goes to the autosave. */
  const change = useCallback((next: GridRow[]) => {
    setRows(next);
    const text = rowsText(next);
    if (sentRows.current.size > 20) sentRows.current.clear();
    sentRows.current.set(text, next);
    saverRef.current?.change(text);
  }, []);

  const shown = useMemo(() => {
    if (!rows) return [];
    const matching = filterRows(rows, filter);
    if (pinned.size === 0) return matching;
    const ids = new Set(matching.map((row) => row.id));
    return rows.filter((row) => ids.has(row.id) || pinned.has(row.id));
  }, [rows, filter, pinned]);

  const counts = useMemo(() => {
    let errors = 0;
    let warnings = 0;
    for (const list of problems.values())
      for (const item of list) {
        if (item.problem.severity === 'error') errors++;
        else warnings++;
      }
    return { errors, warnings };
  }, [problems]);

  const onChange = useCallback(
    (id: number, field: SymbolField, value: string) => {
      if (rows) change(updateCell(rows, id, field, value));
    },
    [rows, change],
  );

  const onAdd = useCallback(
    (field: SymbolField, value: string) => {
      const row = { ...emptyRow(), [field]: value };
      if (rows) change([...rows, row]);
      setPinned((current) => new Set([...current, row.id]));
      return row.id;
    },
    [rows, change],
  );

  const onDelete = useCallback(
    (ids: number[]) => {
      if (!rows) return;
      const gone = new Set(ids);
      change(rows.filter((row) => !gone.has(row.id)));
      setSelected((current) => new Set([...current].filter((id) => !gone.has(id))));
    },
    [rows, change],
  );

  const onSort = useCallback(
    (field: SymbolField) => {
      if (!rows) return;
      const direction: SortDirection = sort?.field === field && sort.direction === 'asc' ? 'desc' : 'asc';
      setSort({ field, direction });
      change(sortRows(rows, field, direction));
    },
    [rows, sort, change],
  );

  const onSelect = useCallback((id: number, on: boolean) => {
    setSelected((current) => {
      const next = new Set(current);
      if (on) next.add(id);
      else next.delete(id);
      return next;
    });
  }, []);

  const addRow = () => {
    if (!rows) return;
    const row = emptyRow();
    change([...rows, row]);
    setPinned((current) => new Set([...current, row.id]));
  };

  const importFile = async (event: ChangeEvent<HTMLInputElement>) => {
    const chosen = event.target.files?.[0];
    event.target.value = '';
    if (!chosen) return;
    setActionError(null);
    setNotice(null);
    try {
      await saverRef.current?.flush();
      const target = fileRef.current;
      const out = await importSymbols(
        target.projectId,
        target.path,
        chosen,
        chosen.name,
        mode,
        saverRef.current?.baseVersion ?? null,
      );
      adopt(out);
      setNotice(t('symbolTable.imported', { count: out.rows.length, name: chosen.name }));
      store.reloadSoon(target.projectId);
    } catch (caught) {
      setActionError(asApiError(caught));
    }
  };

  const reload = async () => {
    setActionError(null);
    try {
      adopt(await getSymbols(fileRef.current.projectId, fileRef.current.path));
    } catch (caught) {
      setActionError(asApiError(caught));
    }
  };

  // F12 on a symbol in an editor: its row becomes the grid's active row (shown even if filtered out).
  const rowRequest = useSymbolRowRequest(file.projectId, file.path);
  const [focusRow, setFocusRow] = useState<{ id: number; seq: number } | null>(null);
  useEffect(() => {
    if (!rowRequest || !rows || focusRow?.seq === rowRequest.seq) return;
    const wanted = rowRequest.name.toLowerCase();
    const row = rows.find((item) => item.name.trim().toLowerCase() === wanted);
    if (!row) return;
    setPinned((current) => new Set([...current, row.id]));
    setFocusRow({ id: row.id, seq: rowRequest.seq });
  }, [rowRequest, rows, focusRow]);

  const activeProblems = activeRow !== null ? (problems.get(activeRow) ?? []) : [];

  if (loadError) {
    return (
      <div className="symbol-table symbol-table--message" hidden={!active} dir={dir} lang={language} role="alert">
        <p>
          {t('symbolTable.loadFailed')} <ProblemLine error={loadError} />
        </p>
        <button type="button" className="button button--small" onClick={() => void load()}>
          {t('symbolTable.retry')}
        </button>
      </div>
    );
  }
  if (!rows) {
    return (
      <div className="symbol-table symbol-table--message" hidden={!active} dir={dir} lang={language} role="status">
        {t('symbolTable.loading')}
      </div>
    );
  }

  return (
    <div className="symbol-table" hidden={!active} data-testid="symbol-table">
      {save.status === 'conflict' && save.error ? (
        <div className="source-banner source-banner--conflict" role="alert" dir={dir} lang={language} data-testid="symbols-conflict">
          <WarningIcon className="source-banner__icon" />
          <p className="source-banner__text">
            <ProblemLine error={save.error} />
          </p>
          <div className="source-banner__actions">
            <button type="button" className="button button--small" data-testid="symbols-conflict-reload" onClick={() => void reload()}>
              {t('editor.conflict.reload')}
            </button>
            <button
              type="button"
              className="button button--small button--primary"
              data-testid="symbols-conflict-overwrite"
              onClick={() => void saverRef.current?.overwrite()}
            >
              {t('editor.conflict.overwrite')}
            </button>
          </div>
        </div>
      ) : null}
      {save.status === 'failed' && save.error ? (
        <div className="source-banner source-banner--failed" role="alert" dir={dir} lang={language} data-testid="symbols-save-failed">
          <ErrorIcon className="source-banner__icon" />
          <p className="source-banner__text">
            {t('editor.save.failedText')} <ProblemLine error={save.error} />
          </p>
          <div className="source-banner__actions">
            <button type="button" className="button button--small" onClick={() => void saverRef.current?.flush()}>
              {t('editor.save.retry')}
            </button>
          </div>
        </div>
      ) : null}
      <div className="symbol-table__toolbar" dir={dir} lang={language}>
        <label className="symbol-table__filter">
          <span className="visually-hidden">{t('symbolTable.filter')}</span>
          <input
            type="search"
            className="input input--compact"
            dir="ltr"
            placeholder={t('symbolTable.filterPlaceholder')}
            value={filter}
            data-testid="symbol-filter"
            onChange={(event) => {
              setFilter(event.target.value);
              setPinned(new Set());
            }}
          />
        </label>
        <button type="button" className="button button--small" data-testid="symbol-add" onClick={addRow}>
          {t('symbolTable.add')}
        </button>
        <button
          type="button"
          className="button button--small"
          data-testid="symbol-delete"
          disabled={selected.size === 0}
          onClick={() => onDelete([...selected])}
        >
          {t('symbolTable.deleteSelected', { count: selected.size })}
        </button>
        <span className="symbol-table__spacer" />
        <label className="symbol-table__mode">
          <span>{t('symbolTable.importMode')}</span>
          <select
            className="input input--compact"
            value={mode}
            data-testid="symbol-import-mode"
            onChange={(event) => setMode(event.target.value as ImportMode)}
          >
            <option value="replace">{t('symbolTable.replace')}</option>
            <option value="merge">{t('symbolTable.merge')}</option>
          </select>
        </label>
        <button type="button" className="button button--small" data-testid="symbol-import" onClick={() => importInput.current?.click()}>
          {t('symbolTable.import')}
        </button>
        <input
          ref={importInput}
          type="file"
          accept=".sdf,.asc,.seq,.csv"
          hidden
          data-testid="symbol-import-file"
          onChange={(event) => void importFile(event)}
        />
        <details className="symbol-table__export">
          <summary className="button button--small" data-testid="symbol-export">
            {t('symbolTable.export')}
          </summary>
          <ul className="symbol-table__menu" role="menu">
            {SYMBOL_FORMATS.map((format) => (
              <li key={format} role="none">
                <a
                  role="menuitem"
                  href={symbolsExportUrl(file.projectId, file.path, format)}
                  download
                  data-testid={`symbol-export-${format}`}
                >
                  {t('symbolTable.exportAs', { format: `.${format}` })}
                </a>
              </li>
            ))}
          </ul>
        </details>
      </div>
      {actionError ? (
        <p className="symbol-table__error" role="alert" dir={dir} lang={language} data-testid="symbol-action-error">
          <ProblemLine error={actionError} />
        </p>
      ) : null}
      <SymbolGrid
        rows={shown}
        problems={problems}
        sort={sort}
        selected={selected}
        onChange={onChange}
        onAdd={onAdd}
        onDelete={onDelete}
        onSort={onSort}
        onSelect={onSelect}
        onActiveRow={setActiveRow}
        focusRow={focusRow}
        visible={active}
      />
      <div className="symbol-table__status" dir={dir} lang={language}>
        <span data-testid="symbol-count">
          {shown.length === rows.length
            ? t('symbolTable.rows', { count: rows.length })
            : t('symbolTable.shown', { shown: shown.length, count: rows.length })}
        </span>
        <span data-testid="symbol-problem-count">
          {counts.errors + counts.warnings === 0
            ? t('symbolTable.noProblems')
            : t('symbolTable.problems', { errors: counts.errors, warnings: counts.warnings })}
        </span>
        <span className="source-status__save" data-testid="symbol-save-state" data-state={save.status}>
          {t(`editor.save.${save.status}`)}
        </span>
        <span role="status">{notice}</span>
      </div>
      <ul className="symbol-table__problems" aria-live="polite" dir={dir} lang={language} data-testid="symbol-row-problems">
        {activeProblems.map((item, index) => (
          <li key={index} className={`symbol-table__problem symbol-table__problem--${item.problem.severity}`}>
            <code className="error-code">{item.problem.code}</code>{' '}
            <span>
              {t(`symbolTable.columns.${item.field}`)}: {message(item.problem)}
            </span>
          </li>
        ))}
      </ul>
      <p className="symbol-table__help" dir={dir} lang={language}>
        {t('symbolTable.keyboardHelp')}
      </p>
    </div>
  );
}
