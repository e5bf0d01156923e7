/** The code editor tells the completion and hover providers which project file its model is. */
import { render, waitFor } from '@testing-library/react';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it, vi } from 'vitest';
import { CodeEditor } from '../../frontend/src/editor/CodeEditor';
import { sourceOf } from '../../frontend/src/editor/intellisense/modelRegistry';
import { createI18n } from '../../frontend/src/i18n/setup';
import { fake } from './fakeMonaco';

vi.mock('../../frontend/src/editor/monaco/load', () => import('./fakeMonaco'));

describe('CodeEditor and the model registry', () => {
  it('binds its model to the file it shows, follows a rename and unbinds it at the end', async () => {
    fake.reset();
    const i18n = createI18n('en');
    const view = (path: string) => (
      <I18nextProvider i18n={i18n}>
        <CodeEditor value="BEGIN" language="scl" ariaLabel="SCL" source={{ projectId: 4, path }} />
      </I18nextProvider>
    );
    const { rerender, unmount } = render(view('Motor.scl'));
    await waitFor(() => expect(fake.models).toHaveLength(1));
    const model = fake.models[0]!;
    expect(sourceOf(model)).toEqual({ projectId: 4, path: 'Motor.scl' });
    rerender(view('Pump.scl'));
    expect(sourceOf(model)).toEqual({ projectId: 4, path: 'Pump.scl' });
    unmount();
    expect(sourceOf(model)).toBeNull();
  });

  it('leaves a text without a project unbound', async () => {
    fake.reset();
    render(
      <I18nextProvider i18n={createI18n('en')}>
        <CodeEditor value="BEGIN" language="stl" ariaLabel="STL" />
      </I18nextProvider>,
    );
    await waitFor(() => expect(fake.models).toHaveLength(1));
    expect(sourceOf(fake.models[0]!)).toBeNull();
  });
});
