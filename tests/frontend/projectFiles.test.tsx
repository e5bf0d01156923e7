/**
 * Project files in the workbench with a fake server and a stand-in for Monaco: the tree's blocks
 * and files, opening them in tabs, autosave with the version check, diagnostics while typing,
 * go to definition and the tree's actions.
 */
import { act, renderHook, screen, waitFor, within } from '@testing-library/react';
import type { ReactNode } from 'react';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { Diagnostic } from '../../frontend/src/api/types';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { useOpenDiagnostic, useProjectDiagnostics } from '../../frontend/src/editor/projectDiagnostics';
import { createI18n } from '../../frontend/src/i18n/setup';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { fake } from './fakeMonaco';
import { makeProject, renderApp } from './helpers';
import { block, projectServer, type FakeProject } from './projectServer';

vi.mock('../../frontend/src/editor/monaco/load', () => import('./fakeMonaco'));

const OB1 = `ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     I 0.0;
      CALL  FC 10;
END_ORGANIZATION_BLOCK
`;

const FC10 = `FUNCTION FC 10 : VOID
BEGIN
NETWORK
      NOP   0;
END_FUNCTION
`;

/** STL201 for every line with an XYZ, as the compiler would say it. */
function unknownXyz(name: string | null, text: string | null): Diagnostic[] {
  if (!name || !text) return [];
  return text
    .split('\n')
    .map((line, index) => [line, index] as const)
    .filter(([line]) => line.includes('XYZ'))
    .map(([line, index]) => ({
      code: 'STL201',
      severity: 'error' as const,
      key: 'stl_unknown_instruction',
      message: 'Unknown instruction XYZ.',
      params: { mnemonic: 'XYZ', hint: '' },
      span: { file: name, line: index + 1, column: line.indexOf('XYZ') + 1, end_line: null, end_column: null },
    }));
}

function motorProject(): FakeProject {
  return {
    project: makeProject(1, 'Motor'),
    files: new Map([
      ['FC10.awl', { text: FC10, version: 1 }],
      ['OB1.awl', { text: OB1, version: 3 }],
      ['symbols.sdf', { text: '"Main","OB 1","OB 1",""\n', version: 1 }],
    ]),
    blocks: [block('OB', 1, 'Main', 'OB1.awl', 1), block('FC', 10, 'Scale', 'FC10.awl', 1)],
    diagnostics: unknownXyz,
  };
}

const tree = () => screen.getByTestId('block-tree');

beforeEach(() => {
  projectContents.clear();
  fake.reset();
});

/** Renders the app, expands the project and waits for its files. */
async function openProject(language?: 'en' | 'fa') {
  const server = projectServer([motorProject()]);
  const view = renderApp(language);
  const node = await within(tree()).findByRole('treeitem', { name: 'Motor' });
  await view.user.click(node.firstElementChild as HTMLElement);
  await within(tree()).findByTestId('file-node-1-OB1.awl');
  return { server, ...view };
}

/** Double-clicks a file in the tree and waits for its editor. */
async function openFile(user: ReturnType<typeof renderApp>['user'], name: string) {
  const before = fake.editors.length;
  await user.dblClick(within(screen.getByTestId(`file-node-1-${name}`)).getByText(name));
  await waitFor(() => expect(fake.editors.length).toBe(before + 1));
  const editor = fake.editors.at(-1)!;
  // Ready: the editor has its go-to-definition action.
  await waitFor(() => expect(editor.actions.has('nasaq.goToDefinition')).toBe(true));
  return { editor, model: editor.getModel() };
}

const tabOf = (name: string) =>
  screen.getAllByTestId(/^editor-tab-source-/).find((tab) => tab.textContent?.includes(name))!;

describe('the project tree with files', () => {
  it('opens a file with a double-click, its text read from the server, saved', async () => {
    const { user, server } = await openProject();
    const { model } = await openFile(user, 'OB1.awl');
    expect(model.value).toBe(OB1);
    expect(model.language).toBe('stl');
    expect(tabOf('OB1.awl').getAttribute('aria-current')).toBe('true');
    expect(tabOf('OB1.awl').dataset.saveState).toBe('saved');
    expect(server.requests()).toContain('GET /api/projects/1/files/OB1.awl');
    // A second double-click brings the same tab to the front.
    await user.dblClick(within(screen.getByTestId('file-node-1-OB1.awl')).getByText('OB1.awl'));
    expect(screen.getAllByTestId(/^editor-tab-source-/)).toHaveLength(1);
    // The symbol table opens as plain text.
    const symbols = await openFile(user, 'symbols.sdf');
    expect(symbols.model.language).toBe('plaintext');
    expect(symbols.editor.options.ariaLabel).toBe('Symbol table symbols.sdf');
  });

  it('opens a block with Enter, at its header line', async () => {
    const { user } = await openProject();
    const fc = await within(tree()).findByRole('treeitem', { name: 'FC10 Scale' });
    fc.focus();
    await user.keyboard('{Enter}');
    await waitFor(() => expect(fake.editors).toHaveLength(1));
    expect(tabOf('FC10.awl')).toBeTruthy();
    await waitFor(() => expect(fake.editors[0]!.revealed).toEqual([1]));
    expect(fc.getAttribute('aria-selected')).toBe('true');
  });

  it('shows the server error when a file cannot be opened', async () => {
    const { user, server } = await openProject();
    server.projects[0]!.files.delete('OB1.awl');
    await user.dblClick(within(screen.getByTestId('file-node-1-OB1.awl')).getByText('OB1.awl'));
    const notice = await screen.findByTestId('project-tree-notice');
    expect(notice.getAttribute('role')).toBe('alert');
    expect(notice.textContent).toContain('API107');
  });
});

describe('autosave', () => {
  it('saves about a second after the last change, with the version it was loaded at', async () => {
    const { user, server } = await openProject();
    const { model } = await openFile(user, 'OB1.awl');
    act(() => model.type('      NOP   0;\n'));
    expect(tabOf('OB1.awl').dataset.saveState).toBe('dirty');
    expect(screen.getByTestId(/^save-state-/).textContent).toBe('Unsaved changes');
    act(() => model.type('      NOP   1;\n'));
    await waitFor(() => expect(server.saves).toHaveLength(1), { timeout: 3000 });
    expect(server.saves[0]).toEqual({ name: 'OB1.awl', text: `${OB1}      NOP   0;\n      NOP   1;\n`, base_version: 3 });
    await waitFor(() => expect(tabOf('OB1.awl').dataset.saveState).toBe('saved'));
    expect(screen.getByTestId(/^save-state-/).textContent).toBe('Saved');
    expect(server.projects[0]!.files.get('OB1.awl')!.version).toBe(4);

    // The next save sends the version the last one made.
    act(() => model.type('// more\n'));
    await waitFor(() => expect(server.saves).toHaveLength(2), { timeout: 3000 });
    expect(server.saves[1]!.base_version).toBe(4);
  });

  it('saves at once when the editor loses the focus, and when the tab closes', async () => {
    const { user, server } = await openProject();
    const { editor, model } = await openFile(user, 'OB1.awl');
    act(() => model.type('// one\n'));
    act(() => editor.blur());
    await waitFor(() => expect(server.saves).toHaveLength(1));
    await waitFor(() => expect(tabOf('OB1.awl').dataset.saveState).toBe('saved'));

    act(() => model.type('// two\n'));
    const tabId = tabOf('OB1.awl').dataset.testid!.replace('editor-tab-', '');
    await user.click(screen.getByTestId(`editor-tab-close-${tabId}`));
    await waitFor(() => expect(server.saves).toHaveLength(2));
    expect(server.saves[1]!.text).toContain('// two');
  });

  it('says when the file changed elsewhere (409) and lets the user reload theirs', async () => {
    const { user, server } = await openProject();
    const { editor, model } = await openFile(user, 'OB1.awl');
    server.projects[0]!.files.set('OB1.awl', { text: `${OB1}// theirs\n`, version: 7 });
    act(() => model.type('// mine\n'));
    act(() => editor.blur());
    const conflict = await screen.findByTestId('save-conflict');
    expect(conflict.getAttribute('role')).toBe('alert');
    expect(conflict.textContent).toContain('API111');
    expect(conflict.textContent).toContain('“OB1.awl” was changed elsewhere after this copy was loaded.');
    expect(tabOf('OB1.awl').dataset.saveState).toBe('conflict');
    // No more saves while the user has not chosen.
    act(() => model.type('// still mine\n'));
    await new Promise((resolve) => setTimeout(resolve, 1300));
    expect(server.saves).toHaveLength(1);

    await user.click(within(conflict).getByRole('button', { name: 'Reload the saved version' }));
    await waitFor(() => expect(screen.queryByTestId('save-conflict')).toBeNull());
    expect(model.value).toBe(`${OB1}// theirs\n`);
    expect(tabOf('OB1.awl').dataset.saveState).toBe('saved');
    // Typing again saves on top of their version.
    act(() => model.type('// next\n'));
    await waitFor(() => expect(server.saves).toHaveLength(2), { timeout: 3000 });
    expect(server.saves[1]!.base_version).toBe(7);
  });

  it('overwrites the newer version on request, in Persian', async () => {
    const { user, server } = await openProject('fa');
    const { editor, model } = await openFile(user, 'OB1.awl');
    server.projects[0]!.files.set('OB1.awl', { text: 'theirs', version: 9 });
    act(() => model.type('// mine\n'));
    act(() => editor.blur());
    const conflict = await screen.findByTestId('save-conflict');
    expect(conflict.textContent).toContain('API111');
    expect(conflict.textContent).toContain('«OB1.awl» پس از بارگذاری این نسخه در جای دیگری تغییر کرده است.');
    expect(tabOf('OB1.awl').querySelector('.visually-hidden')?.textContent).toBe('در جای دیگری تغییر کرده است: ذخیره نشد');
    await user.click(within(conflict).getByRole('button', { name: 'جایگزینی با متن من' }));
    await waitFor(() => expect(server.saves).toHaveLength(2));
    expect(server.saves[1]).toMatchObject({ base_version: 9, text: `${OB1}// mine\n` });
    await waitFor(() => expect(screen.queryByTestId('save-conflict')).toBeNull());
    expect(server.projects[0]!.files.get('OB1.awl')!.text).toBe(`${OB1}// mine\n`);
  });

  it('keeps the text and tries again when the server cannot be reached', async () => {
    const { user, server } = await openProject();
    const { editor, model } = await openFile(user, 'OB1.awl');
    server.putAnswers.push(() => {
      throw new TypeError('Failed to fetch');
    });
    act(() => model.type('// offline\n'));
    act(() => editor.blur());
    const failed = await screen.findByTestId('save-failed');
    expect(failed.textContent).toContain('NET000');
    expect(tabOf('OB1.awl').dataset.saveState).toBe('failed');
    await user.click(within(failed).getByRole('button', { name: 'Save again' }));
    await waitFor(() => expect(tabOf('OB1.awl').dataset.saveState).toBe('saved'));
    expect(server.projects[0]!.files.get('OB1.awl')!.text).toContain('// offline');
  });
});

describe('diagnostics while typing', () => {
  it('checks the unsaved text and shows markers with the code and the translated message', async () => {
    const { user, server } = await openProject('fa');
    const { model } = await openFile(user, 'OB1.awl');
    await waitFor(() => expect(server.checks).toHaveLength(1));
    act(() => model.type('      XYZ   M 1.0;\n'));
    await waitFor(() => expect(fake.markersOf(model)).toHaveLength(1));
    expect(server.checks.at(-1)).toEqual({ name: 'OB1.awl', text: `${OB1}      XYZ   M 1.0;\n` });
    expect(fake.markersOf(model)[0]).toEqual({
      startLineNumber: 7,
      startColumn: 7,
      endLineNumber: 7,
      endColumn: 10,
      severity: 8,
      code: 'STL201',
      message: 'دستور XYZ ناشناخته است.',
    });
    // Fixed: the marker goes.
    act(() => model.replace(`${OB1}      NOP   0;\n`));
    await waitFor(() => expect(fake.markersOf(model)).toEqual([]));
  });

  it('waits for a pause in the typing before checking', async () => {
    const { user, server } = await openProject();
    const { model } = await openFile(user, 'OB1.awl');
    await waitFor(() => expect(server.checks).toHaveLength(1));
    act(() => model.type('A'));
    act(() => model.type('B'));
    act(() => model.type('C'));
    expect(server.checks).toHaveLength(1);
    await waitFor(() => expect(server.checks).toHaveLength(2));
    expect(server.checks[1]!.text.endsWith('ABC')).toBe(true);
  });
});

describe('go to definition', () => {
  it('F12 on a block number opens the file that defines it', async () => {
    const { user } = await openProject();
    const { editor } = await openFile(user, 'OB1.awl');
    act(() => editor.goToDefinition(5, 15));
    await waitFor(() => expect(tabOf('FC10.awl')?.getAttribute('aria-current')).toBe('true'));
    await waitFor(() => expect(fake.editors).toHaveLength(2));
    await waitFor(() => expect(fake.editors[1]!.revealed).toEqual([1]));
  });

  it('says so when nothing is defined there', async () => {
    const { user } = await openProject();
    const { editor } = await openFile(user, 'OB1.awl');
    act(() => editor.goToDefinition(4, 13));
    expect(await screen.findByText('No block of this project is named here.')).toBeTruthy();
  });
});

describe('tree actions', () => {
  it('creates a new STL source from the menu (Shift+F10) and opens it', async () => {
    const { user, server } = await openProject();
    const sources = within(tree()).getByRole('treeitem', { name: 'Sources' });
    sources.focus();
    await user.keyboard('{Shift>}{F10}{/Shift}');
    const menu = await screen.findByRole('menu', { name: 'Actions' });
    await waitFor(() => expect(document.activeElement).toBe(within(menu).getAllByRole('menuitem')[0]));
    await user.keyboard('{Enter}');
    const dialog = await screen.findByRole('dialog', { name: 'New STL source' });
    const input = within(dialog).getByLabelText('File name') as HTMLInputElement;
    expect(input.value).toBe('Source1.awl');
    await user.clear(input);
    await user.type(input, 'Pumps.awl');
    await user.click(within(dialog).getByRole('button', { name: 'Create' }));
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.saves[0]).toMatchObject({ name: 'Pumps.awl', base_version: null });
    expect(server.saves[0]!.text).toMatch(/^FUNCTION FC 1 : VOID/);
    expect(await within(tree()).findByTestId('file-node-1-Pumps.awl')).toBeTruthy();
    await waitFor(() => expect(tabOf('Pumps.awl')?.getAttribute('aria-current')).toBe('true'));
  });

  it('refuses a name the project has, before asking the server', async () => {
    const { user, server } = await openProject();
    within(tree()).getByRole('treeitem', { name: 'Sources' }).focus();
    await user.keyboard('{ContextMenu}');
    await user.click(await screen.findByRole('menuitem', { name: 'New SCL source…' }));
    const input = within(await screen.findByRole('dialog')).getByLabelText('File name');
    await user.clear(input);
    await user.type(input, 'ob1.AWL{Enter}');
    const error = await screen.findByTestId('file-name-error');
    expect(error.textContent).toContain('API108');
    expect(server.saves).toEqual([]);
  });

  it('renames with F2: the server, the tree and the open tab follow; the next save has the new version', async () => {
    const { user, server } = await openProject();
    const { model } = await openFile(user, 'OB1.awl');
    const row = screen.getByTestId('file-node-1-OB1.awl');
    row.focus();
    await user.keyboard('{F2}');
    const dialog = await screen.findByRole('dialog', { name: 'Rename OB1.awl' });
    const input = within(dialog).getByLabelText('File name');
    await user.clear(input);
    await user.type(input, 'Main.awl{Enter}');
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.requests()).toContain('PATCH /api/projects/1/files/OB1.awl');
    expect(await within(tree()).findByTestId('file-node-1-Main.awl')).toBeTruthy();
    expect(within(tree()).queryByTestId('file-node-1-OB1.awl')).toBeNull();
    expect(tabOf('Main.awl')).toBeTruthy();
    act(() => model.type('// after the rename\n'));
    await waitFor(() => expect(server.saves).toHaveLength(1), { timeout: 3000 });
    expect(server.saves[0]).toMatchObject({ name: 'Main.awl', base_version: 4 });
  });

  it('deletes a file after a confirmation, and closes its tab without saving it again', async () => {
    const { user, server } = await openProject();
    await openFile(user, 'FC10.awl');
    screen.getByTestId('file-node-1-FC10.awl').focus();
    await user.keyboard('{Delete}');
    const dialog = await screen.findByRole('dialog', { name: 'Delete FC10.awl?' });
    // Cancel has the focus: Enter does not delete by accident.
    expect(document.activeElement).toBe(within(dialog).getByRole('button', { name: 'Cancel' }));
    await user.click(within(dialog).getByRole('button', { name: 'Delete' }));
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.requests()).toContain('DELETE /api/projects/1/files/FC10.awl');
    await waitFor(() => expect(within(tree()).queryByTestId('file-node-1-FC10.awl')).toBeNull());
    expect(within(tree()).queryByRole('treeitem', { name: 'FC10 Scale' })).toBeNull();
    expect(screen.queryAllByTestId(/^editor-tab-source-/)).toHaveLength(0);
    expect(server.saves).toEqual([]);
    expect(server.projects[0]!.files.has('FC10.awl')).toBe(false);
  });

  it('duplicates a file under a free name from the row menu', async () => {
    const { user, server } = await openProject();
    const row = screen.getByTestId('file-node-1-OB1.awl');
    await user.click(row.querySelector('.tree-row__menu') as HTMLElement);
    await user.click(await screen.findByRole('menuitem', { name: 'Duplicate…' }));
    const dialog = await screen.findByRole('dialog', { name: 'Duplicate OB1.awl' });
    expect((within(dialog).getByLabelText('File name') as HTMLInputElement).value).toBe('OB1_copy.awl');
    await user.click(within(dialog).getByRole('button', { name: 'Duplicate' }));
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.requests()).toContain('POST /api/projects/1/files/OB1.awl/duplicate');
    expect(await within(tree()).findByTestId('file-node-1-OB1_copy.awl')).toBeTruthy();
  });

  it('deletes a project after a confirmation, with its tabs', async () => {
    const { user, server } = await openProject();
    await openFile(user, 'OB1.awl');
    const node = within(tree()).getByRole('treeitem', { name: 'Motor' });
    node.focus();
    await user.keyboard('{Shift>}{F10}{/Shift}');
    await user.click(await screen.findByRole('menuitem', { name: 'Delete project…' }));
    const dialog = await screen.findByRole('dialog', { name: 'Delete project Motor?' });
    await user.click(within(dialog).getByRole('button', { name: 'Delete project' }));
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.requests()).toContain('DELETE /api/projects/1');
    expect(within(tree()).queryByRole('treeitem', { name: 'Motor' })).toBeNull();
    expect(screen.queryAllByTestId(/^editor-tab-source-/)).toHaveLength(0);
  });

  it('imports a zip as a new project: the raw zip is the body', async () => {
    const { user, server } = await openProject();
    await user.click(screen.getByTestId('project-import'));
    const dialog = await screen.findByRole('dialog', { name: 'Import project' });
    const zip = new File([new Uint8Array([0x50, 0x4b, 3, 4])], 'plant.zip', { type: 'application/zip' });
    await user.upload(within(dialog).getByLabelText('Zip file'), zip);
    await user.type(within(dialog).getByLabelText(/Project name/), 'Plant');
    await user.click(within(dialog).getByRole('button', { name: 'Import' }));
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    const post = server.fetch.mock.calls.find(([url]) => String(url).startsWith('/api/projects/import'))!;
    expect(post[0]).toBe('/api/projects/import?name=Plant');
    expect(post[1]?.body).toBe(zip);
    expect(new Headers(post[1]?.headers).get('Content-Type')).toBe('application/zip');
    const node = await within(tree()).findByRole('treeitem', { name: 'Plant' });
    expect(node.getAttribute('aria-selected')).toBe('true');
  });
});

describe('the active project’s diagnostics, for the Diagnostics panel', () => {
  it('lists the diagnostics of the project chosen and opens a diagnostic’s file at its line', async () => {
    const server = projectServer([motorProject()]);
    server.projects[0]!.diagnostics = () => [
      {
        code: 'STL213',
        severity: 'error',
        key: 'stl_missing_block',
        message: 'FC 5 does not exist in the program.',
        params: { block: 'FC 5' },
        span: { file: 'OB1.awl', line: 5, column: 7 },
      },
    ];
    const i18n = createI18n('en');
    const wrapper = ({ children }: { children: ReactNode }) => (
      <I18nextProvider i18n={i18n}>
        <EditorTabsProvider>
          <ActiveProjectProvider>{children}</ActiveProjectProvider>
        </EditorTabsProvider>
      </I18nextProvider>
    );
    const { result } = renderHook(
      () => ({ diagnostics: useProjectDiagnostics(), open: useOpenDiagnostic(), active: useActiveProject() }),
      { wrapper },
    );
    expect(result.current.diagnostics).toEqual([]);
    act(() => result.current.active.setProjectId(1));
    await waitFor(() => expect(result.current.diagnostics.map((d) => d.code)).toEqual(['STL213']));
    let opened = false;
    act(() => {
      opened = result.current.open(result.current.diagnostics[0]!);
    });
    expect(opened).toBe(true);
    await waitFor(() => expect(server.requests()).toContain('GET /api/projects/1/files/OB1.awl'));
  });
});
