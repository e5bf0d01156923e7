/**
 * The online state belongs to the project, not to the browser tab: the motor example runs with
 * a forced input and a breakpoint; a reload attaches the page to the same CPU (still holding at
 * the breakpoint, the force marker and the breakpoint's red dot shown, the breakpoint holding
 * again after a continue), and another browser opening the project attaches too, its editor
 * showing the breakpoint the session holds and the trend the session recorded (then looked at
 * in Persian).
 */
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage, expandProject, openFile, visibleEditor, lineOf, caretTo } from './fixtures';

/** How many samples the trend's plot holds. */
const samples = async (page: Page) => Number(await page.getByTestId('trend-plot').getAttribute('data-samples'));

const scans = async (page: Page) => Number((await page.getByTestId('cpu-scans').textContent())?.replace(/\D/g, ''));

/** What a page attached to the held motor CPU shows: HOLD, the force, the breakpoint and the held line. */
async function expectAttached(page: Page, projectId: number): Promise<void> {
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });
  await page.getByTestId('panel-tab-io').click();
  await expect(page.getByTestId('io-forced-I0.2')).toBeVisible();
  await expect(page.getByTestId('io-force-I0.2')).toHaveAttribute('aria-pressed', 'true');
  const editor = await openFile(page, projectId, 'OB1.awl');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(1);
  await expect(editor.locator('.nasaq-hold-line')).toHaveCount(1);
}

test('a reload and another browser attach to the running CPU with its force and breakpoint', async ({ page, browser, watch }, testInfo) => {
  test.setTimeout(180_000); // two pages, a reload and a second browser on a shared machine
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const projectId = await expandProject(page, 'motor-start-stop');
  const editor = await openFile(page, projectId, 'OB1.awl');
  await page.getByTestId('cpu-download').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 30_000 });

  // Stop and overload are NC contacts (1 when healthy); start the motor, force the overload.
  await page.getByTestId('panel-tab-io').click();
  for (const bit of ['I0.1', 'I0.2']) await page.getByTestId(`io-${bit}`).click();
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', 'on');
  await page.getByTestId('io-force-I0.2').click();
  await expect(page.getByTestId('io-forced-I0.2')).toBeVisible();

  // The trend records the motor while it runs: the server keeps its history for the project.
  await page.getByTestId('panel-tab-trend').click();
  await page.getByTestId('trend-add-entry').fill('"Motor"');
  await page.getByTestId('trend-add').click();
  await expect.poll(() => samples(page)).toBeGreaterThan(3);

  // A breakpoint on `= "Motor"`: the CPU holds there.
  const assign = await lineOf(page, '=     "Motor"');
  expect(assign).toBeGreaterThan(0);
  await caretTo(page, assign);
  await page.keyboard.press('F9');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(1);
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });

  // Reload: the page comes back attached to the same session, nothing clicked.
  const before = (await (await page.request.get(`/api/sessions?project_id=${projectId}`)).json()) as Array<{ id: string }>;
  expect(before).toHaveLength(1);
  await page.reload();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });
  await expandProject(page, 'motor-start-stop');
  await expectAttached(page, projectId);
  const after = (await (await page.request.get(`/api/sessions?project_id=${projectId}`)).json()) as Array<{ id: string; clients: number[] }>;
  expect(after.map((session) => session.id)).toEqual([before[0]!.id]);
  expect(after[0]!.clients).toHaveLength(1); // the old page's socket is gone, the new one attached
  // The trend shows the history recorded before the reload.
  await page.getByTestId('panel-tab-trend').click();
  await expect.poll(() => samples(page)).toBeGreaterThan(3);
  await page.screenshot({ path: testInfo.outputPath('reattached-en.png') });

  // The breakpoint still holds: continue, and the CPU holds there again one scan later.
  const held = await scans(page);
  await page.getByTestId('cpu-continue').click();
  await expect.poll(() => scans(page)).toBeGreaterThan(held);
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold');

  // Another browser (no storage shared) opening the project attaches too, in Persian.
  const other = await browser.newContext();
  try {
    const second = await other.newPage();
    await second.goto('/');
    await expandProject(second, 'motor-start-stop');
    await expectAttached(second, projectId);
    // With nothing stored in this browser, the trend takes the entries the session records.
    await second.getByTestId('panel-tab-trend').click();
    await expect.poll(() => samples(second)).toBeGreaterThan(3);
    await chooseLanguage(second, 'fa');
    await expect(second.locator('html')).toHaveAttribute('dir', 'rtl');
    await expect(second.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold');
    await second.getByTestId('panel-tab-io').click();
    await expect(second.getByTestId('io-forced-I0.2')).toBeVisible();
    await expect(visibleEditor(second).locator('.nasaq-bp')).toHaveCount(1);
    await second.screenshot({ path: testInfo.outputPath('reattached-fa.png') });
    const both = (await (await page.request.get(`/api/sessions?project_id=${projectId}`)).json()) as Array<{ clients: number[] }>;
    expect(both[0]!.clients).toHaveLength(2);
  } finally {
    await other.close();
  }
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
