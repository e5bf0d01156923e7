import { useMemo } from 'react';
import { useTranslation } from 'react-i18next';
import type { Diagnostic, Severity, Span } from '../api/types';
import { countProblems } from '../app/compile';
import { useOpenDiagnostic, useProjectDiagnostics } from '../editor/projectDiagnostics';
import { CheckIcon, ErrorIcon, InfoIcon, WarningIcon } from '../ui/icons';
import type { DiagnosticEntry } from '../api/monitor';
import { CpuDiagnostics, useOpenCpuEntry } from './CpuDiagnostics';
import { diagnosticsStore, useDiagnostics, type DiagnosticsStore } from './diagnosticsStore';

type OpenDiagnostic = (diagnostic: Diagnostic) => boolean;
const NONE: readonly Diagnostic[] = [];

const SEVERITY_ICON = { error: ErrorIcon, warning: WarningIcon, info: InfoIcon } as const;
const SEVERITY_ORDER: Record<Severity, number> = { error: 0, warning: 1, info: 2 };

function sorted(diagnostics: readonly Diagnostic[]): Diagnostic[] {
  return [...diagnostics].sort(
    (a, b) =>
      SEVERITY_ORDER[a.severity] - SEVERITY_ORDER[b.severity] ||
      (a.span?.file ?? '').localeCompare(b.span?.file ?? '') ||
      (a.span?.network ?? 0) - (b.span?.network ?? 0) ||
      (a.span?.line ?? 0) - (b.span?.line ?? 0) ||
      (a.span?.column ?? 0) - (b.span?.column ?? 0),
  );
}

/** `OB1.awl:3:7`, `FB1.lad:NW 2`, or '' for a problem without a place. */
export function spanText(span: Span | null): string {
  if (!span) return '';
  const parts = [span.file ?? ''];
  if (span.network != null) parts.push(`NW ${span.network}`);
  if (span.line != null) parts.push(String(span.line));
  if (span.line != null && span.column != null) parts.push(String(span.column));
  return parts.filter((part) => part !== '').join(':');
}

function DiagnosticRow({ diagnostic, onOpen }: { diagnostic: Diagnostic; onOpen?: OpenDiagnostic }) {
  const { t, i18n } = useTranslation();
  const Icon = SEVERITY_ICON[diagnostic.severity];
  const translated = `problems.${diagnostic.key}`;
  const message = i18n.exists(translated) ? t(translated, { ...diagnostic.params }) : diagnostic.message;
  const where = spanText(diagnostic.span);
  return (
    <li className={`diagnostic diagnostic--${diagnostic.severity}`} data-testid="diagnostic">
      <Icon className="diagnostic__icon" />
      <span className="visually-hidden">{t(`diagnostics.severity.${diagnostic.severity}`)}</span>
      <code className="diagnostic__code">{diagnostic.code}</code>
      <span className="diagnostic__message">{message}</span>
      {where && onOpen && diagnostic.span?.file ? (
        <button
          type="button"
          className="diagnostic__location diagnostic__jump"
          dir="ltr"
          data-testid="diagnostic-open"
          title={t('diagnostics.goTo', { place: where })}
          aria-label={t('diagnostics.goTo', { place: where })}
          onClick={() => onOpen(diagnostic)}
        >
          <code>{where}</code>
        </button>
      ) : where ? (
        <code className="diagnostic__location" dir="ltr">
          {where}
        </code>
      ) : null}
    </li>
  );
}

/**
 * The Diagnostics panel: every reported problem, errors first ("No problems" when there are none),
 * then the diagnostic buffer of the simulated CPU while a session runs.
 */
export function DiagnosticsList({
  store = diagnosticsStore,
  project = NONE,
  onOpen,
  onOpenCpuEntry,
}: {
  store?: DiagnosticsStore;
  /** The compiler's diagnostics of the active project (editor/projectDiagnostics). */
  project?: readonly Diagnostic[];
  /** Opens a diagnostic's file at its line. */
  onOpen?: OpenDiagnostic;
  /** Opens the block of a CPU diagnostic buffer entry at its line. */
  onOpenCpuEntry?: (entry: DiagnosticEntry) => boolean;
}) {
  const { t } = useTranslation();
  const reported = useDiagnostics(store);
  const diagnostics = useMemo(() => (project.length === 0 ? reported : [...reported, ...project]), [reported, project]);

  return (
    <div className="diagnostics" data-testid="diagnostics">
      {diagnostics.length === 0 ? (
        <p className="panel-empty">
          <CheckIcon className="panel-empty__icon panel-empty__icon--ok" />
          {t('diagnostics.none')}
        </p>
      ) : (
        <ul className="diagnostics__list" aria-label={t('diagnostics.listLabel', { count: diagnostics.length })}>
          {sorted(diagnostics).map((diagnostic, index) => (
            <DiagnosticRow
              key={`${diagnostic.code}-${spanText(diagnostic.span)}-${index}`}
              diagnostic={diagnostic}
              onOpen={onOpen}
            />
          ))}
        </ul>
      )}
      <CpuDiagnostics onOpen={onOpenCpuEntry} />
    </div>
  );
}

/**
 * The errors and warnings the Diagnostics panel lists (the reported ones and the compiler's of
 * the active project, as they are now): what the panel's tab and the status bar count, so the two
 * always agree. Notes (info) are listed but not counted, as STEP 7 counts errors and warnings.
 */
export function useDiagnosticCounts(store: DiagnosticsStore = diagnosticsStore): { errors: number; warnings: number } {
  const reported = useDiagnostics(store);
  const project = useProjectDiagnostics();
  return useMemo(() => countProblems([...reported, ...project]), [reported, project]);
}

/** The panel tab's number: the errors and warnings it lists. */
export function useProblemCount(store: DiagnosticsStore = diagnosticsStore): number {
  const { errors, warnings } = useDiagnosticCounts(store);
  return errors + warnings;
}

/**
 * The Diagnostics panel of the workbench: the reported problems and the compiler's diagnostics
 * of the active project, each opening its file at its line, and the CPU's diagnostic buffer.
 */
export function WorkbenchDiagnostics() {
  const project = useProjectDiagnostics();
  const open = useOpenDiagnostic();
  const openEntry = useOpenCpuEntry();
  return <DiagnosticsList project={project} onOpen={open} onOpenCpuEntry={openEntry} />;
}
