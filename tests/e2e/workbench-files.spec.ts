/**
 * Project files in the workbench, against the real server and its example projects: open a file
 * from the tree, diagnostics while typing (markers with code and message, in the UI language),
 * autosave to the database, go to definition, the tree's actions, export and import.
 */
import type { Locator, Page } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { test, expect, chooseLanguage, visibleEditor, tree, expandProject, openFile } from './fixtures';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

interface ShownMarker {
  code: string;
  message: string;
  line: number;
}


/** The markers Monaco shows in the model of the editor in front. */
function markersOf(page: Page): Promise<ShownMarker[]> {
  return page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const model = editor?.getModel();
    if (!model) return [];
    return monaco.editor.getModelMarkers({ resource: model.uri, owner: 'nasaq' }).map((m) => ({
      code: typeof m.code === 'string' ? m.code : (m.code?.value ?? ''),
      message: m.message,
      line: m.startLineNumber,
    }));
  });
}

function caretOf(page: Page): Promise<{ line: number; column: number } | null> {
  return page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const position = editor?.getPosition();
    return position ? { line: position.lineNumber, column: position.column } : null;
  });
}

function textOf(page: Page): Promise<string> {
  return page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    return editor?.getModel()?.getValue() ?? '';
  });
}

/** Scrolls the editor in front to the first line that contains `text` (Monaco draws only the lines in view). */
async function reveal(page: Page, text: string): Promise<void> {
  await page.evaluate((wanted) => {
    const monaco = (window as WithMonaco).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const index = editor?.getModel()?.getLinesContent().findIndex((line) => line.includes(wanted)) ?? -1;
    if (index >= 0) editor?.revealLineInCenter(index + 1);
  }, text);
}

/** Puts the caret at the end of the (first) line that contains `text`, as a click there would. */
async function caretAfter(page: Page, editor: Locator, text: string): Promise<void> {
  await reveal(page, text);
  await editor.locator('.view-line', { hasText: text }).first().click();
  await page.keyboard.press('End');
}

/**
 * Types a new line after the line holding `after`: Escape closes word suggestions, so Enter
 * starts the line.
 */
async function typeLineAfter(page: Page, editor: Locator, after: string, line: string): Promise<void> {
  await caretAfter(page, editor, after);
  await page.keyboard.press('Escape');
  await page.keyboard.press('Enter');
  // Monaco keeps the indentation of the line above.
  await page.keyboard.type(line, { delay: 15 });
  await page.keyboard.press('Escape');
}

/** Replaces the line that holds `find` (from its first non-blank character) with `line`. */
async function replaceLine(page: Page, editor: Locator, find: string, line: string): Promise<void> {
  await caretAfter(page, editor, find);
  await page.keyboard.press('Shift+Home');
  await page.keyboard.type(line, { delay: 15 });
  await page.keyboard.press('Escape');
}

test('a syntax error shows its marker while typing, the fix is autosaved and still there after a reload', async ({
  page,
  request,
  watch,
}) => {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const projectId = await expandProject(page, 'motor-start-stop');
  // The blocks by kind and the files, from /blocks and /files.
  await expect(tree(page).getByTestId(`block-node-${projectId}-OB1`)).toContainText('Main');
  await expect(tree(page).getByTestId(`file-node-${projectId}-symbols.sdf`)).toBeVisible();

  const editor = await openFile(page, projectId, 'OB1.awl');
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'OB1.awl' });
  await expect(tab).toHaveAttribute('data-save-state', 'saved');
  expect(await markersOf(page)).toEqual([]);

  await typeLineAfter(page, editor, '"Fault lamp";', 'XYZ   "Motor";');
  // The check of the unsaved text answers within a moment: a marker with code and message.
  await expect.poll(() => markersOf(page)).toEqual([{ code: 'STL201', message: 'Unknown instruction XYZ.', line: 26 }]);
  await expect(editor.locator('.squiggly-error')).toHaveCount(1);
  await reveal(page, 'XYZ');
  await editor.locator('.view-line span > span', { hasText: 'XYZ' }).last().hover();
  const hover = page.locator('.monaco-hover').filter({ hasText: 'Unknown instruction XYZ.' });
  await expect(hover).toBeVisible();
  await expect(hover).toContainText('STL201');

  // The Diagnostics panel lists it with its place; a click there brings the caret back to it.
  const row = page.getByTestId('diagnostics').getByTestId('diagnostic').filter({ hasText: 'STL201' });
  await expect(row).toContainText('Unknown instruction XYZ.');
  await expect(row).toContainText('OB1.awl:26:7');
  await page.keyboard.press('Escape');
  await page.keyboard.press('Control+Home');
  await row.getByTestId('diagnostic-open').click();
  await expect.poll(() => caretOf(page)).toEqual({ line: 26, column: 7 });

  await replaceLine(page, editor, 'XYZ', 'NOP   0;                         // added in the browser test');
  await expect.poll(() => markersOf(page)).toEqual([]);
  await expect(editor.locator('.squiggly-error')).toHaveCount(0);

  // The autosave: about a second after the last key, the server has the text.
  await expect(tab).toHaveAttribute('data-save-state', 'saved', { timeout: 10_000 });
  await expect(page.locator('[data-testid^="save-state-"]:visible')).toHaveAttribute('data-state', 'saved');
  await expect
    .poll(async () => (await (await request.get(`/api/projects/${projectId}/files/OB1.awl`)).json()).text as string)
    .toContain('// added in the browser test');

  await page.reload();
  const again = await expandProject(page, 'motor-start-stop');
  await openFile(page, again, 'OB1.awl');
  expect(await textOf(page)).toContain('NOP   0;                         // added in the browser test');
  expect(await markersOf(page)).toEqual([]);
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('in Persian the marker keeps its code and shows the Persian message', async ({ page, watch }) => {
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  const projectId = await expandProject(page, 'traffic-light');
  const editor = await openFile(page, projectId, 'OB1.awl');
  // The editor stays left to right in a right-to-left page.
  await expect(editor).toHaveAttribute('dir', 'ltr');

  await typeLineAfter(page, editor, 'SD    "Yellow time";', 'XYZ   "Run";');
  await expect.poll(async () => (await markersOf(page)).map((m) => [m.code, m.message])).toEqual([
    ['STL201', 'دستور XYZ ناشناخته است.'],
  ]);
  await reveal(page, 'XYZ');
  await editor.locator('.view-line span > span', { hasText: 'XYZ' }).last().hover();
  const hover = page.locator('.monaco-hover').filter({ hasText: 'ناشناخته' });
  await expect(hover).toBeVisible();
  await expect(hover).toContainText('STL201');

  await replaceLine(page, editor, 'XYZ', 'NOP   0;');
  await expect.poll(() => markersOf(page)).toEqual([]);
  // The status line speaks Persian too.
  await expect(page.locator('[data-testid^="save-state-"]:visible')).toHaveText('ذخیره شد', { timeout: 10_000 });
  expect(watch.consoleErrors).toEqual([]);
});

test('go to definition opens the block a CALL names, at its header', async ({ page, watch }) => {
  await page.goto('/');
  const projectId = await expandProject(page, 'tank-level');
  const editor = await openFile(page, projectId, 'OB1.awl');

  // Ctrl+click on the FC's symbol.
  await reveal(page, 'CALL "Scale"');
  await editor
    .locator('.view-line', { hasText: 'CALL "Scale"' })
    .locator('span > span', { hasText: '"Scale"' })
    .first()
    .click({ modifiers: ['Control'] });
  const scale = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Scale.scl' });
  await expect(scale).toHaveAttribute('aria-current', 'true');
  await expect(visibleEditor(page)).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  const caret = () =>
    page.evaluate(() => {
      const monaco = (window as WithMonaco).monaco;
      const shown = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
      const position = shown?.getPosition();
      return { line: position?.lineNumber, text: shown?.getModel()?.getLineContent(position?.lineNumber ?? 1) };
    });
  await expect.poll(caret).toMatchObject({ text: expect.stringMatching(/^FUNCTION "Scale"/) });

  // F12 on the instance's FB, back in OB1.
  await page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'OB1.awl' }).click();
  await reveal(page, 'CALL "LevelControl"');
  await visibleEditor(page)
    .locator('.view-line', { hasText: 'CALL "LevelControl"' })
    .locator('span > span', { hasText: '"LevelControl"' })
    .first()
    .click();
  await page.keyboard.press('F12');
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'LevelControl.scl' })).toHaveAttribute(
    'aria-current',
    'true',
  );
  await expect.poll(caret).toMatchObject({ text: expect.stringMatching(/^FUNCTION_BLOCK "LevelControl"/) });

  // A block in the tree opens at its header line too.
  await tree(page).getByTestId(`block-node-${projectId}-DB1`).dblclick();
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'TankSettings.awl' })).toHaveAttribute(
    'aria-current',
    'true',
  );
  await expect.poll(caret).toMatchObject({ text: expect.stringMatching(/^DATA_BLOCK/) });
  expect(watch.consoleErrors).toEqual([]);
});

test('Format Document lays STL out in STEP 7 columns', async ({ page, watch }) => {
  await page.goto('/');
  const projectId = await expandProject(page, 'traffic-light');
  const editor = await openFile(page, projectId, 'OB1.awl');
  await typeLineAfter(page, editor, 'SD    "Red time";', 'a "Red time"  ;   // typed loosely');
  // Monaco's key for Format Document: Ctrl+Shift+I on Linux (where these tests run), Shift+Alt+F elsewhere.
  await page.keyboard.press(process.platform === 'linux' ? 'Control+Shift+I' : 'Shift+Alt+F');
  await expect
    .poll(() => textOf(page))
    .toContain(`      a     "Red time";${' '.repeat(13)}// typed loosely\n`);
  const text = await textOf(page);
  expect(text).toContain(`      AN    "Yellow time";${' '.repeat(10)}// the last phase ran out: restart the cycle\n`);
  // Declarations and headers keep their layout.
  expect(text.startsWith('ORGANIZATION_BLOCK "Main"\nTITLE = Traffic light')).toBe(true);
  expect(watch.consoleErrors).toEqual([]);
});

test('a save refused as stale offers to reload the newer text or to overwrite it', async ({ page, request, watch }) => {
  await page.goto('/');
  const projectId = await expandProject(page, 'tank-level');
  const editor = await openFile(page, projectId, 'Scale.scl');
  // Someone else saves the file meanwhile.
  const current = await (await request.get(`/api/projects/${projectId}/files/Scale.scl`)).json();
  const theirs = `${current.text as string}// changed in another window\n`;
  expect((await request.put(`/api/projects/${projectId}/files/Scale.scl`, { data: { text: theirs } })).ok()).toBe(true);

  await typeLineAfter(page, editor, 'END_FUNCTION', '// my change');
  const conflict = page.getByTestId('save-conflict');
  await expect(conflict).toBeVisible({ timeout: 10_000 });
  await expect(conflict).toContainText('API111');
  await expect(conflict).toContainText('was changed elsewhere');
  await page.getByTestId('save-conflict-reload').click();
  await expect(conflict).toBeHidden();
  expect(await textOf(page)).toBe(theirs);

  // Again, and this time keep mine.
  expect((await request.put(`/api/projects/${projectId}/files/Scale.scl`, { data: { text: `${theirs}// third\n` } })).ok()).toBe(
    true,
  );
  await typeLineAfter(page, editor, 'changed in another window', '// mine wins');
  await expect(conflict).toBeVisible({ timeout: 10_000 });
  await page.getByTestId('save-conflict-overwrite').click();
  await expect(conflict).toBeHidden();
  await expect
    .poll(async () => (await (await request.get(`/api/projects/${projectId}/files/Scale.scl`)).json()).text as string)
    .toContain('// mine wins');
  expect(watch.consoleErrors.filter((text) => !/409/.test(text))).toEqual([]);
});

test('the tree creates, renames and deletes sources from the keyboard, exports and imports a project', async ({
  page,
  watch,
}) => {
  await page.goto('/');
  const projectId = await expandProject(page, 'traffic-light');
  const projectRow = tree(page).getByTestId(`project-node-${projectId}`);

  // Shift+F10 opens the row's actions; the first one has the focus.
  await projectRow.focus();
  await page.keyboard.press('Shift+F10');
  const menu = page.getByTestId('tree-menu');
  await expect(menu).toBeVisible();
  await expect(menu.getByRole('menuitem').first()).toBeFocused();
  await menu.getByRole('menuitem', { name: 'New STL source…' }).click();
  const dialog = page.getByTestId('file-new-dialog');
  await expect(dialog.getByTestId('file-name-input')).toHaveValue('Source1.awl');
  await dialog.getByTestId('file-name-input').fill('Lights.awl');
  await dialog.getByTestId('file-name-submit').click();
  await expect(dialog).toBeHidden();
  const newFile = tree(page).getByTestId(`file-node-${projectId}-Lights.awl`);
  await expect(newFile).toBeVisible();
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Lights.awl' })).toHaveAttribute(
    'aria-current',
    'true',
  );
  // The new source compiles: its FC is in the tree.
  await expect(tree(page).getByTestId(`block-node-${projectId}-FC1`)).toBeVisible();

  // F2 renames, and the open tab follows.
  await newFile.focus();
  await page.keyboard.press('F2');
  const rename = page.getByTestId('file-rename-dialog');
  await rename.getByTestId('file-name-input').fill('Signals.awl');
  await page.keyboard.press('Enter');
  await expect(rename).toBeHidden();
  await expect(tree(page).getByTestId(`file-node-${projectId}-Signals.awl`)).toBeVisible();
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Signals.awl' })).toBeVisible();

  // A taken name is refused with the catalogue's code.
  await tree(page).getByTestId(`file-node-${projectId}-Signals.awl`).focus();
  await page.keyboard.press('F2');
  await rename.getByTestId('file-name-input').fill('ob1.AWL');
  await page.keyboard.press('Enter');
  await expect(rename.getByTestId('file-name-error')).toContainText('API108');
  await page.keyboard.press('Escape');

  // Delete asks first; the tab closes with the file.
  await tree(page).getByTestId(`file-node-${projectId}-Signals.awl`).focus();
  await page.keyboard.press('Delete');
  const confirm = page.getByTestId('file-delete-dialog');
  await expect(confirm).toContainText('Signals.awl');
  await confirm.getByTestId('confirm-submit').click();
  await expect(confirm).toBeHidden();
  await expect(tree(page).getByTestId(`file-node-${projectId}-Signals.awl`)).toHaveCount(0);
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Signals.awl' })).toHaveCount(0);

  // Export from the menu (mouse: the row's three-dot button), then import the zip as a new project.
  await projectRow.locator('.tree-row').hover();
  await projectRow.locator('.tree-row__menu').click();
  const downloading = page.waitForEvent('download');
  await menu.getByRole('menuitem', { name: 'Export as zip' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('traffic-light.zip');
  const zip = await download.path();

  await page.getByTestId('project-import').click();
  const importDialog = page.getByTestId('project-import-dialog');
  await importDialog.getByTestId('project-import-file').setInputFiles(zip);
  const copyName = `Traffic copy ${Date.now()}`;
  await importDialog.getByTestId('project-import-name').fill(copyName);
  await importDialog.getByTestId('project-import-submit').click();
  await expect(importDialog).toBeHidden();
  const copy = tree(page).getByRole('treeitem', { name: copyName, exact: true });
  await expect(copy).toHaveAttribute('aria-expanded', 'true');
  await expect(copy).toHaveAttribute('aria-selected', 'true');
  const copyId = Number((await copy.getAttribute('data-testid'))?.replace('project-node-', ''));
  await expect(tree(page).getByTestId(`file-node-${copyId}-OB1.awl`)).toBeVisible();
  await expect(tree(page).getByTestId(`file-node-${copyId}-symbols.sdf`)).toBeVisible();
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

for (const code of ['en', 'fa', 'ar', 'vi'] as const) {
  test(`no accessibility violations with a project open, a file and the row menu in ${code}`, async ({ page }) => {
    await page.goto('/');
    await chooseLanguage(page, code);
    const projectId = await expandProject(page, 'tank-level');
    await openFile(page, projectId, 'OB1.awl');
    await tree(page).getByTestId(`file-node-${projectId}-OB1.awl`).focus();
    await page.keyboard.press('Shift+F10');
    await expect(page.getByTestId('tree-menu')).toBeVisible();
    const results = await new AxeBuilder({ page }).withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
    const summary = results.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    expect(summary).toEqual([]);
    await page.keyboard.press('Escape');
    await expect(tree(page).getByTestId(`file-node-${projectId}-OB1.awl`)).toBeFocused();
  });
}
