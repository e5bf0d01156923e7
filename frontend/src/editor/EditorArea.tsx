import { useEffect, useRef } from 'react';
import { useTranslation } from 'react-i18next';
import { flushAll } from './autosave';
import { EditorEmptyState } from './EditorEmptyState';
import { EditorTabStrip } from './EditorTabStrip';
import { DbEditorView } from '../dbeditor/DbEditorView';
import { SymbolTableTab } from '../symbols/SymbolTableTab';
import { CpuPropertiesTab } from '../cpuprops/CpuPropertiesTab';
import { useEditorTabs, type DbTab, type EditorTab, type SourceTab } from './EditorTabsContext';
import { SourceView } from './SourceView';
import { StartPage } from './StartPage';
import { hasPendingEdits, holdsUnsavedText } from './unsaved';

/**
 * Saves every file tab when the page is hidden or closed (requests that outlive the page), and
 * asks before leaving while a text is not saved yet (pending, being saved, refused or failed).
 */
function useSaveOnLeave(tabs: readonly EditorTab[]) {
  const tabsRef = useRef(tabs);
  tabsRef.current = tabs;
  useEffect(() => {
    const save = () => void flushAll({ keepalive: true });
    const onVisibility = () => {
      if (document.visibilityState === 'hidden') save();
    };
    const onBeforeUnload = (event: BeforeUnloadEvent) => {
      save();
      if (tabsRef.current.some(holdsUnsavedText) || hasPendingEdits()) {
        event.preventDefault();
        // Older browsers ask only when a return value is set.
        event.returnValue = '';
      }
    };
    window.addEventListener('pagehide', save);
    window.addEventListener('beforeunload', onBeforeUnload);
    document.addEventListener('visibilitychange', onVisibility);
    return () => {
      window.removeEventListener('pagehide', save);
      window.removeEventListener('beforeunload', onBeforeUnload);
      document.removeEventListener('visibilitychange', onVisibility);
    };
  }, []);
}

/**
 * The tabbed editor area. It is always left-to-right: code, networks and addresses
 * read LTR in every language; prose pages inside it set their own direction.
 * Source tabs stay mounted while another tab is in front, so each keeps its undo history,
 * cursor and scroll position.
 */
export function EditorArea() {
  const { t } = useTranslation();
  const { tabs, activeId } = useEditorTabs();
  const active = tabs.find((tab) => tab.id === activeId) ?? null;
  const sources = tabs.filter((tab): tab is SourceTab => tab.kind === 'source');
  const dbs = tabs.filter((tab): tab is DbTab => tab.kind === 'db');
  useSaveOnLeave(tabs);

  return (
    <section className="editor-area" dir="ltr" aria-label={t('editor.areaLabel')} data-testid="editor-area">
      {tabs.length > 0 ? <EditorTabStrip /> : null}
      <div className="editor-area__content">
        {active === null ? <EditorEmptyState /> : null}
        {active?.kind === 'start' ? <StartPage /> : null}
        {sources.map((tab) =>
          tab.language === 'symbols' ? (
            <SymbolTableTab key={tab.id} tab={tab} active={tab.id === activeId} />
          ) : tab.language === 'cpu' ? (
            <CpuPropertiesTab key={tab.id} tab={tab} active={tab.id === activeId} />
          ) : (
            <SourceView key={tab.id} tab={tab} active={tab.id === activeId} />
          ),
        )}
        {dbs.map((tab) => (
          <DbEditorView key={tab.id} tab={tab} active={tab.id === activeId} />
        ))}
      </div>
    </section>
  );
}
