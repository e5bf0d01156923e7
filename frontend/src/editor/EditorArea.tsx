import { useTranslation } from 'react-i18next';
import { CodeEditor } from './CodeEditor';
import { EditorEmptyState } from './EditorEmptyState';
import { EditorTabStrip } from './EditorTabStrip';
import { useEditorTabs, type SourceTab } from './EditorTabsContext';
import { StartPage } from './StartPage';

const LANGUAGE_NAMES = { stl: 'STL', scl: 'SCL' } as const;

function SourceView({ tab, active }: { tab: SourceTab; active: boolean }) {
  const { t } = useTranslation();
  const { updateSource } = useEditorTabs();
  return (
    <div className="source-view" hidden={!active} data-testid={`source-view-${tab.id}`}>
      <CodeEditor
        value={tab.text}
        language={tab.language}
        markers={tab.markers}
        onChange={(text) => updateSource(tab.id, text)}
        ariaLabel={t('editor.code.label', { language: LANGUAGE_NAMES[tab.language], name: tab.name })}
        data-testid="code-editor"
      />
    </div>
  );
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

  return (
    <section className="editor-area" dir="ltr" aria-label={t('editor.areaLabel')} data-testid="editor-area">
      {tabs.length > 0 ? <EditorTabStrip /> : null}
      <div className="editor-area__content">
        {active === null ? <EditorEmptyState /> : null}
        {active?.kind === 'start' ? <StartPage /> : null}
        {sources.map((tab) => (
          <SourceView key={tab.id} tab={tab} active={tab.id === activeId} />
        ))}
      </div>
    </section>
  );
}
