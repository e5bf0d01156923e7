/**
 * Watch tables saved in the project (STEP 7's VATs, `.vat` files): a named table with rows,
 * display formats (S5TIME, C#) and modify values survives a reload and exports as text; a file
 * with a broken line loads its good lines and marks the bad one; in Persian a watch-table error
 * reads without English words. Screenshots: docs/screenshots/en-watch-tables.png, fa-watch-tables.png.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');
const example = path.join(root, 'examples', 'projects', 'motor-start-stop');
const shots = path.join(root, 'docs', 'screenshots');

async function motorProject(request: APIRequestContext, extra: Record<string, string> = {}): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: `Watch ${Date.now()}-${Math.random()}` } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  const files: Record<string, string> = { ...extra };
  for (const file of readdirSync(example).filter((f) => f.endsWith('.awl') || f.endsWith('.sdf'))) {
    files[file] = readFileSync(path.join(example, file), 'utf8');
  }
  for (const [name, text] of Object.entries(files)) {
    expect((await request.put(`/api/projects/${id}/files/${encodeURIComponent(name)}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

async function openProject(page: Page, projectId: number): Promise<void> {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 20_000 });
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') {
    await page.getByTestId('lesson-toggle').click();
  }
  const node = page.getByTestId(`project-node-${projectId}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
}

async function download(page: Page): Promise<void> {
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
}

test.describe.configure({ timeout: 90_000 });

const row = (page: Page, entry: string) => page.locator(`[data-testid="watch-row"][data-entry='${entry}']`);

/** The Watch tab with its table bar in view, on a taller window. */
async function shoot(page: Page, name: string): Promise<void> {
  await page.setViewportSize({ width: 1280, height: 900 });
  await page.getByRole('toolbar', { name: /./ }).filter({ has: page.getByTestId('watch-table-new') }).scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(shots, name) });
  await page.setViewportSize({ width: 1280, height: 720 });
}

async function addRow(page: Page, entry: string): Promise<void> {
  await page.getByTestId('watch-add-entry').fill(entry);
  await page.getByTestId('watch-add').click();
  await expect(row(page, entry)).toBeVisible();
}

test('a named watch table with formats and modify values survives a reload and exports as text', async ({ page, watch }) => {
  const projectId = await motorProject(page.request);
  await openProject(page, projectId);
  await download(page);
  await page.getByTestId('panel-tab-watch').click();

  await page.getByTestId('watch-table-new').click();
  await page.getByTestId('watch-table-name').fill('Motor check');
  await page.getByTestId('watch-table-name-ok').click();
  await expect(page.getByTestId('watch-table-select')).toHaveValue('Motor check.vat');

  await addRow(page, '"Motor"');
  await addRow(page, 'MW10');
  await addRow(page, 'MW12');
  await addRow(page, 'C5');
  // A timer word shown as S5TIME, modified with an S5TIME value: the CPU stores base + BCD.
  await row(page, 'MW10').getByTestId('watch-format').selectOption('s5time');
  await row(page, 'MW10').getByTestId('watch-modify-value').fill('S5T#1S850MS');
  await row(page, 'MW10').getByTestId('watch-modify').click();
  await expect(row(page, 'MW10').getByTestId('watch-value')).toHaveText('S5T#1S850MS');
  await row(page, 'MW10').getByTestId('watch-format').selectOption('hex');
  await expect(row(page, 'MW10').getByTestId('watch-value')).toHaveText('W#16#0185');
  await row(page, 'MW10').getByTestId('watch-format').selectOption('s5time');
  // A counter word: C#25 is stored as BCD.
  await row(page, 'MW12').getByTestId('watch-format').selectOption('counter');
  await row(page, 'MW12').getByTestId('watch-modify-value').fill('C#25');
  await row(page, 'MW12').getByTestId('watch-modify').click();
  await expect(row(page, 'MW12').getByTestId('watch-value')).toHaveText('C#25');
  // A counter shows its count as C#.
  await expect(row(page, 'C5').getByTestId('watch-value')).toHaveText('C#0');
  // A value that is no S5TIME is refused in the row, not sent.
  await row(page, 'MW10').getByTestId('watch-modify-value').fill('S5T#9H');
  await row(page, 'MW10').getByTestId('watch-modify').click();
  await expect(row(page, 'MW10').getByTestId('watch-error')).toContainText('WAT808');
  await row(page, 'MW10').getByTestId('watch-modify-value').fill('S5T#1S850MS');
  await expect(page.getByTestId('watch-table-save')).toHaveAttribute('data-status', 'saved', { timeout: 10_000 });
  await shoot(page, 'en-watch-tables.png');

  // The table is a project file: after a reload it is there with its rows and values.
  await page.reload();
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 20_000 });
  await page.getByTestId(`project-node-${projectId}`).click();
  await page.getByTestId('panel-tab-watch').click();
  await expect(page.getByTestId('watch-table-select')).toHaveValue('Motor check.vat');
  await expect(page.getByTestId('watch-row')).toHaveCount(4);
  await expect(row(page, 'MW10').getByTestId('watch-modify-value')).toHaveValue('S5T#1S850MS');
  await expect(row(page, 'MW12').getByTestId('watch-modify-value')).toHaveValue('C#25');
  // The tree lists it under "Watch tables"; opening it there shows it in the panel.
  await expect(page.getByTestId(`folder-node-${projectId}-watch`)).toContainText('Watch tables');
  await expect(page.getByTestId(`file-node-${projectId}-Motor check.vat`)).toBeVisible();

  // Export: the text file, one row per line.
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByTestId('watch-table-export').click()]);
  expect(file.suggestedFilename()).toBe('Motor check.vat');
  const text = readFileSync((await file.path())!, 'utf8');
  expect(text.split('\n')).toEqual([
    '// Nasaq watch table: operand | format | modify value | force value // comment',
    '"Motor"',
    'MW10         | S5TIME  | S5T#1S850MS',
    'MW12         | COUNTER | C#25',
    'C5',
    '',
  ]);
  // The download ignores the table: the program still compiles and downloads.
  await download(page);
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('a table file with a broken line loads its good lines; in Persian its errors read without English', async ({ page, watch }) => {
  const broken = [
    '// Nasaq watch table: operand | format | modify value | force value // comment',
    '"Motor"      | BOOL',
    'MW12         | DECIMALS',
    'I 0.1        | BOOL     |          | TRUE  // stop button',
  ].join('\n');
  const projectId = await motorProject(page.request, { 'Checks.vat': `${broken}\n` });
  await openProject(page, projectId);
  // Opened from the tree, as TIA Portal opens a watch table.
  await page.getByTestId(`file-node-${projectId}-Checks.vat`).dblclick();
  await expect(page.getByTestId('watch-table-select')).toHaveValue('Checks.vat');
  await expect(page.getByTestId('watch-row')).toHaveCount(2);
  await expect(row(page, 'I 0.1').getByTestId('watch-comment')).toHaveText('stop button');
  const bad = page.getByTestId('watch-broken-line');
  await expect(bad).toHaveCount(1);
  await expect(bad).toContainText('Line 3');
  await expect(bad).toContainText('WAT802');
  await expect(bad).toContainText("is not one of the watch table's display formats");
  await expect(bad).toContainText('DECIMALS');

  // A mistyped row is refused with its reason; nothing is added.
  await page.getByTestId('watch-add-entry').fill('M 0.0 0.1');
  await page.getByTestId('watch-add').click();
  await expect(page.getByTestId('watch-add-error')).toContainText('WAT801');

  await chooseLanguage(page, 'fa');
  await download(page);
  await addRow(page, 'MW999999');
  await addRow(page, '"Ghost"');
  const errors = [
    row(page, 'MW999999').getByTestId('watch-error'),
    row(page, '"Ghost"').getByTestId('watch-error'),
    page.getByTestId('watch-line-error'),
  ];
  await expect(errors[0]).toContainText('MON603');
  await expect(errors[1]).toContainText('WAT806');
  await page.getByTestId('watch-add-entry').fill('M 0.0 0.1');
  await page.getByTestId('watch-add').click();
  errors.push(page.getByTestId('watch-add-error'));
  // What the user typed (addresses, symbols, the broken line) and the codes may be Latin; no
  // other word may be.
  const typed = [broken.split('\n')[2]!, 'MW999999', '"Ghost"', 'M 0.0 0.1', 'DECIMALS'];
  for (const error of errors) {
    const spaced = (value: string) => value.replace(/\s+/g, ' ');
    let text = spaced(await error.innerText()).replace(/\b[A-Z]{3}\d{3}\b/g, '');
    for (const token of typed) text = text.split(spaced(token)).join('');
    expect(text, `rendered: ${await error.innerText()}`).not.toMatch(/[A-Za-z]{2,}/);
    expect(text).toMatch(/[\u0600-\u06FF]/);
  }
  await shoot(page, 'fa-watch-tables.png');
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
