/**
 * One block, three views, as in STEP 7: a LAD/FBD source is shown as LAD, as FBD or as STL
 * (and as its text), and an STL source can be looked at as LAD or FBD without changing it until
 * the user converts it.
 *
 * - LAD <-> FBD always works; switching sets the blocks' language, which the file keeps.
 * - To STL always works (the STL the blocks compile to); what is typed in the STL view goes
 *   back network by network when the user leaves it: a network that has no LAD shape stays an
 *   STL network of the block, with its reason.
 * - The text view is the file itself.
 */
import { useCallback, useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, convertFile, convertSource, getFile, type ApiError } from '../api/client';
import type { Problem } from '../api/monitorClient';
import type { Diagnostic } from '../api/types';
import { CodeEditor } from '../editor/CodeEditor';
import { useDiagnosticMessage } from '../editor/diagnosticMarkers';
import { useEditorTabs, type SourceTab } from '../editor/EditorTabsContext';
import { setPendingEdit } from '../editor/unsaved';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { projectContents } from '../projects/projectContents';
import { LadEditor } from './LadEditor';
import { setLanguage } from './ladCommands';
import { mergeLifted } from './stlView';
import type { LadBlock } from './model';
import { useLadDocument, type LadDocument } from './useLadDocument';

export type DiagramView = 'LAD' | 'FBD' | 'STL' | 'text';

/** Each tab's view, while the page lives (a tab's view may remount). */
const views = new Map<string, DiagramView>();

function ViewBar({ views: choices, view, onView, extra }: { views: readonly DiagramView[]; view: DiagramView; onView: (view: DiagramView) => void; extra?: ReactNode }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  return (
    <div className="view-bar" dir={dir} lang={language}>
      <div className="view-bar__choices" role="group" aria-label={t('lad.views.label')}>
        {choices.map((choice) => (
          <button
            key={choice}
            type="button"
            className="view-bar__choice"
            aria-pressed={view === choice}
            data-testid={`view-${choice}`}
            onClick={() => onView(choice)}
          >
            {t(`lad.views.${choice}`)}
          </button>
        ))}
      </div>
      {extra}
    </div>
  );
}

/**
 * Why a diagram cannot be drawn: the file's syntax errors with their lines, or the server could
 * not read it. Shared by the LAD/FBD views and the S7-Graph chart (`kind` picks the texts'
 * namespace and the test ids).
 */
export function CannotDraw({ kind, problems, error, onText, onRetry }: { kind: 'lad' | 'graph'; problems: readonly Diagnostic[]; error: ApiError | null; onText: () => void; onRetry: () => void }) {
  const { t } = useTranslation();
  const message = useDiagnosticMessage();
  const errorText = useApiErrorText();
  const { dir, language } = useUiLanguage();
  const texts = kind === 'lad' ? 'lad.cannot' : 'graphChart.cannot';
  return (
    <div className="cannot-draw" role="alert" dir={dir} lang={language} data-testid={`${kind}-cannot-draw`}>
      <h3 className="cannot-draw__title">{error ? t(`${texts}.serverTitle`) : t(`${texts}.title`)}</h3>
      <p>{error ? t(`${texts}.serverText`) : t(`${texts}.text`)}</p>
      {error ? (
        <p>
          <code className="error-code">{error.code}</code> {errorText(error)}
        </p>
      ) : (
        <ul className="cannot-draw__list">
          {problems.slice(0, 20).map((problem, k) => (
            <li key={k}>
              <code className="error-code">{problem.code}</code>{' '}
              <span dir="ltr">{problem.span?.line ? t(`${texts}.line`, { line: problem.span.line }) : null}</span> {message(problem)}
            </li>
          ))}
        </ul>
      )}
      <div className="cannot-draw__actions">
        <button type="button" className="button button--primary" data-testid={`${kind}-show-text`} onClick={onText}>
          {t(`${texts}.showText`)}
        </button>
        {error ? (
          <button type="button" className="button" onClick={onRetry}>
            {t(`${texts}.retry`)}
          </button>
        ) : null}
      </div>
    </div>
  );
}

interface StlViewState {
  text: string;
  /** The STL the blocks stand for now (as converted, or as last taken back). */
  original: string;
  error: ApiError | null;
  /** Why the typed STL cannot go back to the blocks yet (its syntax errors). */
  problems: readonly Diagnostic[];
}

/** How long typing in the STL view must rest before the text goes back to the blocks (and is saved). */
const STL_APPLY_MS = 1500;

/** The STL of a LAD/FBD file's blocks, editable; changes go back after a pause and when the view is left. */
function useStlView(tab: SourceTab, on: boolean) {
  const [state, setState] = useState<StlViewState | null>(null);
  const [attempt, setAttempt] = useState(0);
  useEffect(() => {
    if (!on) return;
    const request = new AbortController();
    convertSource(tab.name, tab.text, 'stl', request.signal).then(
      (converted) => setState({ text: converted.text, original: converted.text, error: null, problems: [] }),
      (error: unknown) => {
        if (!request.signal.aborted) setState({ text: '', original: '', error: asApiError(error), problems: [] });
      },
    );
    return () => request.abort();
    // Converted when the view opens (or is tried again); the view's own edits go the other way.
  }, [on, attempt]);
  const retry = useCallback(() => {
    setState(null);
    setAttempt((n) => n + 1);
  }, []);
  return [state, setState, retry] as const;
}

function stemOf(name: string): string {
  const dot = name.lastIndexOf('.');
  return dot > 0 ? name.slice(0, dot) : name;
}

export interface LadSourceViewsProps {
  tab: SourceTab;
  active: boolean;
  monitoring: boolean;
  onMonitorProblem: (problem: Problem | null) => void;
  /** The file's text editor (Monaco), shown in the text view. */
  textEditor: ReactNode;
  /** The status line's extra (the view follows the user's choice). */
  onViewChange?: (view: DiagramView) => void;
}

/** The views of a `.lad`/`.fbd` file. */
export function LadSourceViews({ tab, active, monitoring, onMonitorProblem, textEditor, onViewChange }: LadSourceViewsProps) {
  const { t } = useTranslation();
  const { updateSource } = useEditorTabs();
  const [view, setViewState] = useState<DiagramView>(() => views.get(tab.id) ?? (tab.language === 'fbd' ? 'FBD' : 'LAD'));
  const [textShown, setTextShown] = useState(view === 'text');
  const setText = useCallback((text: string) => updateSource(tab.id, text), [updateSource, tab.id]);
  const doc = useLadDocument(tab.name, tab.text, setText, view !== 'text');
  const [stl, setStl, retryStl] = useStlView(tab, view === 'STL');
  const [busy, setBusy] = useState(false);
  const initialView = useRef(views.has(tab.id));

  // A file that cannot be drawn opens in its text view (the diagram views say why).
  useEffect(() => {
    if (doc.state.status !== 'unreadable' || initialView.current) return;
    initialView.current = true;
    setTextShown(true);
    setViewState('text');
  }, [doc.state.status]);

  // The first time the file is read, the view follows the blocks' language (an FBD block in a .lad file).
  useEffect(() => {
    if (initialView.current || !doc.blocks || doc.blocks.length === 0) return;
    initialView.current = true;
    const language = doc.blocks[0]?.language;
    if (language && language !== view && (view === 'LAD' || view === 'FBD')) setViewState(language);
  }, [doc.blocks, view]);

  /** The typed STL back to the blocks, network by network; false while it cannot (it stays in the view). */
  const applyStl = useCallback(async (): Promise<boolean> => {
    if (!stl || stl.error || stl.text === stl.original) return true;
    const typed = stl.text;
    setBusy(true);
    try {
      const language = doc.blocks?.[0]?.language === 'FBD' ? 'fbd' : 'lad';
      const converted = await convertSource(`${stemOf(tab.name)}.awl`, typed, language);
      const blocks = converted.blocks;
      const problems = converted.diagnostics.filter((d) => d.severity === 'error');
      if (!blocks || problems.length > 0) {
        setStl((current) => (current ? { ...current, problems } : current));
        return false;
      }
      const shown = stl.original;
      doc.edit((model) => mergeLifted(model, shown, typed, blocks) ?? blocks, t('lad.undo.stl'));
      setStl((current) => (current ? { ...current, original: typed, problems: [] } : current));
      return true;
    } catch (caught) {
      setStl((current) => (current ? { ...current, problems: [], error: asApiError(caught) } : current));
      return false;
    } finally {
      setBusy(false);
    }
  }, [stl, setStl, doc, tab.name, t]);

  // What is typed in the STL view goes back to the file after a pause: nothing waits for the view to be left.
  const applyRef = useRef(applyStl);
  applyRef.current = applyStl;
  useEffect(() => {
    if (!stl || stl.text === stl.original) return;
    const timer = setTimeout(() => void applyRef.current(), STL_APPLY_MS);
    return () => clearTimeout(timer);
  }, [stl]);
  // Typed STL not yet taken back: a reload asks first (editor/unsaved).
  const stlPending = !!stl && !stl.error && stl.text !== stl.original;
  useEffect(() => {
    setPendingEdit(`${tab.id}:stl`, stlPending);
    return () => setPendingEdit(`${tab.id}:stl`, false);
  }, [stlPending, tab.id]);

  const choose = useCallback(
    async (next: DiagramView) => {
      if (next === view || busy) return;
      if (view === 'STL' && !(await applyStl())) return;
      if ((next === 'LAD' || next === 'FBD') && doc.state.status === 'ready') {
        doc.edit((blocks) => setLanguage(blocks, next), t(next === 'FBD' ? 'lad.undo.toFbd' : 'lad.undo.toLad'));
      }
      if (next === 'STL') setStl(null);
      if (next === 'text') setTextShown(true);
      views.set(tab.id, next);
      setViewState(next);
      onViewChange?.(next);
    },
    [view, busy, applyStl, doc, t, setStl, tab.id, onViewChange],
  );

  useEffect(() => onViewChange?.(view), [view, onViewChange]);

  const diagram = view === 'LAD' || view === 'FBD';
  const file = tab.file;
  return (
    <div className="diagram-views">
      <ViewBar views={['LAD', 'FBD', 'STL', 'text']} view={view} onView={(next) => void choose(next)} extra={busy ? <span className="view-bar__busy">{t('lad.views.converting')}</span> : null} />
      <div className="diagram-views__content" hidden={!diagram}>
        {diagram ? (
          <DiagramOrReason doc={doc} onText={() => void choose('text')}>
            <LadEditor
              doc={doc}
              text={tab.text}
              projectId={file?.projectId ?? null}
              file={file?.path ?? null}
              mode={view === 'FBD' ? 'FBD' : 'LAD'}
              active={active && diagram}
              readOnly={false}
              monitoring={monitoring}
              onMonitorProblem={onMonitorProblem}
              reveal={tab.reveal}
            />
          </DiagramOrReason>
        ) : null}
      </div>
      {view === 'STL' ? (
        <div className="diagram-views__content" data-testid="lad-stl-view">
          {stl === null ? (
            <p className="diagram-views__loading">{t('lad.views.converting')}</p>
          ) : stl.error ? (
            <CannotDraw kind="lad" problems={[]} error={stl.error} onText={() => void choose('text')} onRetry={retryStl} />
          ) : (
            <>
              {stl.problems.length > 0 ? <StlProblems problems={stl.problems} /> : null}
              <CodeEditor value={stl.text} language="stl" onChange={(text) => setStl((current) => (current ? { ...current, text } : current))} ariaLabel={t('lad.views.stlLabel', { name: tab.name })} className="source-view__editor" data-testid="stl-view-editor" />
            </>
          )}
        </div>
      ) : null}
      <div className="diagram-views__content" hidden={view !== 'text'}>
        {textShown || view === 'text' ? textEditor : null}
      </div>
    </div>
  );
}

/** Why the typed STL does not go back to the blocks yet: its syntax errors, with their lines. */
function StlProblems({ problems }: { problems: readonly Diagnostic[] }) {
  const { t } = useTranslation();
  const message = useDiagnosticMessage();
  const { dir, language } = useUiLanguage();
  return (
    <div className="stl-problems" role="alert" dir={dir} lang={language} data-testid="lad-stl-problems">
      <p>{t('lad.views.stlProblems')}</p>
      <ul className="cannot-draw__list">
        {problems.slice(0, 10).map((problem, k) => (
          <li key={k}>
            <code className="error-code">{problem.code}</code> <span dir="ltr">{problem.span?.line ? t('lad.cannot.line', { line: problem.span.line }) : null}</span> {message(problem)}
          </li>
        ))}
      </ul>
    </div>
  );
}

function DiagramOrReason({ doc, onText, children }: { doc: LadDocument; onText: () => void; children: ReactNode }) {
  const { t } = useTranslation();
  if (doc.state.status === 'unreadable') return <CannotDraw kind="lad" problems={doc.state.problems} error={null} onText={onText} onRetry={doc.retry} />;
  if (doc.state.status === 'failed' && !doc.blocks) return <CannotDraw kind="lad" problems={[]} error={doc.state.error} onText={onText} onRetry={doc.retry} />;
  if (!doc.blocks) return <p className="diagram-views__loading">{t('lad.views.reading')}</p>;
  return <>{children}</>;
}

// -- an STL source shown as LAD/FBD ----------------------------------------------------------------

interface Shown {
  blocks: LadBlock[] | null;
  converted: number;
  kept: number;
  error: ApiError | null;
}

/** The STL text lifted to LAD/FBD, as a document nothing can change. */
function useLiftedDocument(tab: SourceTab, to: 'lad' | 'fbd' | null): { doc: LadDocument; shown: Shown | null } {
  const [shown, setShown] = useState<Shown | null>(null);
  const [attempt, setAttempt] = useState(0);
  useEffect(() => {
    if (!to) return;
    const request = new AbortController();
    convertSource(tab.name, tab.text, to, request.signal).then(
      (converted) => setShown({ blocks: converted.blocks, converted: converted.converted, kept: converted.kept, error: null }),
      (error: unknown) => {
        if (!request.signal.aborted) setShown({ blocks: null, converted: 0, kept: 0, error: asApiError(error) });
      },
    );
    return () => request.abort();
  }, [tab.name, tab.text, to, attempt]);
  const doc = useMemo<LadDocument>(() => {
    const nothing = () => undefined;
    const state: LadDocument['state'] = shown === null ? { status: 'loading' } : shown.error ? { status: 'failed', error: shown.error } : { status: 'ready' };
    return { state, blocks: shown?.blocks ?? null, pending: false, edit: nothing, undo: nothing, redo: nothing, canUndo: false, canRedo: false, retry: () => setAttempt((n) => n + 1) };
  }, [shown]);
  return { doc, shown };
}

export interface StlAsDiagramProps {
  tab: SourceTab;
  active: boolean;
  /** The STL editor (with its monitoring), shown in the STL view. */
  stlEditor: ReactNode;
}

/** The views of an `.awl` source: STL (the file), or LAD/FBD to look at, and convert. */
export function StlSourceViews({ tab, active, stlEditor }: StlAsDiagramProps) {
  const { t } = useTranslation();
  const { openSource, closeFileTabs } = useEditorTabs();
  const [view, setView] = useState<DiagramView>(() => views.get(tab.id) ?? 'STL');
  const diagram = view === 'LAD' || view === 'FBD';
  const { doc, shown } = useLiftedDocument(tab, diagram ? (view === 'FBD' ? 'fbd' : 'lad') : null);
  const [problem, setProblem] = useState<ApiError | null>(null);
  const errorText = useApiErrorText();
  const file = tab.file;

  const convert = async () => {
    if (!file) return;
    setProblem(null);
    try {
      const made = await convertFile(file.projectId, file.path, view === 'FBD' ? 'fbd' : 'lad');
      closeFileTabs(file.projectId, file.path);
      projectContents.reloadSoon(file.projectId);
      const language = view === 'FBD' ? 'fbd' : 'lad';
      const loaded = await getFile(file.projectId, made.name);
      openSource({ name: made.name, language, text: loaded.text, file: { projectId: file.projectId, path: made.name }, version: loaded.version, dirty: false });
    } catch (caught) {
      setProblem(asApiError(caught));
    }
  };

  const banner = diagram ? (
    <div className="view-bar__note" data-testid="stl-as-diagram-note">
      <span>{shown ? t('lad.views.asDiagram', { converted: shown.converted, kept: shown.kept, view }) : t('lad.views.converting')}</span>
      {file ? (
        <button type="button" className="button button--small button--primary" data-testid="convert-file" onClick={() => void convert()}>
          {t('lad.views.convert', { view })}
        </button>
      ) : null}
      {problem ? (
        <span className="view-bar__problem" role="alert">
          <code className="error-code">{problem.code}</code> {errorText(problem)}
        </span>
      ) : null}
    </div>
  ) : null;

  return (
    <div className="diagram-views">
      <ViewBar
        views={['STL', 'LAD', 'FBD']}
        view={view}
        onView={(next) => {
          views.set(tab.id, next);
          setView(next);
        }}
        extra={banner}
      />
      <div className="diagram-views__content" hidden={diagram}>
        {stlEditor}
      </div>
      {diagram ? (
        <div className="diagram-views__content">
          <DiagramOrReason doc={doc} onText={() => setView('STL')}>
            <LadEditor
              doc={doc}
              text=""
              projectId={file?.projectId ?? null}
              file={null}
              mode={view === 'FBD' ? 'FBD' : 'LAD'}
              active={active}
              readOnly
              monitoring={false}
              onMonitorProblem={() => undefined}
            />
          </DiagramOrReason>
        </div>
      ) : null}
    </div>
  );
}
