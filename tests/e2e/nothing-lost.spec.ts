/**
 * Nothing is lost, and the rough edges a new user found, against the real server: the Start
 * page's new source is a project file and a reload with a pending save asks first (and the text
 * is on the server after it); "New symbol table" gives an empty table where Tab moves across the
 * cells and `M 1.0 : INT` is marked, the compiler reports it with its line and the status bar
 * counts what the Diagnostics panel lists; a diagnostic buffer entry opens the faulting block at
 * its line and F12 on a symbol selects its row in the symbol table.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { test, expect, chooseLanguage, visibleEditor, tree } from './fixtures';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

async function makeProject(request: APIRequestContext, name: string, files: Record<string, string>): Promise<number> {
  const created = await request.post('/api/projects', { data: { name, description: '' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [file, text] of Object.entries(files)) {
    expect((await request.put(`/api/projects/${id}/files/${file}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

async function expand(page: Page, projectId: number): Promise<void> {
  const node = page.getByTestId(`project-node-${projectId}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
}

/** The caret of the editor in front: [line, column]. */
function caret(page: Page): Promise<[number, number]> {
  return page.evaluate(() => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const position = editor?.getPosition();
    return [position?.lineNumber ?? 0, position?.column ?? 0] as [number, number];
  });
}

const OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Main cycle
BEGIN
NETWORK
TITLE = Motor
      A     "Start"
      =     "Motor"
NETWORK
TITLE = A data block that was never downloaded
      L     1
      T     MW 10
      OPN   DB 99
      L     DBW 0
END_ORGANIZATION_BLOCK
`;
const PLAIN_OB1 = 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      A     I 0.0\n      =     Q 4.0\nEND_ORGANIZATION_BLOCK\n';
const SYMBOLS = '"Start","I 0.0","BOOL","start button"\n"Motor","Q 4.0","BOOL","motor contactor"\n';

test('a new source from the Start page is a project file; a reload with a save pending asks, and nothing is lost', async ({
  page,
  request,
  watch,
}, testInfo) => {
  test.setTimeout(90_000); // two reloads, each loading the editor again
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 15_000 });
  // No project is selected: the Start page asks where the source goes.
  await page.getByTestId('new-source-stl').click();
  const pick = page.getByTestId('project-pick-dialog');
  await expect(pick).toBeVisible();
  await expect(pick.getByTestId('project-pick-select')).toBeVisible();
  await page.screenshot({ path: testInfo.outputPath('en-pick-project.png') });
  await pick.getByTestId('project-pick-new').click();
  const name = `Nothing lost ${Date.now()}`;
  await page.getByTestId('project-name-input').fill(name);
  await page.getByTestId('project-create-submit').click();

  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Source1.awl' });
  await expect(tab).toHaveAttribute('data-save-state', 'saved');
  // The tree shows the new project open at its new file.
  const projectRow = tree(page).getByRole('treeitem', { name, exact: true });
  await expect(projectRow).toHaveAttribute('aria-expanded', 'true');
  const projectId = Number((await projectRow.getAttribute('data-testid'))?.replace('project-node-', ''));
  await expect(tree(page).getByTestId(`file-node-${projectId}-Source1.awl`)).toBeVisible();

  // Typed, and the page reloaded at once, before the autosave's second is up: the browser asks.
  await editor.locator('.view-lines').click();
  await page.keyboard.press('Control+End');
  await page.keyboard.press('Escape');
  await page.keyboard.type('\n// typed just before the reload');
  await expect(tab).not.toHaveAttribute('data-save-state', 'saved');
  const asked: string[] = [];
  page.once('dialog', (dialog) => {
    asked.push(dialog.type());
    void dialog.accept(); // the user leaves anyway
  });
  await page.reload();
  expect(asked).toEqual(['beforeunload']);
  // The pending save went out as the page left: the text is on the server.
  await expect
    .poll(async () => ((await (await request.get(`/api/projects/${projectId}/files/Source1.awl`)).json()) as { text: string }).text)
    .toContain('// typed just before the reload');

  // Everything saved: a reload does not ask.
  await expand(page, projectId);
  await tree(page).getByTestId(`file-node-${projectId}-Source1.awl`).dblclick();
  await expect(visibleEditor(page)).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
  const shown = await page.evaluate(() => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    return editor?.getModel()?.getValue() ?? '';
  });
  expect(shown).toContain('// typed just before the reload');
  const again: string[] = [];
  page.on('dialog', (dialog) => {
    again.push(dialog.type());
    void dialog.accept();
  });
  await page.reload();
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 15_000 });
  expect(again).toEqual([]);
  expect(watch.consoleErrors).toEqual([]);
});

test('"New symbol table" gives an empty table: Tab moves across the cells, M 1.0 : INT is an error with its line', async ({
  page,
  request,
  watch,
}, testInfo) => {
  test.setTimeout(90_000); // two compiles and a language switch
  const projectId = await makeProject(request, `Symbols ${Date.now()}`, { 'OB1.awl': PLAIN_OB1 });
  await page.goto('/');
  await expand(page, projectId);
  await page.getByTestId(`project-node-${projectId}`).focus();
  await page.keyboard.press('Shift+F10');
  await page.getByTestId('tree-menu').getByRole('menuitem', { name: 'New symbol table…' }).click();
  const dialog = page.getByTestId('file-new-dialog');
  await expect(dialog.getByTestId('file-name-input')).toHaveValue('Symbols.sdf');
  await dialog.getByTestId('file-name-submit').click();

  const table = page.locator('[data-testid="symbol-table"]:not([hidden])');
  await expect(table).toBeVisible({ timeout: 15_000 });
  // Empty: no template rows, only the row that adds one.
  await expect(table.getByTestId('symbol-row')).toHaveCount(0);
  await expect(table.getByTestId('symbol-count')).toHaveText('0 rows');

  // Typed as in a spreadsheet: Tab to the next cell, and from the last cell to the next row.
  await table.getByTestId('symbol-row-new').getByTestId('symbol-cell-name').click();
  await page.keyboard.type('Count');
  const focused = () => page.evaluate(() => {
    const element = document.activeElement as HTMLElement | null;
    return `${element?.dataset.row}:${element?.dataset.col}`;
  });
  for (const [value, cell] of [['M 1.0', '0:1'], ['INT', '0:2'], ['starts of the motor', '0:3']] as const) {
    await page.keyboard.press('Tab');
    expect(await focused()).toBe(cell);
    await page.keyboard.type(value);
  }
  await page.keyboard.press('Tab');
  expect(await focused()).toBe('1:0');
  await page.keyboard.press('Shift+Tab');
  expect(await focused()).toBe('0:3');
  await page.keyboard.press('Shift+Tab');
  expect(await focused()).toBe('0:2');

  // The type does not fit the bit address: the cell is marked, with the code and what fits.
  const row = table.locator('[data-testid="symbol-row"][data-name="Count"]');
  await expect(row.getByTestId('symbol-cell-type')).toHaveAttribute('aria-invalid', 'true', { timeout: 10_000 });
  await expect(table.getByTestId('symbol-row-problems')).toContainText('SYT002');
  await expect(table.getByTestId('symbol-row-problems')).toContainText('M 1.0, which takes BOOL');
  await expect(table.getByTestId('symbol-save-state')).toHaveAttribute('data-state', 'saved');
  await page.screenshot({ path: testInfo.outputPath('en-symbol-misfit.png') });

  // The compiler says so too, at the table's line; the status bar counts what the panel lists.
  await page.keyboard.press('Control+F7');
  const list = page.getByTestId('diagnostics');
  await expect(list.getByTestId('diagnostic').filter({ hasText: 'SYT001' })).toContainText('Symbols.sdf:1');
  const count = await list.getByTestId('diagnostic').count();
  const errors = await list.locator('.diagnostic--error').count();
  const warnings = await list.locator('.diagnostic--warning').count();
  await expect(page.getByTestId('compile-status')).toHaveText(`Compiled — errors: ${errors}, warnings: ${warnings}`);
  expect(errors).toBeGreaterThan(0);
  await expect(page.getByTestId('panel-tab-diagnostics')).toContainText(String(errors + warnings));
  expect(count).toBeGreaterThanOrEqual(errors + warnings);

  // Fixed: the mark and the error go, and the footer follows the panel.
  await row.getByTestId('symbol-cell-type').fill('BOOL');
  await expect(row.getByTestId('symbol-cell-type')).not.toHaveAttribute('aria-invalid', 'true', { timeout: 10_000 });
  await expect(table.getByTestId('symbol-save-state')).toHaveAttribute('data-state', 'saved');
  await page.keyboard.press('Control+F7');
  await expect(list.getByTestId('diagnostic').filter({ hasText: 'SYT001' })).toHaveCount(0);
  await expect(page.getByTestId('compile-status')).toHaveText(/^Compiled — errors: 0, warnings: \d+$/);

  // In Persian: the problem in Persian, the grid still left-to-right.
  await row.getByTestId('symbol-cell-type').fill('INT');
  await expect(row.getByTestId('symbol-cell-type')).toHaveAttribute('aria-invalid', 'true', { timeout: 10_000 });
  await chooseLanguage(page, 'fa');
  await row.getByTestId('symbol-cell-type').click();
  await expect(table.getByTestId('symbol-row-problems')).toContainText('جور نیست');
  await expect(table.getByTestId('symbol-grid')).toHaveAttribute('dir', 'ltr');
  await page.screenshot({ path: testInfo.outputPath('fa-symbol-misfit.png') });
  expect(watch.consoleErrors).toEqual([]);
});

test('a diagnostic buffer entry opens the faulting block at its line; F12 on a symbol selects its row', async ({
  page,
  request,
  watch,
}, testInfo) => {
  test.setTimeout(90_000); // a download, a RUN and two editors
  const projectId = await makeProject(request, `Buffer ${Date.now()}`, { 'OB1.awl': OB1, 'symbols.sdf': SYMBOLS });
  await page.goto('/');
  await expand(page, projectId);
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  // OPN DB 99 on line 12: the CPU goes to STOP with an entry in its buffer.
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('panel-tab-diagnostics').click();
  const entry = page.getByTestId('cpu-diagnostic').filter({ hasText: 'SIM505' });
  await expect(entry).toBeVisible({ timeout: 10_000 });
  await expect(entry.getByTestId('cpu-diagnostic-open')).toContainText('OB1 NW 2 L 12');
  await entry.getByTestId('cpu-diagnostic-open').click();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
  await expect(page.locator('[data-testid^="editor-tab-source-"][aria-current="true"]')).toContainText('OB1.awl');
  await expect.poll(() => caret(page)).toEqual([12, 1]);
  await page.screenshot({ path: testInfo.outputPath('en-buffer-jump.png') });

  // F12 on "Motor": the symbol table, its row selected.
  await page.evaluate(() => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const lines = editor?.getModel()?.getLinesContent() ?? [];
    const index = lines.findIndex((line) => line.includes('"Motor"'));
    editor?.setPosition({ lineNumber: index + 1, column: (lines[index] ?? '').indexOf('Motor') + 2 });
    editor?.focus();
  });
  await page.keyboard.press('F12');
  const table = page.locator('[data-testid="symbol-table"]:not([hidden])');
  await expect(table).toBeVisible({ timeout: 15_000 });
  const motor = table.locator('[data-testid="symbol-row"][data-name="Motor"]');
  await expect(motor).toHaveAttribute('aria-selected', 'true');
  await expect(motor.getByTestId('symbol-cell-name')).toBeFocused();
  await expect(table.locator('[data-testid="symbol-row"][aria-selected="true"]')).toHaveCount(1);

  await chooseLanguage(page, 'fa');
  await page.getByTestId('panel-tab-diagnostics').click();
  await expect(entry).toBeVisible();
  await page.screenshot({ path: testInfo.outputPath('fa-buffer.png') });
  expect(watch.consoleErrors).toEqual([]);
});
