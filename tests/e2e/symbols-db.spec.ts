/**
 * The symbol table editor and the DB editor against the real server and the "tank-level"
 * example: add a symbol in the grid (autosaved: it is there after a reload), download the table
 * as a STEP 7 .asc, import a .sdf, see the text view; open DB "LevelData" in the DB editor, its
 * offline values, then download, RUN, watch a live value and modify one.
 */
import type { Page } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { test, expect, chooseLanguage, tree, expandProject } from './fixtures';


async function openSymbols(page: Page, projectId: number) {
  await tree(page).getByTestId(`file-node-${projectId}-symbols.sdf`).dblclick();
  const table = page.locator('[data-testid="symbol-table"]:not([hidden])');
  await expect(table.getByTestId('symbol-row').first()).toBeVisible({ timeout: 15_000 });
  return table;
}

const rowNamed = (page: Page, name: string) => page.locator(`[data-testid="symbol-row"][data-name="${name}"]`);

test('edit, autosave, export and import the symbol table', async ({ page, watch }) => {
  test.setTimeout(90_000); // a reload, a download, an import and an accessibility scan
  await page.goto('/');
  const projectId = await expandProject(page, 'tank-level');
  const table = await openSymbols(page, projectId);
  await expect(rowNamed(page, 'LevelData')).toBeVisible();
  await expect(table.getByTestId('symbol-problem-count')).toHaveText('No problems');

  // A new symbol, typed into the empty last row; the autosave PUTs the rows.
  const saved = page.waitForResponse(
    (response) => response.request().method() === 'PUT' && response.url().includes('/symbols/symbols.sdf') && response.ok(),
  );
  await table.getByTestId('symbol-row-new').getByTestId('symbol-cell-name').click();
  await page.keyboard.type('Drain valve');
  for (const value of ['Q 4.2', 'BOOL', 'drain valve of the tank']) {
    await page.keyboard.press('ArrowRight');
    await page.keyboard.type(value);
  }
  await saved;
  await expect(table.getByTestId('symbol-save-state')).toHaveAttribute('data-state', 'saved');
  await expect(rowNamed(page, 'Drain valve').getByTestId('symbol-cell-address')).toHaveValue('Q 4.2');

  // A bad address shows its problem with its code on the cell.
  await rowNamed(page, 'Drain valve').getByTestId('symbol-cell-type').fill('FLOAT');
  await expect(rowNamed(page, 'Drain valve').getByTestId('symbol-cell-type')).toHaveAttribute('aria-invalid', 'true', {
    timeout: 5_000,
  });
  await expect(table.getByTestId('symbol-row-problems')).toContainText('API123');
  await rowNamed(page, 'Drain valve').getByTestId('symbol-cell-type').fill('BOOL');
  await expect(rowNamed(page, 'Drain valve').getByTestId('symbol-cell-type')).not.toHaveAttribute('aria-invalid', 'true');
  await expect(table.getByTestId('symbol-save-state')).toHaveAttribute('data-state', 'saved');

  // Saved in the database: there after a reload.
  await page.reload();
  const again = await expandProject(page, 'tank-level');
  const reloaded = await openSymbols(page, again);
  await expect(rowNamed(page, 'Drain valve').getByTestId('symbol-cell-comment')).toHaveValue('drain valve of the tank');

  // The .asc download: STEP 7's fixed columns, Windows line ends.
  await reloaded.getByTestId('symbol-export').click();
  const downloading = page.waitForEvent('download');
  await reloaded.getByTestId('symbol-export-asc').click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('symbols.asc');
  const chunks: Buffer[] = [];
  for await (const chunk of (await download.createReadStream())!) chunks.push(chunk as Buffer);
  const asc = Buffer.concat(chunks).toString('latin1');
  expect(asc).toContain(`126,${'Drain valve'.padEnd(24)}${'Q 4.2'.padEnd(12)}${'BOOL'.padEnd(10)}drain valve of the tank\r\n`);
  expect(asc).toContain(`126,${'LevelData'.padEnd(24)}${'DB 10'.padEnd(12)}FB 10`);
  await reloaded.getByTestId('symbol-export').click(); // closes the menu

  // Importing a .sdf, merged by name.
  await reloaded.getByTestId('symbol-import-mode').selectOption('merge');
  const sdf = '"Mixer                   ","Q 5.0       ","BOOL      ","agitator motor"\r\n';
  await reloaded.getByTestId('symbol-import-file').setInputFiles({ name: 'extra.sdf', mimeType: 'text/plain', buffer: Buffer.from(sdf, 'latin1') });
  await expect(rowNamed(page, 'Mixer')).toBeVisible();
  await expect(rowNamed(page, 'Drain valve')).toBeVisible();
  await expect(reloaded.getByRole('status')).toContainText('extra.sdf');

  // Accessible in a right-to-left language too; the grid's data stays left-to-right.
  await chooseLanguage(page, 'ar');
  await expect(reloaded.getByTestId('symbol-grid')).toHaveAttribute('dir', 'ltr');
  const axe = await new AxeBuilder({ page }).include('[data-testid="symbol-table"]:not([hidden])').analyze();
  expect(axe.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
  await chooseLanguage(page, 'en');

  // The raw text is one click away, with the imported symbol in it.
  await page.getByTestId('symbol-view-text').click();
  const editor = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(editor.locator('.view-lines')).toContainText('Mixer');
  await page.getByTestId('symbol-view-table').click();
  await expect(rowNamed(page, 'Mixer')).toBeVisible();
  expect(watch.consoleErrors).toEqual([]);
});

test('the DB editor shows LevelData offline, then live, and modifies a value', async ({ page, watch }) => {
  test.setTimeout(60_000); // compiles and starts a simulated CPU
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const projectId = await expandProject(page, 'tank-level');
  const db = tree(page).getByTestId(`block-node-${projectId}-DB10`);
  await db.focus();
  await page.keyboard.press('Shift+F10');
  await page.getByTestId('tree-menu').getByRole('menuitem', { name: 'Open data view' }).click();
  const editor = page.locator('[data-testid^="db-editor-"]:not([hidden])');
  const row = (path: string) => editor.locator(`[data-testid="db-row"][data-path="${path}"]`);
  await expect(row('LowLevel').getByTestId('db-actual')).toHaveText('0.0');
  await expect(row('Enable').getByTestId('db-actual')).toHaveText('FALSE');
  await expect(editor.getByTestId('db-online-state')).toContainText('Offline');

  // The declaration view, and the link to the FB's declaration.
  await editor.getByTestId('db-view-declaration').click();
  await expect(row('Level')).toContainText('REAL');
  await editor.getByTestId('db-view-data').click();

  // Download (Ctrl+B) and RUN: the live values arrive.
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect(editor.getByTestId('db-online-state')).toContainText('Online');
  await expect(row('LowLevel').getByTestId('db-online')).toHaveText(/^20(\.0)?$/);

  // Modify: the pump's start counter (the controller is off, so the program leaves it).
  await row('Starts').getByTestId('db-modify-value').fill('5');
  await row('Starts').getByTestId('db-modify').click();
  await expect(row('Starts').getByTestId('db-online')).toHaveText('5');

  const axe = await new AxeBuilder({ page }).include('[data-testid^="db-editor-"]:not([hidden])').analyze();
  expect(axe.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);

  // Edit source opens the instance DB's text at its header.
  await editor.getByTestId('db-edit-source').click();
  await expect(page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'LevelData.awl' })).toHaveAttribute(
    'aria-current',
    'true',
  );
  expect(watch.consoleErrors).toEqual([]);
});
