/**
 * What the S7-Graph source compiles to, read-only: the FB's interface (its VAR sections: the FB
 * parameters of the chosen set, the user's declarations, one STRUCT per step and transition)
 * and the whole STL source, as the server's compiler makes it (`POST /api/convert` to STL). A
 * source with errors has no STL: the view lists the errors with their lines instead.
 *
 * The text is compiled again when it changes while the view is shown (after a short pause), and
 * the last result stays on screen meanwhile.
 */
import { useEffect, useMemo, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, convertSource, type ApiError } from '../api/client';
import type { Diagnostic } from '../api/types';
import { CodeEditor } from '../editor/CodeEditor';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import '../lad/lad.css';
import './control.css';

export interface GeneratedViewProps {
  name: string;
  text: string;
  active: boolean;
}

/** How long the text must rest before it is compiled again. */
export const GENERATE_DELAY_MS = 400;

type Part = 'interface' | 'stl';

type Result =
  | { status: 'loading' }
  | { status: 'ready'; stl: string }
  | { status: 'errors'; problems: readonly Diagnostic[] }
  | { status: 'failed'; error: ApiError };

const HEADER = /^\s*(FUNCTION_BLOCK|FUNCTION|ORGANIZATION_BLOCK|DATA_BLOCK|TYPE)\b/i;
const BEGIN = /^\s*BEGIN\b/i;

/** The declaration part of every block of an STL source: its header line to the line before BEGIN. */
export function interfaceOf(stl: string): string {
  const out: string[] = [];
  let inside = false;
  for (const line of stl.split('\n')) {
    if (!inside && HEADER.test(line)) {
      if (out.length > 0) out.push('');
      inside = true;
    }
    if (!inside) continue;
    if (BEGIN.test(line)) {
      inside = false;
      continue;
    }
    out.push(line);
  }
  return out.join('\n');
}

export function GeneratedView({ name, text, active }: GeneratedViewProps) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const message = useDiagnosticMessage();
  const errorText = useApiErrorText();
  const [part, setPart] = useState<Part>('interface');
  const [result, setResult] = useState<Result>({ status: 'loading' });
  const [attempt, setAttempt] = useState(0);
  const [compiled, setCompiled] = useState<string | null>(null);

  useEffect(() => {
    if (!active) return;
    const request = new AbortController();
    const timer = setTimeout(
      () => {
        convertSource(name, text, 'stl', request.signal).then(
          (converted) => {
            if (request.signal.aborted) return;
            const errors = converted.diagnostics.filter((d) => d.severity === 'error');
            setResult(errors.length > 0 || !converted.text ? { status: 'errors', problems: errors } : { status: 'ready', stl: converted.text });
            setCompiled(text);
          },
          (error: unknown) => {
            if (!request.signal.aborted) setResult({ status: 'failed', error: asApiError(error) });
          },
        );
      },
      compiled === null ? 0 : GENERATE_DELAY_MS,
    );
    return () => {
      request.abort();
      clearTimeout(timer);
    };
    // `compiled` only chooses the delay; a new text or a retry compiles again.
  }, [active, name, text, attempt]);

  const shown = useMemo(() => (result.status === 'ready' ? (part === 'stl' ? result.stl : interfaceOf(result.stl)) : ''), [result, part]);
  if (!active) return null;

  return (
    <div className="graph-generated" data-testid="graph-generated" data-status={result.status}>
      <div className="graph-generated__bar" dir={dir} lang={language}>
        <div className="view-bar__choices" role="group" aria-label={t('graphControl.generated.label')}>
          {(['interface', 'stl'] as const).map((choice) => (
            <button
              key={choice}
              type="button"
              className="view-bar__choice"
              aria-pressed={part === choice}
              data-testid={`graph-generated-${choice}`}
              onClick={() => setPart(choice)}
            >
              {choice === 'stl' ? 'STL' : t('graphControl.generated.interface')}
            </button>
          ))}
        </div>
        <span className="graph-generated__note">{t('graphControl.generated.readOnly')}</span>
      </div>
      {result.status === 'loading' ? (
        <p className="panel-empty" role="status" dir={dir} lang={language}>
          {t('graphControl.generated.loading')}
        </p>
      ) : null}
      {result.status === 'errors' ? (
        <div className="cannot-draw" role="alert" dir={dir} lang={language} data-testid="graph-generated-errors">
          <h3 className="cannot-draw__title">{t('graphControl.generated.errorTitle')}</h3>
          <p>{t('graphControl.generated.errorText')}</p>
          <ul className="cannot-draw__list">
            {result.problems.slice(0, 20).map((problem, k) => (
              <li key={k}>
                <code className="error-code">{problem.code}</code>{' '}
                {problem.span?.line ? <span dir="ltr">{t('graphControl.generated.line', { line: problem.span.line })}</span> : null} {message(problem)}
              </li>
            ))}
          </ul>
        </div>
      ) : null}
      {result.status === 'failed' ? (
        <div className="cannot-draw" role="alert" dir={dir} lang={language} data-testid="graph-generated-errors">
          <h3 className="cannot-draw__title">{t('graphControl.generated.failedTitle')}</h3>
          <p>
            <code className="error-code">{result.error.code}</code> {errorText(result.error)}
          </p>
          <div className="cannot-draw__actions">
            <button type="button" className="button" onClick={() => setAttempt((n) => n + 1)}>
              {t('graphControl.generated.retry')}
            </button>
          </div>
        </div>
      ) : null}
      {result.status === 'ready' ? (
        <CodeEditor
          key={part}
          value={shown}
          language="stl"
          readOnly
          ariaLabel={t(part === 'stl' ? 'graphControl.generated.stlLabel' : 'graphControl.generated.interfaceLabel', { name })}
          className="source-view__editor"
          data-testid="graph-generated-editor"
        />
      ) : null}
    </div>
  );
}
