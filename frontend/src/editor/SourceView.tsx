import { useCallback, useEffect, useRef, useState } from 'react';
import { useTranslation } from 'react-i18next';
import type { ApiError } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { projectContents } from '../projects/projectContents';
import { ErrorIcon, WarningIcon } from '../ui/icons';
import type { Problem } from '../api/monitorClient';
import { CodeEditor, LINE_HEIGHT, type RenderEditorExtras } from './CodeEditor';
import { EditorMonitoring } from './monitoring/EditorMonitoring';
import { MonitorToggle, monitorToggleOf, rememberMonitorToggle } from './monitoring/MonitorToggle';
import { requestSymbolRow } from '../symbols/symbolSelection';
import { findDefinition } from './definitions';
import { outlines } from './intellisense/outlineStore';
import { useEditorTabs, type SaveStatus, type SourceTab } from './EditorTabsContext';
import { useOpenProjectFile } from './useOpenProjectFile';
import { useSourceFile } from './useSourceFile';
import { LadSourceViews, StlSourceViews, type DiagramView } from '../lad/DiagramViews';
import { GraphSourceViews, drawsBlock, type GraphView } from '../graph/GraphSourceViews';
import { XrefEditorActions } from '../xref/XrefEditorActions';
import './source.css';

const LANGUAGE_NAMES = { stl: 'STL', scl: 'SCL', lad: 'LAD', fbd: 'FBD', graph: 'S7-Graph', cpu: 'CPU', plant: 'YAML' } as const;

/** How long "no definition here" stays in the status line. */
const NOTICE_MS = 4000;

function ProblemText({ error }: { error: ApiError }) {
  const errorText = useApiErrorText();
  return (
    <>
      <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
    </>
  );
}

/** What the status line says about the save of a file tab. */
function SaveStatusText({ status }: { status: SaveStatus }) {
  const { t } = useTranslation();
  return <span className="source-status__save">{t(`editor.save.${status}`)}</span>;
}

/** One source tab's editor, with the autosave, live diagnostics and go to definition of its file. */
export function SourceView({ tab, active }: { tab: SourceTab; active: boolean }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { updateSource } = useEditorTabs();
  const session = useSourceFile(tab);
  const openFile = useOpenProjectFile();
  const [notice, setNotice] = useState<string | null>(null);
  const [monitoring, setMonitoring] = useState(() => monitorToggleOf(tab.id));
  const [monitorProblem, setMonitorProblem] = useState<Problem | null>(null);
  const [diagramView, setDiagramView] = useState<DiagramView | null>(null);
  const [graphView, setGraphView] = useState<GraphView | null>(null);
  const noticeTimer = useRef<ReturnType<typeof setTimeout> | null>(null);
  const file = tab.file;

  useEffect(() => () => {
    if (noticeTimer.current !== null) clearTimeout(noticeTimer.current);
  }, []);

  const showNotice = useCallback((text: string) => {
    setNotice(text);
    if (noticeTimer.current !== null) clearTimeout(noticeTimer.current);
    noticeTimer.current = setTimeout(() => setNotice(null), NOTICE_MS);
  }, []);

  const fileRef = useRef(file);
  fileRef.current = file;
  const goToDefinition = useCallback(
    async (lineText: string, column: number) => {
      const target = fileRef.current;
      if (!target) return;
      const blocks = projectContents.get(target.projectId)?.blocks ?? [];
      // The symbols come with the project's outline, which may not have been read yet.
      const outline = outlines.get(target.projectId) ?? (await outlines.ready(target.projectId));
      const block = findDefinition(blocks, lineText, column, outline?.symbols);
      if (!block) {
        showNotice(t('editor.definition.notFound'));
        return;
      }
      const at = block.line != null ? { line: block.line } : null;
      if ('symbol' in block && block.symbol) requestSymbolRow(target.projectId, block.file, block.symbol);
      openFile(target.projectId, block.file, at).catch(() => showNotice(t('editor.definition.openFailed', { name: block.file })));
    },
    [openFile, showNotice, t],
  );

  const label =
    tab.language === 'symbols'
      ? t('editor.code.symbolsLabel', { name: tab.name })
      : t('editor.code.label', { language: LANGUAGE_NAMES[tab.language], name: tab.name });
  const save = tab.save;
  const toggleMonitoring = useCallback(
    (on: boolean) => {
      rememberMonitorToggle(tab.id, on);
      setMonitoring(on);
    },
    [tab.id],
  );
  // Monitoring and breakpoints follow STL and SCL lines, and a LAD/FBD block's networks in its
  // diagram (its element status needs the rung, not the text).
  const codeLanguage = tab.language === 'stl' || tab.language === 'scl' ? tab.language : null;
  const diagramFile = tab.language === 'lad' || tab.language === 'fbd';
  const diagramMonitoring = diagramFile && (diagramView === 'LAD' || diagramView === 'FBD');
  // An S7-Graph FB is monitored in its drawn views (chart, step, permanent instructions).
  const graphMonitoring = tab.language === 'graph' && drawsBlock(graphView);
  const renderExtras: RenderEditorExtras | undefined =
    file && codeLanguage
      ? (editor, monaco) => (
          <>
            <EditorMonitoring
              editor={editor}
              monaco={monaco}
              projectId={file.projectId}
              file={file.path}
              language={codeLanguage}
              monitoring={monitoring && active}
              lineHeight={LINE_HEIGHT}
              onProblem={setMonitorProblem}
            />
            <XrefEditorActions editor={editor} monaco={monaco} projectId={file.projectId} onNothing={showNotice} />
          </>
        )
      : file && tab.language === 'graph'
        ? // An S7-Graph FB as text: cross-references work; its online status is the chart's.
          (editor, monaco) => <XrefEditorActions editor={editor} monaco={monaco} projectId={file.projectId} onNothing={showNotice} />
        : undefined;

  const codeEditor = (
    <CodeEditor
      value={tab.text}
      language={tab.language}
      markers={session.markers}
      onChange={(text) => updateSource(tab.id, text)}
      onBlur={file ? session.flush : undefined}
      reveal={tab.reveal}
      onGoToDefinition={file ? goToDefinition : undefined}
      definitionLabel={t('editor.definition.label')}
      source={file ? { projectId: file.projectId, path: file.path } : null}
      renderExtras={renderExtras}
      ariaLabel={label}
      className="source-view__editor"
      data-testid="code-editor"
    />
  );

  return (
    <div className="source-view" hidden={!active} data-testid={`source-view-${tab.id}`}>
      {file && save.status === 'conflict' && save.error ? (
        <div className="source-banner source-banner--conflict" role="alert" dir={dir} lang={language} data-testid="save-conflict">
          <WarningIcon className="source-banner__icon" />
          <p className="source-banner__text">
            <ProblemText error={save.error} />
          </p>
          <div className="source-banner__actions">
            <button
              type="button"
              className="button button--small"
              data-testid="save-conflict-reload"
              onClick={() => void session.reload()}
            >
              {t('editor.conflict.reload')}
            </button>
            <button
              type="button"
              className="button button--small button--primary"
              data-testid="save-conflict-overwrite"
              onClick={session.overwrite}
            >
              {t('editor.conflict.overwrite')}
            </button>
          </div>
          {session.reloadError ? (
            <p className="source-banner__text">
              <ProblemText error={session.reloadError} />
            </p>
          ) : null}
        </div>
      ) : null}
      {file && save.status === 'failed' && save.error ? (
        <div className="source-banner source-banner--failed" role="alert" dir={dir} lang={language} data-testid="save-failed">
          <ErrorIcon className="source-banner__icon" />
          <p className="source-banner__text">
            {t('editor.save.failedText')} <ProblemText error={save.error} />
          </p>
          <div className="source-banner__actions">
            <button type="button" className="button button--small" onClick={session.flush}>
              {t('editor.save.retry')}
            </button>
          </div>
        </div>
      ) : null}
      {diagramFile ? (
        <LadSourceViews
          tab={tab}
          active={active}
          monitoring={monitoring && active}
          onMonitorProblem={setMonitorProblem}
          onViewChange={setDiagramView}
          textEditor={codeEditor}
        />
      ) : tab.language === 'graph' ? (
        <GraphSourceViews
          tab={tab}
          active={active}
          monitoring={monitoring && active}
          onMonitorProblem={setMonitorProblem}
          onViewChange={setGraphView}
          textEditor={codeEditor}
        />
      ) : tab.language === 'stl' ? (
        <StlSourceViews tab={tab} active={active} stlEditor={codeEditor} />
      ) : (
        codeEditor
      )}
      {file ? (
        <div className="source-status" dir={dir} lang={language}>
          <span className="source-status__state" data-testid={`save-state-${tab.id}`} data-state={save.status}>
            <SaveStatusText status={save.status} />
          </span>
          <span className="source-status__notice" role="status">
            {notice}
          </span>
          {codeLanguage || diagramMonitoring || graphMonitoring ? (
            <MonitorToggle on={monitoring} onChange={toggleMonitoring} projectId={file.projectId} problem={monitorProblem} />
          ) : null}
        </div>
      ) : null}
    </div>
  );
}
