import { useTranslation } from 'react-i18next';
import { EditorEmptyState } from './EditorEmptyState';
import { EditorTabStrip } from './EditorTabStrip';
import { useEditorTabs, type EditorTab } from './EditorTabsContext';
import { StartPage } from './StartPage';

function EditorView({ tab }: { tab: EditorTab }) {
  switch (tab.kind) {
    case 'start':
      return <StartPage />;
  }
}

/**
 * The tabbed editor area. It is always left-to-right: code, networks and addresses
 * read LTR in every language; prose pages inside it set their own direction.
 */
export function EditorArea() {
  const { t } = useTranslation();
  const { tabs, activeId } = useEditorTabs();
  const active = tabs.find((tab) => tab.id === activeId) ?? null;

  return (
    <section className="editor-area" dir="ltr" aria-label={t('editor.areaLabel')} data-testid="editor-area">
      {tabs.length > 0 ? <EditorTabStrip /> : null}
      <div className="editor-area__content">{active ? <EditorView tab={active} /> : <EditorEmptyState />}</div>
    </section>
  );
}
