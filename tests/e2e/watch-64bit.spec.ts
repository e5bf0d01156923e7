/**
 * A watch table of an S7-1500 project shows and modifies the 64-bit values: an LREAL and an LINT
 * the program computes with (modified, the next scans use them), an LINT beyond 2**53 exact in
 * DEC and HEX, an LTIME as LT#; the same rows read the same in Persian (right to left, values
 * left to right).
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { test, expect, chooseLanguage } from './fixtures';

const MAIN = `DATA_BLOCK "Data"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      x : LREAL := 1.5;
      big : LINT := 40000000000;
      lt : LTIME := LT#1D2H3M4S5MS6US7NS;
      y : LREAL;
      sum : LINT;
   END_VAR
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
BEGIN
  "Data".y := "Data".x * 2.0;
  "Data".sum := "Data".big + 1;
END_ORGANIZATION_BLOCK
`;

async function makeProject(request: APIRequestContext): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: `Long values ${Date.now()}` } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [name, text] of Object.entries({ 'Main.scl': MAIN, 'cpu.properties': 'profile = S7-1500\n' })) {
    expect((await request.put(`/api/projects/${id}/files/${name}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

const row = (page: Page, entry: string) => page.locator(`[data-testid="watch-row"][data-entry='${entry}']`);

async function addRow(page: Page, entry: string): Promise<void> {
  await page.getByTestId('watch-add-entry').fill(entry);
  await page.getByTestId('watch-add').click();
  await expect(row(page, entry)).toBeVisible();
}

async function modify(page: Page, entry: string, value: string): Promise<void> {
  await row(page, entry).getByTestId('watch-modify-value').fill(value);
  await row(page, entry).getByTestId('watch-modify').click();
}

test.describe.configure({ timeout: 120_000 });
test.use({ viewport: { width: 1280, height: 1200 } });

test('watch and modify an LREAL and an LINT of an S7-1500 project', async ({ page, watch }, testInfo) => {
  const projectId = await makeProject(page.request);
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 20_000 });
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') {
    await page.getByTestId('lesson-toggle').click();
  }
  const node = page.getByTestId(`project-node-${projectId}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await page.getByTestId('panel-tab-watch').click();

  for (const entry of ['"Data".x', '"Data".y', '"Data".big', '"Data".sum', '"Data".lt']) await addRow(page, entry);
  const value = (entry: string) => row(page, entry).getByTestId('watch-value');
  await expect(value('"Data".y')).toHaveText('3');
  await expect(value('"Data".sum')).toHaveText('40000000001');
  await expect(value('"Data".lt')).toHaveText('LT#1D_2H_3M_4S_5MS_6US_7NS');

  // Modified, the program computes with them at its next scans.
  await modify(page, '"Data".x', '0.1');
  await modify(page, '"Data".big', '9000000000000000000');
  await expect(value('"Data".y')).toHaveText('0.2');
  await expect(value('"Data".sum')).toHaveText('9000000000000000001');
  await row(page, '"Data".sum').getByTestId('watch-format').selectOption('hex');
  await expect(value('"Data".sum')).toHaveText('LW#16#7CE6_6C50_E284_0001');
  // A value that does not fit the type is refused with the reason, the variable unchanged.
  await modify(page, '"Data".big', '9223372036854775808');
  await expect(page.getByRole('alert').filter({ hasText: 'MON606' })).toContainText('does not fit type LINT');
  await expect(value('"Data".sum')).toHaveText('LW#16#7CE6_6C50_E284_0001');
  await row(page, '"Data".lt').scrollIntoViewIfNeeded();
  await page.screenshot({ path: testInfo.outputPath('en-watch-64bit.png') });

  await chooseLanguage(page, 'fa');
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await expect(value('"Data".lt')).toHaveText('LT#1D_2H_3M_4S_5MS_6US_7NS');
  await expect(value('"Data".y')).toHaveText('0.2');
  await row(page, '"Data".lt').scrollIntoViewIfNeeded();
  await page.screenshot({ path: testInfo.outputPath('fa-watch-64bit.png') });
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
