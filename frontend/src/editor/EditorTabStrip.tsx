import { useState } from 'react';
import { useTranslation } from 'react-i18next';
import { ConfirmDialog } from '../projects/TreeDialogs';
import { CloseIcon, DocumentIcon, WarningIcon } from '../ui/icons';
import { useEditorTabs, type EditorTab } from './EditorTabsContext';
import { closingLosesText } from './unsaved';

export function useTabTitle(): (tab: EditorTab) => string {
  const { t } = useTranslation();
  return (tab) => (tab.kind === 'source' || tab.kind === 'db' ? tab.name : t(`editor.tabs.${tab.kind}`));
}

/** The row of open editors; each has its own close button, which asks first when closing would
 * lose text the autosave could not save. */
export function EditorTabStrip() {
  const { t } = useTranslation();
  const { tabs, activeId, activate, close } = useEditorTabs();
  const titleOf = useTabTitle();
  const [asking, setAsking] = useState<EditorTab | null>(null);
  const requestClose = (tab: EditorTab) => (closingLosesText(tab) ? setAsking(tab) : close(tab.id));

  return (
    <div className="editor-tabs">
      <ul className="editor-tabs__list" aria-label={t('editor.openEditors')}>
        {tabs.map((tab) => {
          const active = tab.id === activeId;
          const title = titleOf(tab);
          return (
            <li key={tab.id} className={active ? 'editor-tab editor-tab--active' : 'editor-tab'}>
              <button
                type="button"
                className="editor-tab__button"
                aria-current={active ? 'true' : undefined}
                data-testid={`editor-tab-${tab.id}`}
                data-save-state={tab.kind === 'source' && tab.file ? tab.save.status : undefined}
                onClick={() => activate(tab.id)}
              >
                <DocumentIcon className="editor-tab__icon" />
                <bdi>{title}</bdi>
                {tab.kind === 'source' && (tab.save.status === 'conflict' || tab.save.status === 'failed') ? (
                  <span
                    className={`editor-tab__state editor-tab__state--${tab.save.status}`}
                    title={t(`editor.save.${tab.save.status}`)}
                  >
                    <WarningIcon size={12} />
                    <span className="visually-hidden">{t(`editor.save.${tab.save.status}`)}</span>
                  </span>
                ) : tab.kind === 'source' && tab.dirty ? (
                  <span className="editor-tab__dirty" title={t('editor.unsaved')}>
                    <span aria-hidden="true">●</span>
                    <span className="visually-hidden">{t('editor.unsaved')}</span>
                  </span>
                ) : null}
              </button>
              <button
                type="button"
                className="editor-tab__close"
                aria-label={t('editor.closeTab', { title })}
                title={t('editor.closeTab', { title })}
                data-testid={`editor-tab-close-${tab.id}`}
                onClick={() => requestClose(tab)}
              >
                <CloseIcon size={12} />
              </button>
            </li>
          );
        })}
      </ul>
      {asking ? (
        <ConfirmDialog
          title={t('editor.closeUnsaved.title', { name: titleOf(asking) })}
          confirmLabel={t('editor.closeUnsaved.confirm')}
          testId="close-unsaved-dialog"
          onClose={() => setAsking(null)}
          onConfirm={async () => {
            close(asking.id);
            setAsking(null);
          }}
        >
          <p className="dialog__text">{t('editor.closeUnsaved.text', { name: titleOf(asking) })}</p>
        </ConfirmDialog>
      ) : null}
    </div>
  );
}
