import { useEffect, useRef, useState, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import type { editor as MonacoEditor, IDisposable } from 'monaco-editor/editor/editor.api';
import type { Severity } from '../api/types';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { loadMonaco, type MonacoApi } from './monaco/load';
import { THEME_NAME } from './monaco/constants';
import { bindModel, type ModelSource } from './intellisense/modelRegistry';

export type SourceLanguage = 'stl' | 'scl' | 'lad' | 'fbd' | 'graph' | 'symbols' | 'cpu' | 'plant';

/** Monaco's language of each source language: LAD and FBD share their text format, symbol
 * tables are plain CSV-like text. */
const MODEL_LANGUAGE: Record<SourceLanguage, string> = {
  stl: 'stl',
  scl: 'scl',
  lad: 'lad',
  fbd: 'lad',
  graph: 'graph', // S7-Graph as text until the chart editor (editor/languages/graph.ts)
  symbols: 'plaintext',
  cpu: 'plaintext', // cpu.properties: key = value lines, shown as a page (cpuprops/)
  plant: 'plaintext', // <name>.plant: the project's virtual plant, YAML (plants/)
};

/** A place the editor should show (see `RevealRequest` of the tabs): a new object each time. */
export interface EditorReveal {
  line: number;
  column: number;
}

/** A problem to show in the text: 1-based lines and columns, the end column exclusive. */
export interface EditorMarker {
  line: number;
  column: number;
  endLine: number;
  endColumn: number;
  severity: Severity;
  /** The catalogue code (STL101, SIM502 ...), shown with the message. */
  code: string;
  message: string;
}

export interface CodeEditorProps {
  value: string;
  language: SourceLanguage;
  onChange?: (value: string) => void;
  markers?: readonly EditorMarker[];
  readOnly?: boolean;
  /** The name a screen reader announces for the text area. */
  ariaLabel: string;
  /** The text area lost the focus (the autosave saves then). */
  onBlur?: () => void;
  /** Scrolls to this place and puts the caret there whenever a new object is given. */
  reveal?: EditorReveal | null;
  /**
   * F12 or Ctrl+click (Cmd+click) on a word: the line's text and the 1-based column. The
   * context menu offers it as `definitionLabel`.
   */
  onGoToDefinition?: (lineText: string, column: number) => void;
  definitionLabel?: string;
  /** The project file the text is (completion and hover help use the project's outline). */
  source?: ModelSource | null;
  /**
   * What the editor shows beside or over the text once Monaco is ready (online monitoring,
   * breakpoints): rendered inside the editor's frame, given the editor and Monaco's API.
   */
  renderExtras?: (editor: MonacoEditor.IStandaloneCodeEditor, monaco: MonacoApi) => ReactNode;
  className?: string;
  'data-testid'?: string;
}

/** Draws what the editor shows beside or over its text (see `CodeEditorProps.renderExtras`). */
export type RenderEditorExtras = NonNullable<CodeEditorProps['renderExtras']>;

/** The bundled JetBrains Mono (styles/fonts.css), Vazirmatn for Arabic/Persian comments. */
const FONT_FAMILY = "'JetBrains Mono Variable', 'JetBrains Mono', 'Vazirmatn Variable', ui-monospace, monospace";
const FONT_SIZE = 13;
/** The height of a line in pixels (the STL status rows are drawn at the same height). */
export const LINE_HEIGHT = 20;
const NO_MARKERS: readonly EditorMarker[] = [];
const MARKER_OWNER = 'nasaq';

function severityOf(monaco: MonacoApi, severity: Severity): MonacoEditor.IMarkerData['severity'] {
  switch (severity) {
    case 'error':
      return monaco.MarkerSeverity.Error;
    case 'warning':
      return monaco.MarkerSeverity.Warning;
    default:
      return monaco.MarkerSeverity.Info;
  }
}

/** Waits (briefly) for the code font, so Monaco measures the glyphs it will draw. */
async function codeFontReady(): Promise<void> {
  const fonts = typeof document !== 'undefined' ? document.fonts : undefined;
  if (!fonts) return;
  const timeout = new Promise<void>((resolve) => setTimeout(resolve, 1500));
  await Promise.race([fonts.load(`${FONT_SIZE}px 'JetBrains Mono Variable'`).then(() => undefined), timeout]).catch(
    () => undefined,
  );
}

type Status = 'loading' | 'ready' | 'failed';

/**
 * A Monaco editor for an STL or SCL source. Monaco itself is loaded on first use (see
 * `monaco/load.ts`); until then a placeholder says so. The text always runs left to right,
 * whatever the interface language.
 */
export function CodeEditor({
  value,
  language,
  onChange,
  markers = NO_MARKERS,
  readOnly = false,
  ariaLabel,
  onBlur,
  reveal = null,
  onGoToDefinition,
  definitionLabel,
  renderExtras,
  source = null,
  className,
  'data-testid': testId,
}: CodeEditorProps) {
  const { t } = useTranslation();
  const { dir: uiDir } = useUiLanguage();
  const hostRef = useRef<HTMLDivElement>(null);
  const monacoRef = useRef<MonacoApi | null>(null);
  const editorRef = useRef<MonacoEditor.IStandaloneCodeEditor | null>(null);
  const onChangeRef = useRef(onChange);
  const onBlurRef = useRef(onBlur);
  const definitionRef = useRef(onGoToDefinition);
  const sourceRef = useRef(source);
  sourceRef.current = source;
  const applyingValue = useRef(false);
  const [status, setStatus] = useState<Status>('loading');
  const [attempt, setAttempt] = useState(0);

  // The latest props, read when the editor is created (it is created once, asynchronously).
  const initial = useRef({ value, language, readOnly, ariaLabel });
  initial.current = { value, language, readOnly, ariaLabel };
  useEffect(() => {
    onChangeRef.current = onChange;
    onBlurRef.current = onBlur;
    definitionRef.current = onGoToDefinition;
  }, [onChange, onBlur, onGoToDefinition]);

  useEffect(() => {
    let cancelled = false;
    const disposables: IDisposable[] = [];
    setStatus('loading');
    Promise.all([loadMonaco(), codeFontReady()])
      .then(([monaco]) => {
        const host = hostRef.current;
        if (cancelled || !host) return;
        const { value: text, language: lang, readOnly: ro, ariaLabel: label } = initial.current;
        const model = monaco.editor.createModel(text, MODEL_LANGUAGE[lang]);
        const editor = monaco.editor.create(host, {
          model,
          theme: THEME_NAME,
          readOnly: ro,
          ariaLabel: label,
          automaticLayout: true,
          fontFamily: FONT_FAMILY,
          fontSize: FONT_SIZE,
          fontLigatures: false,
          lineHeight: LINE_HEIGHT,
          minimap: { enabled: false },
          // STL has no nesting to guide, and each guide costs a layout read per line while
          // scrolling (the longest tasks of a 500-network block under monitoring).
          guides: { indentation: lang !== 'stl' },
          scrollBeyondLastLine: false,
          renderLineHighlight: 'all',
          tabSize: 4,
          insertSpaces: true,
          wordBasedSuggestions: 'currentDocument',
          fixedOverflowWidgets: true,
          // The hidden textarea, not Chromium's EditContext: with EditContext, keys typed 30 ms
          // apart lost characters in the browser tests (Chromium 156), and the textarea is the
          // input path screen readers have long been tested with.
          editContext: false,
          // Arabic or Persian comments are normal here: do not flag their letters as look-alikes.
          unicodeHighlight: { ambiguousCharacters: false, invisibleCharacters: true },
        });
        disposables.push(
          bindModel(model, () => sourceRef.current),
          model.onDidChangeContent(() => {
            if (!applyingValue.current) onChangeRef.current?.(model.getValue());
          }),
          editor,
          model,
        );
        monacoRef.current = monaco;
        editorRef.current = editor;
        // Fonts that arrive later (another script's subset) change glyph widths: measure again.
        void document.fonts?.ready.then(() => {
          if (!cancelled) monaco.editor.remeasureFonts();
        });
        setStatus('ready');
      })
      .catch(() => {
        if (!cancelled) setStatus('failed');
      });
    return () => {
      cancelled = true;
      monacoRef.current = null;
      editorRef.current = null;
      // In order: the listener, the editor, then its model (never a model still in use).
      for (const disposable of disposables) disposable.dispose();
    };
  }, [attempt]);

  // The text from outside (a file loaded, a lesson reset): replace it as one undoable edit.
  useEffect(() => {
    const model = editorRef.current?.getModel();
    if (status !== 'ready' || !model || model.getValue() === value) return;
    applyingValue.current = true;
    try {
      model.pushEditOperations([], [{ range: model.getFullModelRange(), text: value }], () => null);
    } finally {
      applyingValue.current = false;
    }
  }, [status, value]);

  useEffect(() => {
    const model = editorRef.current?.getModel();
    if (status === 'ready' && model && monacoRef.current) monacoRef.current.editor.setModelLanguage(model, MODEL_LANGUAGE[language]);
  }, [status, language]);

  useEffect(() => {
    if (status === 'ready') editorRef.current?.updateOptions({ readOnly, ariaLabel });
  }, [status, readOnly, ariaLabel]);

  useEffect(() => {
    const monaco = monacoRef.current;
    const model = editorRef.current?.getModel();
    if (status !== 'ready' || !monaco || !model) return;
    monaco.editor.setModelMarkers(
      model,
      MARKER_OWNER,
      markers.map((marker) => ({
        startLineNumber: marker.line,
        startColumn: marker.column,
        endLineNumber: marker.endLine,
        endColumn: marker.endColumn,
        severity: severityOf(monaco, marker.severity),
        code: marker.code,
        message: marker.message,
      })),
    );
  }, [status, markers]);

  const hasBlur = onBlur !== undefined;
  useEffect(() => {
    const editor = editorRef.current;
    if (status !== 'ready' || !editor || !hasBlur) return;
    const subscription = editor.onDidBlurEditorText(() => onBlurRef.current?.());
    return () => subscription.dispose();
  }, [status, hasBlur]);

  // Go to definition: F12 and the context menu, and Ctrl+click (Cmd+click) on a word.
  const hasDefinition = onGoToDefinition !== undefined;
  useEffect(() => {
    const monaco = monacoRef.current;
    const editor = editorRef.current;
    if (status !== 'ready' || !monaco || !editor || !hasDefinition) return;
    const goTo = (lineNumber: number, column: number) => {
      const text = editor.getModel()?.getLineContent(lineNumber);
      if (text !== undefined) definitionRef.current?.(text, column);
    };
    const action = editor.addAction({
      id: 'nasaq.goToDefinition',
      label: definitionLabel ?? 'Go to definition',
      keybindings: [monaco.KeyCode.F12],
      contextMenuGroupId: 'navigation',
      contextMenuOrder: 1,
      run: (ed) => {
        const position = ed.getPosition();
        if (position) goTo(position.lineNumber, position.column);
      },
    });
    const click = editor.onMouseDown((event) => {
      const position = event.target.position;
      if (!position || !(event.event.ctrlKey || event.event.metaKey) || event.event.leftButton === false) return;
      goTo(position.lineNumber, position.column);
    });
    return () => {
      click.dispose();
      action.dispose();
    };
  }, [status, hasDefinition, definitionLabel]);

  useEffect(() => {
    const editor = editorRef.current;
    if (status !== 'ready' || !editor || !reveal) return;
    // The tab may have come to the front in this very render: measure before scrolling.
    editor.layout();
    editor.setPosition({ lineNumber: reveal.line, column: reveal.column });
    editor.revealLineInCenter(reveal.line);
    editor.focus();
  }, [status, reveal]);

  const classes = ['code-editor', className].filter(Boolean).join(' ');
  const readyEditor = status === 'ready' ? editorRef.current : null;
  const readyMonaco = status === 'ready' ? monacoRef.current : null;
  return (
    <div className={classes} dir="ltr" data-testid={testId} data-state={status}>
      <div ref={hostRef} className="code-editor__host" />
      {renderExtras && readyEditor && readyMonaco ? renderExtras(readyEditor, readyMonaco) : null}
      {status === 'loading' ? (
        <p className="code-editor__message" role="status" dir={uiDir}>
          {t('editor.code.loading')}
        </p>
      ) : null}
      {status === 'failed' ? (
        <div className="code-editor__message" role="alert" dir={uiDir}>
          <p>{t('editor.code.loadFailed')}</p>
          <button type="button" className="button" onClick={() => setAttempt((n) => n + 1)}>
            {t('common.retry')}
          </button>
        </div>
      ) : null}
    </div>
  );
}
