/**
 * Cross-references and rename in the "motor-start-stop" example, as a user drives them:
 * Shift+F12 on "Motor" lists every use and a click on a row goes to its line; F2 renames
 * "Motor" to "Pump" in every file (source and symbol table) after a preview, the renamed
 * program still passes the example's scenario (`nasaq test`), and Undo restores every file;
 * renaming to a symbol that exists is refused with XRF705 and changes nothing. Screenshots in
 * English and Persian: docs/screenshots/en-xref.png, fa-xref-rename.png.
 */
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import { test, expect, chooseLanguage, expandProject, openFile, visibleEditor } from './fixtures';

const root = path.resolve(__dirname, '../..');
const shots = path.join(root, 'docs', 'screenshots');

async function texts(request: APIRequestContext, projectId: number): Promise<Record<string, string>> {
  const listed = (await (await request.get(`/api/projects/${projectId}/files`)).json()) as { name: string }[];
  const found: Record<string, string> = {};
  for (const { name } of listed) {
    const file = (await (await request.get(`/api/projects/${projectId}/files/${encodeURIComponent(name)}`)).json()) as {
      text: string;
    };
    found[name] = file.text;
  }
  return found;
}

/** Puts the caret on the first letter of the quoted name on the editor line holding `lineText`. */
async function caretOn(page: Page, editor: Locator, lineText: string, quoted: string): Promise<void> {
  const line = editor.locator('.view-line', { hasText: lineText }).first();
  await line.click();
  await page.keyboard.press('Home'); // the first character that is not a blank
  const content = (await line.textContent())!.replace(/\u00a0/g, ' ');
  const steps = content.indexOf(quoted) + 1 - (content.length - content.trimStart().length);
  for (let i = 0; i < steps; i += 1) await page.keyboard.press('ArrowRight');
}

/** The line the editor's caret is on (Monaco marks its number in the gutter). */
const caretLine = (editor: Locator) => editor.locator('.line-numbers.active-line-number');

test('cross-references of "Motor", rename to "Pump" with preview and undo, and a refusal', async ({ page, watch, request }) => {
  test.setTimeout(240_000); // two renames, an undo, a scenario run and a language switch on a shared machine
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  const projectId = await expandProject(page, 'motor-start-stop');
  // A watch table naming the symbol: rename reaches it too (other tests may have left tables).
  const table = `/api/projects/${projectId}/files/${encodeURIComponent('Rename check.vat')}`;
  expect((await request.put(table, { data: { text: '"Motor" | BOOL  // the contactor\nQ 4.1 | BOOL\n' } })).ok()).toBe(true);
  const original = await texts(request, projectId);
  const tableLines = Object.entries(original)
    .filter(([name]) => name.endsWith('.vat'))
    .reduce((count, [, text]) => count + text.split('\n').filter((line) => line.includes('"Motor"')).length, 0);
  expect(tableLines).toBeGreaterThan(0);
  const editor = await openFile(page, projectId, 'OB1.awl');

  // Shift+F12 on "Motor": every use, with its block, network and line.
  await caretOn(page, editor, 'O     "Motor"', '"Motor"');
  await page.keyboard.press('Shift+F12');
  const panel = page.getByTestId('xref-panel');
  await expect(page.getByTestId('panel-tab-xref')).toHaveAttribute('aria-selected', 'true');
  const rows = panel.getByTestId('xref-row');
  await expect(rows).toHaveCount(3);
  expect(await rows.evaluateAll((items) => items.map((row) => row.getAttribute('data-line')))).toEqual(['15', '19', '22']);
  await expect(rows.nth(0)).toContainText('Read');
  await expect(rows.nth(1)).toContainText('Write');
  await expect(rows.nth(1)).toContainText('OB 1');
  await expect(rows.nth(2)).toContainText('NW 2 · 22');
  await expect(panel.getByTestId('xref-summary')).toContainText('"Motor" Q 4.0');

  // A click on each row goes to its line.
  for (const line of ['22', '15', '19']) {
    await panel.locator(`[data-testid="xref-row"][data-line="${line}"]`).click();
    await expect(caretLine(editor)).toHaveText(line);
  }
  await page.screenshot({ path: path.join(shots, 'en-xref.png'), animations: 'disabled' });

  // The assignment list: I 0.0-0.2 read, Q 4.0 read and written.
  await page.getByTestId('panel-tab-assignments').click();
  const assignments = page.getByTestId('assignment-panel');
  await expect(assignments.locator('[data-address="QB 4"]')).toContainText('RW');
  await expect(assignments.locator('[data-address="IB 0"]')).toContainText('R');

  // F2 on "Motor": preview, apply, every file renamed.
  await caretOn(page, editor, 'A     "Motor"', '"Motor"');
  await page.keyboard.press('F2');
  const dialog = page.getByTestId('rename-dialog');
  await expect(dialog).toBeVisible();
  await expect(dialog.getByTestId('rename-new-name')).toHaveValue('Motor');
  await dialog.getByTestId('rename-new-name').fill('Pump');
  await dialog.getByRole('button', { name: 'Preview changes' }).click();
  const changes = dialog.getByTestId('rename-change');
  await expect(changes).toHaveCount(4 + tableLines); // three lines of OB1.awl, the symbol table, the tables' rows
  await expect(changes.filter({ hasText: 'symbols.sdf' })).toHaveCount(1);
  await expect(changes.filter({ hasText: 'Rename check.vat' })).toHaveCount(1);
  expect(await texts(request, projectId)).toEqual(original); // a preview writes nothing
  await dialog.getByRole('button', { name: 'Apply' }).click();
  await expect(dialog.getByTestId('rename-done')).toBeVisible();
  const renamed = await texts(request, projectId);
  expect(renamed['OB1.awl']!.match(/"Pump"/g)).toHaveLength(3);
  expect(renamed['OB1.awl']).not.toContain('"Motor"');
  expect(renamed['symbols.sdf']).toContain('"Pump","Q 4.0"');
  expect(renamed['Rename check.vat']).toBe('"Pump" | BOOL  // the contactor\nQ 4.1 | BOOL\n');
  // The open editor took the renamed text (no conflict with its autosave).
  await expect(visibleEditor(page).locator('.view-line', { hasText: '=     "Pump"' })).toBeVisible();

  // The renamed program still passes the example's scenario.
  const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'nasaq-xref-'));
  for (const [name, text] of Object.entries(renamed)) if (!name.endsWith('.vat')) fs.writeFileSync(path.join(folder, name), text);
  fs.copyFileSync(path.join(root, 'examples', 'projects', 'motor-start-stop', 'motor.yaml'), path.join(folder, 'motor.yaml'));
  execFileSync(path.join(root, '.venv', 'bin', 'nasaq'), ['test', path.join(folder, 'motor.yaml')], { stdio: 'pipe' });
  fs.rmSync(folder, { recursive: true, force: true });

  // Undo restores every file.
  await dialog.getByRole('button', { name: 'Undo rename' }).click();
  await expect(dialog.getByTestId('rename-undone')).toBeVisible();
  expect(await texts(request, projectId)).toEqual(original);
  await expect(visibleEditor(page).locator('.view-line', { hasText: '=     "Motor"' })).toBeVisible();
  await dialog.getByRole('button', { name: 'Close', exact: true }).click();
  await expect(dialog).toBeHidden();

  // Renaming to a symbol that exists is refused with its code, and nothing changes.
  await caretOn(page, editor, 'A     "Motor"', '"Motor"');
  await page.keyboard.press('F2');
  await dialog.getByTestId('rename-new-name').fill('Start');
  await dialog.getByRole('button', { name: 'Preview changes' }).click();
  await expect(dialog.getByTestId('rename-error')).toContainText('XRF705');
  await expect(dialog.getByTestId('rename-error')).toContainText("'Start' is already used");
  expect(await texts(request, projectId)).toEqual(original);
  await dialog.getByRole('button', { name: 'Close', exact: true }).click();

  // Persian: right-to-left panel and dialog, the refusal in Persian.
  await chooseLanguage(page, 'fa');
  await page.getByTestId('panel-tab-xref').click();
  await expect(panel).toHaveAttribute('dir', 'rtl');
  await caretOn(page, editor, 'A     "Motor"', '"Motor"');
  await page.keyboard.press('F2');
  await dialog.getByTestId('rename-new-name').fill('Start');
  await dialog.getByRole('button', { name: 'پیش‌نمایش تغییرها' }).click();
  await expect(dialog.getByTestId('rename-error')).toContainText('XRF705');
  await expect(dialog.getByTestId('rename-error')).toContainText('به کار رفته است');
  await page.screenshot({ path: path.join(shots, 'fa-xref-rename.png'), animations: 'disabled' });
  await dialog.getByRole('button', { name: 'بستن', exact: true }).click();
  expect(await texts(request, projectId)).toEqual(original);

  expect((await request.delete(table)).ok()).toBe(true);
  expect(watch.consoleErrors.filter((text) => !text.includes('409') && !text.includes('422'))).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
