/**
 * "Close one first" (MON610): the server runs as many simulations as it may. There are no user
 * accounts yet (issue 22), so every session on the server counts as the user's own: each is
 * listed with its project's name, its CPU mode and its age, with a Close button, and the
 * download can be tried again once one is closed.
 */
import { useCallback, useEffect, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { ApiError } from '../api/client';
import type { Problem } from '../api/monitorClient';
import { deleteSession, listSessions, type SessionOut } from '../api/sessions';
import { problemOf } from './SessionContext';
import { useProblemText } from './useProblemText';
import './session.css';

/** "5 minutes ago" in the interface language. */
function ageText(seconds: number, language: string): string {
  const format = new Intl.RelativeTimeFormat(language, { numeric: 'auto' });
  if (seconds < 60) return format.format(-Math.round(seconds), 'second');
  if (seconds < 3600) return format.format(-Math.floor(seconds / 60), 'minute');
  if (seconds < 86_400) return format.format(-Math.floor(seconds / 3600), 'hour');
  return format.format(-Math.floor(seconds / 86_400), 'day');
}

export function SessionLimit({ onRetry }: { onRetry: () => void }) {
  const { t, i18n } = useTranslation();
  const problemText = useProblemText();
  const [sessions, setSessions] = useState<SessionOut[] | null>(null);
  const [problem, setProblem] = useState<Problem | null>(null);
  const [closing, setClosing] = useState<string | null>(null);

  const load = useCallback(async () => {
    try {
      setSessions(await listSessions());
    } catch (error) {
      setProblem(problemOf(error));
    }
  }, []);
  useEffect(() => {
    void load();
  }, [load]);

  const close = async (id: string) => {
    setClosing(id);
    setProblem(null);
    try {
      await deleteSession(id);
    } catch (error) {
      // Already closed (idle, another tab): the list below shows it gone.
      if (!(error instanceof ApiError && error.code === 'MON609')) setProblem(problemOf(error));
    } finally {
      setClosing(null);
      await load();
    }
  };

  const nameOf = (item: SessionOut) => item.project_name ?? t('session.limit.noProject');
  return (
    <section className="session-limit" data-testid="session-limit" aria-label={t('session.limit.title')}>
      <p className="session-limit__intro">{t('session.limit.intro')}</p>
      {sessions === null && problem === null ? <p className="session-limit__note">{t('session.limit.loading')}</p> : null}
      {sessions !== null && sessions.length === 0 ? <p className="session-limit__note">{t('session.limit.none')}</p> : null}
      {sessions !== null && sessions.length > 0 ? (
        <table className="session-limit__table">
          <thead>
            <tr>
              <th scope="col">{t('session.limit.project')}</th>
              <th scope="col">{t('session.limit.cpu')}</th>
              <th scope="col">{t('session.limit.started')}</th>
              <th scope="col">{t('session.limit.pages')}</th>
              <th scope="col">
                <span className="visually-hidden">{t('session.limit.actions')}</span>
              </th>
            </tr>
          </thead>
          <tbody>
            {sessions.map((item) => (
              <tr key={item.id} data-testid="session-row" data-session={item.id}>
                <td className="session-limit__project">{nameOf(item)}</td>
                <td>
                  <code dir="ltr">
                    {item.profile} · {item.cpu.mode}
                  </code>
                </td>
                <td title={new Date(item.started_at).toLocaleString(i18n.language)}>{ageText(item.age_seconds, i18n.language)}</td>
                <td>{t('session.limit.pageCount', { count: item.clients.length })}</td>
                <td>
                  <button
                    type="button"
                    className="button button--small"
                    data-testid="session-close"
                    disabled={closing !== null}
                    aria-label={t('session.limit.close', { project: nameOf(item) })}
                    onClick={() => void close(item.id)}
                  >
                    {t('common.close')}
                  </button>
                </td>
              </tr>
            ))}
          </tbody>
        </table>
      ) : null}
      {problem ? (
        <p className="session-limit__problem" role="alert">
          <code className="error-code">{problem.code}</code> {problemText(problem)}
        </p>
      ) : null}
      <div className="session-limit__actions">
        <button type="button" className="button button--small button--primary" data-testid="session-limit-retry" onClick={onRetry}>
          {t('session.limit.retry')}
        </button>
      </div>
    </section>
  );
}
