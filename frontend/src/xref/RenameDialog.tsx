import { useEffect, useRef, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, getFile, type ApiError } from '../api/client';
import { flushFile, reloadedFile } from '../editor/autosave';
import { useEditorTabs } from '../editor/EditorTabsContext';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { projectContents } from '../projects/projectContents';
import { Dialog } from '../ui/Dialog';
import { applyRename, previewRename, undoRename, type RenameApplied, type RenamePreview } from './api';
import { renameRequests, useRequest, type XrefRequest } from './xrefRequests';
import './xref.css';

/** The name the dialog offers to edit: a member's own name, a symbol without its quotes. */
function currentName(target: string): string {
  const member = /^"[^"]*"\.(.+)$/.exec(target) ?? /^DB\s*\d+\.(?!DB[XBWD])(.+)$/i.exec(target);
  if (member) return member[1] ?? '';
  return target.replace(/^"|"$/g, '');
}

type Stage =
  | { kind: 'edit' }
  | { kind: 'preview'; preview: RenamePreview }
  | { kind: 'applied'; applied: RenameApplied }
  | { kind: 'undone'; applied: RenameApplied };

/**
 * Rename (F2) of a symbol, a block or a DB member everywhere in the project: a preview of every
 * changed line, Apply, then Undo, which restores every file unless it changed meanwhile. Open
 * editor tabs save first and take the renamed text after.
 */
function RenameDialog({ request, onClose }: { request: XrefRequest; onClose: () => void }) {
  const { t } = useTranslation();
  const { dir } = useUiLanguage();
  const errorText = useApiErrorText();
  const { tabs, replaceText } = useEditorTabs();
  const [name, setName] = useState(() => currentName(request.target));
  const [stage, setStage] = useState<Stage>({ kind: 'edit' });
  const [error, setError] = useState<ApiError | null>(null);
  const [busy, setBusy] = useState(false);
  const input = useRef<HTMLInputElement>(null);
  const { projectId, target } = request;

  useEffect(() => {
    input.current?.select();
  }, []);

  async function refreshTabs(files: readonly string[]) {
    const open = new Set(
      tabs.filter((tab) => tab.kind === 'source' && tab.file?.projectId === projectId).map((tab) => tab.kind === 'source' ? tab.file?.path : ''),
    );
    await Promise.all(
      files
        .filter((file) => open.has(file))
        .map(async (file) => {
          const theirs = await getFile(projectId, file);
          reloadedFile(projectId, file, theirs.text, theirs.version);
          for (const tab of tabs) {
            if (tab.kind === 'source' && tab.file?.projectId === projectId && tab.file.path === file) {
              replaceText(tab.id, theirs.text, theirs.version);
            }
          }
        }),
    );
    void projectContents.reload(projectId);
  }

  async function run(step: () => Promise<void>) {
    setBusy(true);
    setError(null);
    try {
      await step();
    } catch (caught) {
      setError(asApiError(caught));
    } finally {
      setBusy(false);
    }
  }

  function preview(event?: FormEvent) {
    event?.preventDefault();
    void run(async () => {
      await flushFile(projectId);
      setStage({ kind: 'preview', preview: await previewRename(projectId, target, name) });
    });
  }

  function apply(shown: RenamePreview) {
    void run(async () => {
      const applied = await applyRename(projectId, shown);
      setStage({ kind: 'applied', applied });
      await refreshTabs(applied.files.map((file) => file.name));
    });
  }

  function undo(applied: RenameApplied) {
    void run(async () => {
      await flushFile(projectId);
      await undoRename(projectId, applied.undo);
      setStage({ kind: 'undone', applied });
      await refreshTabs(applied.undo.map((file) => file.name));
    });
  }

  const changes = stage.kind === 'preview' ? stage.preview.changes : stage.kind === 'applied' ? stage.applied.changes : [];
  const footer = (
    <>
      {stage.kind === 'edit' ? (
        <button type="submit" form="xref-rename-form" className="button button--primary" disabled={busy || !name}>
          {t('xref.rename.preview')}
        </button>
      ) : null}
      {stage.kind === 'preview' ? (
        <>
          <button type="button" className="button" onClick={() => setStage({ kind: 'edit' })} disabled={busy}>
            {t('xref.rename.back')}
          </button>
          <button type="button" className="button button--primary" onClick={() => apply(stage.preview)} disabled={busy}>
            {t('xref.rename.apply')}
          </button>
        </>
      ) : null}
      {stage.kind === 'applied' ? (
        <button type="button" className="button" onClick={() => undo(stage.applied)} disabled={busy}>
          {t('xref.rename.undo')}
        </button>
      ) : null}
      <button type="button" className="button" onClick={onClose}>
        {t('xref.rename.close')}
      </button>
    </>
  );

  return (
    <Dialog title={t('xref.rename.title')} onClose={onClose} footer={footer} testId="rename-dialog" size="medium" initialFocus={input}>
      <div dir={dir} className="xref-rename">
        <form id="xref-rename-form" className="form" onSubmit={preview}>
          <p>
            {t('xref.rename.what')} <code dir="ltr">{target}</code>
          </p>
          <div className="field">
            <label className="field__label" htmlFor="xref-new-name">
              {t('xref.rename.newName')}
            </label>
            <input
              ref={input}
              id="xref-new-name"
              className="input"
              dir="ltr"
              value={name}
              readOnly={stage.kind !== 'edit'}
              aria-invalid={error ? 'true' : undefined}
              onChange={(event) => setName(event.target.value)}
              data-testid="rename-new-name"
            />
          </div>
        </form>
        {error ? (
          <p className="field__error" role="alert" data-testid="rename-error">
            <code className="error-code">{error.code}</code> <span>{errorText(error)}</span>
          </p>
        ) : null}
        {stage.kind === 'preview' ? (
          <p role="status">{t('xref.rename.previewSummary', { count: changes.length, files: stage.preview.files.length })}</p>
        ) : null}
        {stage.kind === 'applied' ? (
          <p role="status" data-testid="rename-done">
            {t('xref.rename.applied', { count: changes.length, files: stage.applied.files.length })}
          </p>
        ) : null}
        {stage.kind === 'undone' ? (
          <p role="status" data-testid="rename-undone">
            {t('xref.rename.undone', { files: stage.applied.undo.length })}
          </p>
        ) : null}
        {changes.length > 0 ? (
          <table className="data-table xref__table xref__changes" data-testid="rename-changes">
            <thead>
              <tr>
                <th scope="col">{t('xref.column.file')}</th>
                <th scope="col">{t('xref.column.line')}</th>
                <th scope="col">{t('xref.rename.change')}</th>
              </tr>
            </thead>
            <tbody>
              {changes.map((change) => (
                <tr key={`${change.file}:${change.line}`} data-testid="rename-change">
                  <td>
                    <code dir="ltr">{change.file}</code>
                  </td>
                  <td>
                    <code dir="ltr">{change.line}</code>
                  </td>
                  <td dir="ltr">
                    <del className="xref__before">{change.before.trim()}</del>
                    <ins className="xref__after">{change.after.trim()}</ins>
                  </td>
                </tr>
              ))}
            </tbody>
          </table>
        ) : null}
      </div>
    </Dialog>
  );
}

/** Shows the rename dialog while the editor asks for one (F2). */
export function RenameHost() {
  const request = useRequest(renameRequests);
  if (!request) return null;
  return (
    <RenameDialog
      key={`${request.projectId}:${request.target}`}
      request={request}
      onClose={() => renameRequests.set(null)}
    />
  );
}
