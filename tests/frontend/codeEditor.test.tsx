/**
 * The CodeEditor component and the source tabs, with a stand-in for Monaco (the real one is
 * tested in the browser by tests/e2e/editor.spec.ts): what the component asks Monaco to do.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import { CodeEditor, type EditorMarker } from '../../frontend/src/editor/CodeEditor';
import { createI18n } from '../../frontend/src/i18n/setup';
import { healthyServer, renderApp } from './helpers';

const fake = vi.hoisted(() => {
  type Listener = () => void;
  class FakeModel {
    listeners = new Set<Listener>();
    disposed = false;
    constructor(
      public value: string,
      public language: string,
    ) {}
    getValue = () => this.value;
    getFullModelRange = () => ({ startLineNumber: 1, startColumn: 1, endLineNumber: 1, endColumn: 1 });
    pushEditOperations = (_before: unknown, edits: Array<{ text: string }>) => {
      this.value = edits[0]!.text;
      this.listeners.forEach((listener) => listener());
      return null;
    };
    onDidChangeContent = (listener: Listener) => {
      this.listeners.add(listener);
      return { dispose: () => this.listeners.delete(listener) };
    };
    /** What a keystroke does: the text changes and the listeners hear of it. */
    type = (text: string) => {
      this.value += text;
      this.listeners.forEach((listener) => listener());
    };
    dispose = () => {
      this.disposed = true;
    };
  }
  class FakeEditor {
    disposed = false;
    constructor(
      public host: HTMLElement,
      public options: Record<string, unknown>,
    ) {}
    getModel = () => this.options.model as FakeModel;
    updateOptions = (options: Record<string, unknown>) => Object.assign(this.options, options);
    dispose = () => {
      this.disposed = true;
    };
  }
  const state = {
    editors: [] as FakeEditor[],
    models: [] as FakeModel[],
    markers: [] as Array<{ model: FakeModel; owner: string; markers: unknown[] }>,
    fail: false,
    loads: 0,
  };
  const monaco = {
    MarkerSeverity: { Hint: 1, Info: 2, Warning: 4, Error: 8 },
    editor: {
      createModel: (value: string, language: string) => {
        const model = new FakeModel(value, language);
        state.models.push(model);
        return model;
      },
      create: (host: HTMLElement, options: Record<string, unknown>) => {
        const editor = new FakeEditor(host, options);
        state.editors.push(editor);
        return editor;
      },
      setModelLanguage: (model: FakeModel, language: string) => {
        model.language = language;
      },
      setModelMarkers: (model: FakeModel, owner: string, markers: unknown[]) => {
        state.markers.push({ model, owner, markers });
      },
      remeasureFonts: () => undefined,
    },
  };
  const load = () => {
    state.loads += 1;
    return state.fail ? Promise.reject(new Error('offline')) : Promise.resolve(monaco);
  };
  return { state, load };
});

vi.mock('../../frontend/src/editor/monaco/load', () => ({ loadMonaco: () => fake.load() }));

beforeEach(() => {
  fake.state.editors.length = 0;
  fake.state.models.length = 0;
  fake.state.markers.length = 0;
  fake.state.fail = false;
  fake.state.loads = 0;
});

function renderEditor(props: Partial<Parameters<typeof CodeEditor>[0]> = {}) {
  const i18n = createI18n('en');
  const onChange = vi.fn();
  const all = { value: 'A I 0.0', language: 'stl' as const, ariaLabel: 'STL source test.awl', onChange, ...props };
  const view = render(
    <I18nextProvider i18n={i18n}>
      <CodeEditor {...all} data-testid="code-editor" />
    </I18nextProvider>,
  );
  const rerender = (next: Partial<Parameters<typeof CodeEditor>[0]>) =>
    view.rerender(
      <I18nextProvider i18n={i18n}>
        <CodeEditor {...all} {...next} data-testid="code-editor" />
      </I18nextProvider>,
    );
  return { ...view, onChange, rerender };
}

const ready = () => waitFor(() => expect(screen.getByTestId('code-editor').dataset.state).toBe('ready'));

describe('CodeEditor', () => {
  it('creates a left-to-right Monaco editor with the text, language, name and the code font', async () => {
    document.documentElement.dir = 'rtl';
    renderEditor({ readOnly: true });
    expect(screen.getByRole('status').textContent).toBe('Loading the editor…');
    await ready();
    expect(screen.queryByRole('status')).toBeNull();
    const wrapper = screen.getByTestId('code-editor');
    expect(wrapper.getAttribute('dir')).toBe('ltr');
    const [editor] = fake.state.editors;
    expect(wrapper.contains(editor!.host)).toBe(true);
    expect(editor!.getModel().value).toBe('A I 0.0');
    expect(editor!.getModel().language).toBe('stl');
    expect(editor!.options).toMatchObject({
      readOnly: true,
      ariaLabel: 'STL source test.awl',
      automaticLayout: true,
      theme: 'nasaq-light',
      editContext: false,
    });
    expect(String(editor!.options.fontFamily)).toMatch(/^'JetBrains Mono Variable'/);
  });

  it('reports edits, and takes a new text from outside without reporting it back', async () => {
    const { onChange, rerender } = renderEditor();
    await ready();
    const model = fake.state.models[0]!;
    act(() => model.type('\nAN I 0.1'));
    expect(onChange).toHaveBeenLastCalledWith('A I 0.0\nAN I 0.1');
    onChange.mockClear();
    rerender({ value: 'L MW 10' });
    expect(model.value).toBe('L MW 10');
    expect(onChange).not.toHaveBeenCalled();
    rerender({ value: 'L MW 10', language: 'scl', readOnly: true, ariaLabel: 'SCL source' });
    expect(model.language).toBe('scl');
    expect(fake.state.editors[0]!.options).toMatchObject({ readOnly: true, ariaLabel: 'SCL source' });
  });

  it('shows markers with their catalogue code and severity', async () => {
    const markers: EditorMarker[] = [
      { line: 2, column: 7, endLine: 2, endColumn: 12, severity: 'error', code: 'STL204', message: 'Unknown symbol' },
      { line: 3, column: 1, endLine: 3, endColumn: 4, severity: 'warning', code: 'STL301', message: 'Unused' },
      { line: 4, column: 1, endLine: 4, endColumn: 2, severity: 'info', code: 'SIM501', message: 'Note' },
    ];
    const { rerender } = renderEditor({ markers });
    await ready();
    const last = () => fake.state.markers.at(-1)!;
    expect(last().owner).toBe('nasaq');
    expect(last().model).toBe(fake.state.models[0]);
    expect(last().markers).toEqual([
      { startLineNumber: 2, startColumn: 7, endLineNumber: 2, endColumn: 12, severity: 8, code: 'STL204', message: 'Unknown symbol' },
      { startLineNumber: 3, startColumn: 1, endLineNumber: 3, endColumn: 4, severity: 4, code: 'STL301', message: 'Unused' },
      { startLineNumber: 4, startColumn: 1, endLineNumber: 4, endColumn: 2, severity: 2, code: 'SIM501', message: 'Note' },
    ]);
    rerender({ markers: [] });
    expect(last().markers).toEqual([]);
  });

  it('disposes the editor and its model when it goes away', async () => {
    const { unmount } = renderEditor();
    await ready();
    const [editor] = fake.state.editors;
    const [model] = fake.state.models;
    act(() => model!.type(' '));
    unmount();
    expect(editor!.disposed).toBe(true);
    expect(model!.disposed).toBe(true);
    expect(model!.listeners.size).toBe(0);
  });

  it('says when Monaco cannot be loaded, and tries again on request', async () => {
    fake.state.fail = true;
    renderEditor();
    const alert = await screen.findByRole('alert');
    expect(alert.textContent).toContain('The editor could not be loaded from the server.');
    fake.state.fail = false;
    await userEvent.click(within(alert).getByRole('button', { name: 'Try again' }));
    await ready();
    expect(fake.state.loads).toBe(2);
    expect(fake.state.editors).toHaveLength(1);
  });
});

describe("the Start page's new source without a chosen project", () => {
  it('asks which project (here: none yet) and opens no buffer that could not be saved', async () => {
    healthyServer();
    const { user } = renderApp('en');
    await user.click(screen.getByRole('button', { name: 'New STL source' }));
    const dialog = await screen.findByTestId('project-pick-dialog');
    await waitFor(() => expect(dialog.textContent).toContain('You have no project yet: create one first.'));
    expect(within(dialog).getByTestId('project-pick-new').textContent).toBe('New project…');
    expect(screen.queryByTestId('editor-tab-source-1')).toBeNull();
    expect(fake.state.editors).toHaveLength(0);
  });

  it('asks in Persian too', async () => {
    healthyServer();
    const { user } = renderApp('fa');
    await user.click(screen.getByRole('button', { name: 'منبع STL جدید' }));
    const dialog = await screen.findByTestId('project-pick-dialog');
    expect(within(dialog).getByTestId('project-pick-new').textContent).not.toMatch(/[A-Za-z]/);
    expect(fake.state.editors).toHaveLength(0);
  });
});
