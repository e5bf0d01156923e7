import { useCallback, useEffect, useState, type FormEvent, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { useActiveProject } from '../projects/ActiveProject';
import { getCrossReferences, type XrefEntry, type XrefResult } from './api';
import { referenceRequests, useRequest } from './xrefRequests';
import './xref.css';

/** Where a use is, as the table's "Location" column shows it: `NW 2 · 22`, or the line in SCL. */
function location(entry: XrefEntry): string {
  return entry.network !== null ? `NW ${entry.network} · ${entry.line}` : `${entry.line}:${entry.column}`;
}

/**
 * The Cross-references panel (TIA Portal's): every place an operand is read, written, set,
 * reset, called or opened, in STL, SCL and LAD/FBD; a row opens its file at the place.
 */
export function CrossReferencesPanel() {
  const { t } = useTranslation();
  const { dir } = useUiLanguage();
  const errorText = useApiErrorText();
  const openFile = useOpenProjectFile();
  const { projectId: activeId } = useActiveProject();
  const request = useRequest(referenceRequests);
  const [target, setTarget] = useState('');
  const [result, setResult] = useState<XrefResult | null>(null);
  const [error, setError] = useState<ApiError | null>(null);
  const [busy, setBusy] = useState(false);
  const projectId = request?.projectId ?? activeId;

  const load = useCallback(async (project: number, wanted: string) => {
    setBusy(true);
    setError(null);
    try {
      setResult(await getCrossReferences(project, wanted));
    } catch (caught) {
      setResult(null);
      setError(asApiError(caught));
    } finally {
      setBusy(false);
    }
  }, []);

  useEffect(() => {
    if (!request) return;
    setTarget(request.target);
    void load(request.projectId, request.target);
  }, [request, load]);

  function submit(event: FormEvent) {
    event.preventDefault();
    if (projectId === null || !target.trim()) return;
    referenceRequests.set({ projectId, target: target.trim() });
  }

  function open(entry: XrefEntry) {
    if (projectId === null) return;
    openFile(projectId, entry.file, { line: entry.line, column: entry.column }).catch((caught: unknown) =>
      setError(asApiError(caught)),
    );
  }

  function onRowKey(event: KeyboardEvent<HTMLTableRowElement>, entry: XrefEntry) {
    if (event.key === 'Enter' || event.key === ' ') {
      event.preventDefault();
      open(entry);
    }
  }

  return (
    <div className="xref" dir={dir} data-testid="xref-panel">
      <form className="xref__query" onSubmit={submit}>
        <label className="xref__label" htmlFor="xref-target">
          {t('xref.panel.target')}
        </label>
        <input
          id="xref-target"
          className="input xref__input"
          dir="ltr"
          value={target}
          placeholder={t('xref.panel.placeholder')}
          onChange={(event) => setTarget(event.target.value)}
          data-testid="xref-target"
        />
        <button type="submit" className="button button--small" disabled={projectId === null || busy}>
          {t('xref.panel.show')}
        </button>
      </form>
      {projectId === null ? <p className="panel-empty">{t('xref.panel.noProject')}</p> : null}
      {error ? (
        <p className="field__error" role="alert" data-testid="xref-error">
          <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
        </p>
      ) : null}
      {result ? (
        <>
          <p className="xref__summary" role="status" data-testid="xref-summary">
            {t('xref.panel.summary', { count: result.entries.length })}{' '}
            <bdi dir="ltr">
              <code>{result.symbol ? `"${result.symbol}" ${result.address}` : result.address}</code>
            </bdi>
          </p>
          <table className="data-table xref__table">
            <thead>
              <tr>
                <th scope="col">{t('xref.column.operand')}</th>
                <th scope="col">{t('xref.column.access')}</th>
                <th scope="col">{t('xref.column.block')}</th>
                <th scope="col">{t('xref.column.location')}</th>
                <th scope="col">{t('xref.column.file')}</th>
                <th scope="col">{t('xref.column.instruction')}</th>
              </tr>
            </thead>
            <tbody>
              {result.entries.map((entry) => (
                <tr
                  key={`${entry.file}:${entry.line}:${entry.column}:${entry.element ?? ''}:${entry.access}:${entry.address}`}
                  className={`xref__row${entry.exact ? '' : ' xref__row--overlap'}`}
                  tabIndex={0}
                  data-testid="xref-row"
                  data-file={entry.file}
                  data-line={entry.line}
                  title={t('xref.panel.open', { file: entry.file, line: entry.line })}
                  onClick={() => open(entry)}
                  onKeyDown={(event) => onRowKey(event, entry)}
                >
                  <td>
                    <bdi dir="ltr">
                      <code>{entry.address}</code>
                      {entry.symbol ? <span className="xref__symbol"> "{entry.symbol}"</span> : null}
                    </bdi>
                    {entry.exact ? null : <span className="xref__tag">{t('xref.panel.overlap')}</span>}
                  </td>
                  <td>
                    <span className={`xref__access xref__access--${entry.access}`}>{t(`xref.access.${entry.access}`)}</span>
                  </td>
                  <td>
                    <bdi dir="ltr">
                      <code>{entry.block}</code>
                      {entry.block_name ? <span className="xref__symbol"> "{entry.block_name}"</span> : null}
                    </bdi>
                  </td>
                  <td>
                    <code dir="ltr">{location(entry)}</code>
                  </td>
                  <td>
                    <code dir="ltr">{entry.file}</code>
                  </td>
                  <td>
                    <code dir="ltr">{entry.instruction}</code>
                  </td>
                </tr>
              ))}
            </tbody>
          </table>
        </>
      ) : null}
    </div>
  );
}
