import { useTranslation } from 'react-i18next';
import { useDiagnosticCounts } from '../panels/DiagnosticsList';
import { useActiveProject } from '../projects/ActiveProject';
import { Icon, type IconProps } from '../ui/icons';
import { useCompile } from './compile';
import { ariaKeys, keyText } from './shortcuts';
import './shortcuts.css';

/** Compile: a page with a check mark, as the toolbar draws its other actions (16×16, currentColor). */
function CompileIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M3.5 1.5h6l3 3v10h-9z" />
      <path d="M5.5 9.5l2 2 3.5-4" />
    </Icon>
  );
}

/** The toolbar's Compile button (Ctrl+F7), beside Download. */
export function CompileButton() {
  const { t } = useTranslation();
  const { projectId } = useActiveProject();
  const { compiling, compile } = useCompile();
  const shortcut = keyText('compile');
  const reason = projectId === null ? ` — ${t('cpu.reason.noProject')}` : '';
  return (
    <button
      type="button"
      className="cpu-button cpu-button--compile"
      data-testid="cpu-compile"
      disabled={projectId === null || compiling}
      aria-keyshortcuts={ariaKeys('compile')}
      aria-busy={compiling}
      title={`${t('shortcuts.compile.label')} (${shortcut})${reason}`}
      onClick={() => void compile()}
    >
      <CompileIcon className="cpu-button__icon" />
      <span className="cpu-button__text cpu-button__text--word">
        {compiling ? t('shortcuts.compile.busy') : t('shortcuts.compile.text')}
      </span>
    </button>
  );
}

/**
 * The status bar's report of the last compile; a live region, so screen readers say it. Once
 * compiled, its counts are the Diagnostics panel's, kept current as the editors check what is
 * typed (never a snapshot that disagrees with the list below).
 */
export function CompileStatus() {
  const { t } = useTranslation();
  const { result, compiling } = useCompile();
  const counts = useDiagnosticCounts();
  let text = '';
  if (compiling) text = t('shortcuts.compile.busy');
  else if (result?.failed) text = t('shortcuts.compile.failed', { code: result.code });
  else if (result) text = t('shortcuts.compile.result', { errors: counts.errors, warnings: counts.warnings });
  const state = result === null || result.failed ? 'none' : counts.errors > 0 ? 'errors' : 'ok';
  return (
    <span className="status-item" role="status" data-testid="compile-status" data-state={compiling ? 'busy' : state}>
      {text}
    </span>
  );
}
