import { useEffect, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { getFile } from '../api/client';
import { flushFile } from '../editor/autosave';
import { useEditorTabs, type SourceTab } from '../editor/EditorTabsContext';
import { SourceView } from '../editor/SourceView';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { useSymbolRowRequest } from './symbolSelection';
import { SymbolTableView } from './SymbolTableView';

export type SymbolTabView = 'table' | 'text';

/** Which view each symbol table tab shows, by tab id (kept while the page lives). */
const chosen = new Map<string, SymbolTabView>();

/**
 * A symbol table tab: the table editor, or its raw text in the code editor. The text view stays
 * mounted behind the table (it keeps its undo history); switching saves what the view being left
 * has not saved and gives the other view the server's newest copy, so the two never save over
 * each other.
 */
export function SymbolTableTab({ tab, active }: { tab: SourceTab; active: boolean }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const { replaceText } = useEditorTabs();
  const [view, setView] = useState<SymbolTabView>(() => chosen.get(tab.id) ?? (tab.file ? 'table' : 'text'));
  // A new text editor (with a new autosave from the tab's text and version) after table edits.
  const [generation, setGeneration] = useState(0);
  const [busy, setBusy] = useState(false);
  const file = tab.file;
  // F12 on a symbol: the table view, where its row is selected.
  const rowRequest = useSymbolRowRequest(file?.projectId ?? -1, file?.path ?? '');
  const requestSeq = rowRequest?.seq ?? 0;

  const switchTo = async (next: SymbolTabView) => {
    if (next === view || busy || !file) return;
    setBusy(true);
    try {
      await flushFile(file.projectId, file.path).catch(() => undefined);
      if (next === 'text') {
        const theirs = await getFile(file.projectId, file.path).catch(() => null);
        if (theirs && (theirs.text !== tab.text || theirs.version !== tab.version)) {
          replaceText(tab.id, theirs.text, theirs.version);
          setGeneration((count) => count + 1);
        }
      }
      chosen.set(tab.id, next);
      setView(next);
    } finally {
      setBusy(false);
    }
  };

  useEffect(() => {
    if (requestSeq > 0 && view === 'text') void switchTo('table');
    // Only a new request switches; the user may go back to the text afterwards.
  }, [requestSeq]);

  return (
    <div className="symbol-tab" hidden={!active} data-testid={`symbol-tab-${tab.id}`}>
      {file ? (
        <div className="symbol-tab__views" role="group" aria-label={t('symbolTable.viewLabel')} dir={dir} lang={language}>
          {(['table', 'text'] as const).map((item) => (
            <button
              key={item}
              type="button"
              className={`button button--small${view === item ? ' button--primary' : ''}`}
              aria-pressed={view === item}
              disabled={busy}
              data-testid={`symbol-view-${item}`}
              onClick={() => void switchTo(item)}
            >
              {t(item === 'table' ? 'symbolTable.viewTable' : 'symbolTable.viewText')}
            </button>
          ))}
        </div>
      ) : null}
      {file && view === 'table' ? <SymbolTableView tabId={tab.id} file={file} active={active} /> : null}
      <SourceView key={`${tab.id}-${generation}`} tab={tab} active={active && view === 'text'} />
    </div>
  );
}
