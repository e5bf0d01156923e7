import { useState } from 'react';
import type { i18n as I18n } from 'i18next';
import { I18nextProvider } from 'react-i18next';
import { EditorTabsProvider } from '../editor/EditorTabsContext';
import { ServerHealthProvider } from '../health/ServerHealth';
import { createI18n } from '../i18n/setup';
import { Workbench } from './Workbench';

/** The whole application: shared services around the workbench layout. */
export function App({ i18n }: { i18n?: I18n }) {
  const [instance] = useState(() => i18n ?? createI18n());
  return (
    <I18nextProvider i18n={instance}>
      <ServerHealthProvider>
        <EditorTabsProvider>
          <Workbench />
        </EditorTabsProvider>
      </ServerHealthProvider>
    </I18nextProvider>
  );
}
