import { useCallback, useEffect, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, type ApiError } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { useActiveProject } from '../projects/ActiveProject';
import { useProjectContents } from '../projects/projectContents';
import { getAssignments, type AssignedBit, type AssignedByte, type AssignmentList } from './api';
import { showReferences } from './xrefRequests';
import './xref.css';

const BITS = [7, 6, 5, 4, 3, 2, 1, 0];
const WIDTH_LETTER = { byte: 'B', word: 'W', dword: 'D' } as const;

function mark(bit: AssignedBit | undefined): string {
  if (!bit) return '';
  return `${bit.read ? 'R' : ''}${bit.write ? 'W' : ''}`;
}

/**
 * The assignment list (STEP 7's "Assignment list" / TIA's "Assignment list"): the I, Q, M, PI
 * and PQ bytes the program uses, bit by bit (R read, W written) and as bytes, words and double
 * words, then its timers and counters. A cell shows the cross-references of its address.
 */
/**
 * `shown` is whether its tab is in front: the list is a compile of the whole project on the
 * server, so a hidden panel does not ask for it after every save (a class shares one server).
 */
export function AssignmentPanel({ shown = true }: { shown?: boolean }) {
  const { t } = useTranslation();
  const { dir } = useUiLanguage();
  const errorText = useApiErrorText();
  const { projectId } = useActiveProject();
  const contents = useProjectContents(projectId);
  const [list, setList] = useState<AssignmentList | null>(null);
  const [error, setError] = useState<ApiError | null>(null);

  const load = useCallback(async (project: number, signal?: AbortSignal) => {
    try {
      setList(await getAssignments(project, signal));
      setError(null);
    } catch (caught) {
      if (caught instanceof DOMException && caught.name === 'AbortError') return;
      setError(asApiError(caught));
    }
  }, []);

  // Read again whenever the project's build changes (a save, a rename) while the tab is shown.
  const diagnostics = contents?.diagnostics;
  useEffect(() => {
    if (projectId === null || !shown) return;
    const controller = new AbortController();
    void load(projectId, controller.signal);
    return () => controller.abort();
  }, [projectId, diagnostics, load, shown]);

  if (projectId === null) return <p className="panel-empty">{t('xref.panel.noProject')}</p>;

  const refs = (address: string) => showReferences(projectId, address);
  const byteName = (row: AssignedByte) => `${row.area}B ${row.byte}`;

  return (
    <div className="xref" dir={dir} data-testid="assignment-panel">
      <div className="xref__query">
        <p className="xref__summary">{t('xref.assignments.hint')}</p>
        <button type="button" className="button button--small" onClick={() => void load(projectId)}>
          {t('xref.assignments.refresh')}
        </button>
      </div>
      {error ? (
        <p className="field__error" role="alert">
          <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
        </p>
      ) : null}
      {list && list.bytes.length === 0 && list.timers.length === 0 ? (
        <p className="panel-empty">{t('xref.assignments.empty')}</p>
      ) : null}
      {list && list.bytes.length > 0 ? (
        <table className="data-table xref__table xref__bits" dir="ltr" aria-label={t('xref.assignments.bytes')}>
          <thead>
            <tr>
              <th scope="col">{t('xref.assignments.address')}</th>
              {BITS.map((bit) => (
                <th scope="col" key={bit}>
                  {bit}
                </th>
              ))}
              <th scope="col">B</th>
              <th scope="col">W</th>
              <th scope="col">D</th>
            </tr>
          </thead>
          <tbody>
            {list.bytes.map((row) => (
              <tr key={`${row.area}${row.byte}`} data-testid="assignment-row" data-address={byteName(row)}>
                <th scope="row">
                  <button type="button" className="xref__cell" onClick={() => refs(byteName(row))}>
                    {byteName(row)}
                  </button>
                </th>
                {BITS.map((bit) => {
                  const used = row.bits.find((item) => item.bit === bit);
                  const address = `${row.area} ${row.byte}.${bit}`;
                  return (
                    <td key={bit} className={used ? 'xref__used' : undefined}>
                      {used ? (
                        <button
                          type="button"
                          className="xref__cell"
                          title={used.symbol ? `${address} "${used.symbol}"` : address}
                          aria-label={`${address}${used.symbol ? ` "${used.symbol}"` : ''}: ${mark(used)}`}
                          onClick={() => refs(address)}
                        >
                          {mark(used)}
                        </button>
                      ) : null}
                    </td>
                  );
                })}
                {(['byte', 'word', 'dword'] as const).map((width) => (
                  <td key={width} className={row.widths.includes(width) ? 'xref__used' : undefined}>
                    {row.widths.includes(width) ? (
                      <button
                        type="button"
                        className="xref__cell"
                        onClick={() => refs(`${row.area}${WIDTH_LETTER[width]} ${row.byte}`)}
                      >
                        ●
                      </button>
                    ) : null}
                  </td>
                ))}
              </tr>
            ))}
          </tbody>
        </table>
      ) : null}
      {list && list.timers.length > 0 ? (
        <table className="data-table xref__table" aria-label={t('xref.assignments.timers')}>
          <thead>
            <tr>
              <th scope="col">{t('xref.assignments.address')}</th>
              <th scope="col">{t('xref.column.access')}</th>
            </tr>
          </thead>
          <tbody>
            {list.timers.map((timer) => {
              const address = `${timer.kind} ${timer.number}`;
              return (
                <tr key={address} data-testid="assignment-row" data-address={address}>
                  <th scope="row">
                    <button type="button" className="xref__cell" dir="ltr" onClick={() => refs(address)}>
                      {address}
                      {timer.symbol ? ` "${timer.symbol}"` : ''}
                    </button>
                  </th>
                  <td>{timer.accesses.map((access) => t(`xref.access.${access}`)).join(' · ')}</td>
                </tr>
              );
            })}
          </tbody>
        </table>
      ) : null}
    </div>
  );
}
