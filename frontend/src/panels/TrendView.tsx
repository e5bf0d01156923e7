import { lazy, Suspense, useEffect, useId, useMemo, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { Problem } from '../api/monitorClient';
import { trendCsvUrl } from '../api/sessions';
import { ExportIcon } from '../cpu/cpuIcons';
import { problemOf, useMonitor, useSession } from '../cpu/SessionContext';
import { useProblemText } from '../cpu/useProblemText';
import { useActiveProject } from '../projects/ActiveProject';
import { CloseIcon, PlusIcon } from '../ui/icons';
import { TREND_COLORS } from './trendColors';
import { trendValueText } from './trendLayout';
import { useStoredList } from './useStoredList';

const TrendChart = lazy(() => import('./TrendChart'));

/** The server records at most 32 trend entries per client (PROTOCOL.md). */
export const MAX_TREND_ENTRIES = 32;

const isEntry = (item: unknown): item is string => typeof item === 'string' && item.trim() !== '';

/** Where the trend entries of a project are remembered. */
export const trendStorageKey = (projectId: number | null) => `nasaq.trend.${projectId ?? 'none'}`;

/**
 * The trend: the chosen entries sampled at the end of every scan, plotted against the simulated
 * time (zoom by dragging), with the samples as CSV from the server. The session records the
 * trend, not the page: after a reload the same entries come back with the samples recorded so
 * far, and a page with no entries of its own shows the ones the session records.
 */
export function TrendView() {
  const { t } = useTranslation();
  const problemText = useProblemText();
  const fieldId = useId();
  const { projectId } = useActiveProject();
  const { session, client } = useSession();
  const [entries, setEntries] = useStoredList(trendStorageKey(session?.projectId ?? projectId), isEntry);
  const [entry, setEntry] = useState('');
  const [problem, setProblem] = useState<Problem | null>(null);
  const hello = useMonitor((state) => state.hello);
  const connection = useMonitor((state) => state.connection);
  const samples = useMonitor((state) => state.trend);
  const types = useMonitor((state) => state.trendTypes);
  const sessionTrend = useMonitor((state) => state.sessionTrend);
  const key = entries.join('\n');

  // Another tab or browser attached to the session: show the trend it records (with its history).
  useEffect(() => {
    if (sessionTrend.length > 0) setEntries((items) => (items.length === 0 ? [...sessionTrend] : items));
  }, [sessionTrend, setEntries]);

  useEffect(() => {
    if (!client) return;
    const chosen = key === '' ? [] : key.split('\n');
    client.setTrend(chosen).catch((error: unknown) => {
      const found = problemOf(error);
      setProblem(found);
      // An entry the server cannot record leaves the list; the others are recorded again.
      const bad = String(found.params.target ?? '');
      if (chosen.includes(bad)) setEntries((items) => items.filter((item) => item !== bad));
    });
  }, [client, key, setEntries]);

  const add = (event: FormEvent) => {
    event.preventDefault();
    const text = entry.trim();
    if (text === '' || entries.length >= MAX_TREND_ENTRIES) return;
    setProblem(null);
    setEntries((items) => (items.includes(text) ? items : [...items, text]));
    setEntry('');
  };

  const last = samples[samples.length - 1];
  const chartable = session !== null && entries.length > 0 && samples.length > 0 && types.length === entries.length;
  const csv = session && hello && connection === 'open' ? trendCsvUrl(session.id, hello.client) : null;
  const labels = useMemo(
    () => ({
      time: t('trend.time'),
      reset: t('trend.resetZoom'),
      resize: t('trend.resize'),
      units: { int: t('trend.unit.int'), real: t('trend.unit.real'), time: t('trend.unit.time') },
    }),
    [t],
  );

  return (
    <div className="trend" data-testid="trend">
      <div className="trend__bar">
        <ul className="trend__entries" aria-label={t('trend.entries')}>
          {entries.map((item, index) => (
            <li key={item} className="trend-entry" data-testid="trend-entry" data-entry={item}>
              <span
                className="trend-entry__swatch"
                style={{ background: TREND_COLORS[index % TREND_COLORS.length] }}
                aria-hidden="true"
              />
              <code dir="ltr">{item}</code>
              {last && chartable ? (
                <span className="trend-entry__value" dir="ltr">
                  {trendValueText(last.values[index], types[index])}
                </span>
              ) : null}
              <button
                type="button"
                className="icon-button icon-button--tiny"
                aria-label={t('trend.remove', { entry: item })}
                title={t('trend.remove', { entry: item })}
                onClick={() => setEntries((items) => items.filter((other) => other !== item))}
              >
                <CloseIcon size={12} />
              </button>
            </li>
          ))}
        </ul>
        <form className="trend__add" onSubmit={add}>
          <label htmlFor={fieldId} className="visually-hidden">
            {t('trend.addLabel')}
          </label>
          <input
            id={fieldId}
            className="input input--compact"
            data-testid="trend-add-entry"
            dir="ltr"
            placeholder={t('watch.addPlaceholder')}
            value={entry}
            onChange={(event) => setEntry(event.target.value)}
          />
          <button
            type="submit"
            className="button button--small"
            data-testid="trend-add"
            disabled={entry.trim() === '' || entries.length >= MAX_TREND_ENTRIES}
          >
            <PlusIcon />
            {t('trend.add')}
          </button>
        </form>
        {csv ? (
          <a className="button button--small" href={csv} download data-testid="trend-export">
            <ExportIcon />
            {t('trend.exportCsv')}
          </a>
        ) : (
          <button type="button" className="button button--small" disabled data-testid="trend-export">
            <ExportIcon />
            {t('trend.exportCsv')}
          </button>
        )}
      </div>
      {problem ? (
        <p className="trend__problem" role="alert">
          <code className="error-code">{problem.code}</code> {problemText(problem)}
        </p>
      ) : null}
      <div className="trend__body">
        {chartable ? (
          <Suspense fallback={<p className="panel-empty">{t('trend.loading')}</p>}>
            <TrendChart entries={entries} types={types} samples={samples} labels={labels} />
          </Suspense>
        ) : (
          <p className="panel-empty">{session ? t('trend.noEntries') : t('trend.noSession')}</p>
        )}
      </div>
    </div>
  );
}
