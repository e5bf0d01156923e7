import { useTranslation } from 'react-i18next';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { NasaqMark } from '../ui/icons';
import { useEditorTabs } from './EditorTabsContext';

/** Shown when every editor tab is closed. */
export function EditorEmptyState() {
  const { t } = useTranslation();
  const { dir } = useUiLanguage();
  const { openStart } = useEditorTabs();
  return (
    <div className="editor-empty" dir={dir} data-testid="editor-empty">
      <NasaqMark size={40} className="editor-empty__mark" />
      <h1 className="editor-empty__title">{t('editor.empty.title')}</h1>
      <p className="editor-empty__text">{t('editor.empty.text')}</p>
      <button type="button" className="button button--primary" data-testid="open-start-page" onClick={openStart}>
        {t('editor.openStart')}
      </button>
    </div>
  );
}
