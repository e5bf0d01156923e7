import { useTranslation } from 'react-i18next';
import type { Diagnostic } from '../api/types';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { CheckIcon, ErrorIcon, WarningIcon } from '../ui/icons';
import type { CheckDiagnostic, CheckOutcome, CheckResult, Where } from './api';
import { valueText, virtualTime } from './progress';

/** `OB1.lad · NW 4`, `OB1.awl:12`: where a failing expectation points. */
export function whereText(where: Where): string {
  const parts = [where.file];
  if (where.network != null) parts.push(`NW ${where.network}`);
  else if (where.line != null) parts.push(String(where.line));
  return parts.join(where.network != null ? ' · ' : ':');
}

/** A check's diagnostic as the Diagnostics panel knows it (to translate it by its key when it has one). */
function asDiagnostic(diagnostic: CheckDiagnostic): Diagnostic {
  return {
    code: diagnostic.code,
    severity: diagnostic.severity,
    key: diagnostic.key ?? '',
    message: diagnostic.message,
    params: diagnostic.params ?? {},
    span: { file: diagnostic.file, line: diagnostic.line, column: diagnostic.column },
  } as Diagnostic;
}

function Place({ where, onOpen }: { where: Where; onOpen: (where: Where) => void }) {
  const { t } = useTranslation();
  const place = whereText(where);
  return (
    <button
      type="button"
      className="lesson-check__where"
      dir="ltr"
      data-testid="lesson-where"
      title={t('lessonPane.check.openPlace', { place })}
      aria-label={t('lessonPane.check.openPlace', { place })}
      onClick={() => onOpen(where)}
    >
      <code>{place}</code>
    </button>
  );
}

export function DiagnosticList({ diagnostics, onOpen }: { diagnostics: readonly CheckDiagnostic[]; onOpen: (where: Where) => void }) {
  const { t } = useTranslation();
  const message = useDiagnosticMessage();
  return (
    <ul className="lesson-diagnostics" data-testid="lesson-diagnostics">
      {diagnostics.map((diagnostic, k) => (
        <li key={k} className={`lesson-diagnostics__item lesson-diagnostics__item--${diagnostic.severity}`}>
          {diagnostic.severity === 'error' ? <ErrorIcon className="lesson-diagnostics__icon" /> : <WarningIcon className="lesson-diagnostics__icon" />}
          <span className="visually-hidden">{t(`diagnostics.severity.${diagnostic.severity}`)}</span>
          <code className="error-code">{diagnostic.code}</code> <span>{message(asDiagnostic(diagnostic))}</span>{' '}
          {diagnostic.file ? <Place where={{ file: diagnostic.file, line: diagnostic.line, network: diagnostic.network ?? null, element: diagnostic.element ?? null }} onOpen={onOpen} /> : null}
        </li>
      ))}
    </ul>
  );
}

function Outcome({ outcome, onOpen }: { outcome: CheckOutcome; onOpen: (where: Where) => void }) {
  const { t } = useTranslation();
  const message = useDiagnosticMessage();
  return (
    <li className={`lesson-check ${outcome.passed ? 'lesson-check--passed' : 'lesson-check--failed'}`} data-testid="lesson-check-outcome" data-passed={outcome.passed}>
      <p className="lesson-check__title">
        {outcome.passed ? <CheckIcon className="lesson-check__icon" /> : <ErrorIcon className="lesson-check__icon" />}
        <span>{t(`lessonPane.check.kind.${outcome.kind}`)}</span> <code dir="ltr">{outcome.name}</code>{' '}
        <strong>{outcome.passed ? t('lessonPane.check.passed') : t('lessonPane.check.failed')}</strong>
      </p>
      {outcome.error ? (
        <p className="lesson-check__error" role="alert">
          {outcome.error}
        </p>
      ) : null}
      {outcome.stop ? (
        <p className="lesson-check__stop" data-testid="lesson-stop">
          {t('lessonPane.check.stop')} <code className="error-code">{outcome.stop.code}</code>{' '}
          <span dir="auto">{message(asDiagnostic({ code: outcome.stop.code, severity: 'error', message: outcome.stop.reason, file: null, line: null, column: null, ...pickKey(outcome.stop) }))}</span>
        </p>
      ) : null}
      {outcome.diagnostics.length > 0 ? <DiagnosticList diagnostics={outcome.diagnostics} onOpen={onOpen} /> : null}
      {outcome.steps.length > 0 ? (
        <ol className="lesson-steps">
          {outcome.steps.map((step) => (
            <li key={step.step} className={step.passed ? 'lesson-step lesson-step--passed' : 'lesson-step lesson-step--failed'} data-testid="lesson-step" data-passed={step.passed}>
              <span className="lesson-step__head">
                {t('lessonPane.check.step', { number: step.step })}: {step.passed ? t('lessonPane.check.passed') : t('lessonPane.check.failed')}
              </span>
              {step.note ? (
                <span className="lesson-step__note" dir="auto">
                  {step.note}
                </span>
              ) : null}
              {step.failures.length > 0 ? (
                <table className="lesson-failures">
                  <thead>
                    <tr>
                      <th scope="col">{t('lessonPane.check.address')}</th>
                      <th scope="col">{t('lessonPane.check.expected')}</th>
                      <th scope="col">{t('lessonPane.check.actual')}</th>
                      <th scope="col">{t('lessonPane.check.at')}</th>
                      <th scope="col">{t('lessonPane.check.where')}</th>
                    </tr>
                  </thead>
                  <tbody>
                    {step.failures.map((failure, k) => (
                      <tr key={k} data-testid="lesson-failure">
                        <td dir="ltr">
                          <code>{failure.address}</code>
                        </td>
                        <td dir="ltr">{valueText(failure.expected)}</td>
                        <td dir="ltr">{valueText(failure.actual)}</td>
                        <td dir="ltr">{failure.at_ms != null ? virtualTime(failure.at_ms) : '—'}</td>
                        <td>{failure.where ? <Place where={failure.where} onOpen={onOpen} /> : '—'}</td>
                      </tr>
                    ))}
                  </tbody>
                </table>
              ) : null}
            </li>
          ))}
        </ol>
      ) : null}
    </li>
  );
}

/** The catalogue key and parameters a stop reason may carry (optional in the answer). */
function pickKey(stop: { code: string; reason: string; key?: string; params?: Record<string, unknown> }): { key?: string; params?: Record<string, unknown> } {
  return { ...(stop.key ? { key: stop.key } : {}), ...(stop.params ? { params: stop.params } : {}) };
}

/**
 * What "Check" found: the verdict, then each check with its steps passed or failed, the
 * expected and actual values, and a button that opens the network or line a failing
 * expectation points at. A program that does not compile shows the compiler's diagnostics
 * (it did not fail a check: it was not run).
 */
export function CheckResults({ result, onOpen }: { result: CheckResult; onOpen: (where: Where) => void }) {
  const { t } = useTranslation();
  const compileDiagnostics = result.status === 'compile_error' ? result.checks.flatMap((check) => check.diagnostics) : [];
  return (
    <section className="lesson-results" aria-label={t('lessonPane.check.results')} data-testid="lesson-results" data-status={result.status}>
      <p className={`lesson-verdict lesson-verdict--${result.status}`} role="status" data-testid="lesson-verdict">
        {result.status === 'passed' ? <CheckIcon className="lesson-verdict__icon" /> : <ErrorIcon className="lesson-verdict__icon" />}
        {t(`lessonPane.verdict.${result.status}`)}
      </p>
      {result.status === 'compile_error' ? (
        compileDiagnostics.length > 0 ? (
          <DiagnosticList diagnostics={compileDiagnostics} onOpen={onOpen} />
        ) : null
      ) : (
        <ul className="lesson-checks">
          {result.checks.map((check, k) => (
            <Outcome key={`${check.kind}-${check.name}-${k}`} outcome={check} onOpen={onOpen} />
          ))}
        </ul>
      )}
    </section>
  );
}
