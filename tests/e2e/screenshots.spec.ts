/**
 * Pictures of the main views for the README, in English and Persian: the start page, the
 * workbench with the motor example downloaded and running (I/O panel), the watch table and the
 * trend. Saved to docs/screenshots/ at 1440×900; the CPU's scan counter and clock are hidden so
 * that two runs give nearly the same pictures.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');
const folder = path.join(root, 'docs', 'screenshots');
const example = path.join(root, 'examples', 'projects', 'motor-start-stop');

/** What changes from one run to the next: the scan count, the simulated time, the cycle time. */
const HIDE_CLOCKS = `
  .cpu-state__details, .stl-status__scan { visibility: hidden !important; }
  .monaco-editor .cursor { visibility: hidden !important; }
`;

const NAMES = { en: 'Motor start-stop', fa: 'موتور استارت و استاپ' } as const;
type Shown = keyof typeof NAMES;

async function shoot(page: Page, language: Shown, view: string): Promise<void> {
  await page.screenshot({ path: path.join(folder, `${language}-${view}.png`), animations: 'disabled', style: HIDE_CLOCKS });
}

/** The motor example as its own project (other tests may change the imported one). */
async function motorProject(request: APIRequestContext, name: string): Promise<number> {
  const created = await request.post('/api/projects', { data: { name, description: 'Self-holding motor circuit' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const file of ['OB1.awl', 'symbols.sdf']) {
    const saved = await request.put(`/api/projects/${id}/files/${file}`, {
      data: { text: readFileSync(path.join(example, file), 'utf8') },
    });
    expect(saved.ok()).toBe(true);
  }
  return id;
}

for (const language of ['en', 'fa'] as const) {
  test(`screenshots of the main views in ${language === 'en' ? 'English' : 'Persian'}`, async ({ page, request, watch }) => {
    test.setTimeout(90_000);
    const projectId = await motorProject(request, NAMES[language]);
    await page.setViewportSize({ width: 1440, height: 900 });
    await page.goto('/');
    await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
    if (language !== 'en') await chooseLanguage(page, language);
    await page.evaluate(() => document.fonts.ready);
    await expect(page.getByTestId('start-page')).toBeVisible();
    await shoot(page, language, 'start');

    // The workbench: the example open in the editor, downloaded, in RUN, the motor started.
    if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') {
      await page.getByTestId('lesson-toggle').click();
    }
    const node = page.getByTestId(`project-node-${projectId}`);
    await node.click();
    await expect(node).toHaveAttribute('aria-expanded', 'true');
    await page.getByTestId(`file-node-${projectId}-OB1.awl`).dblclick();
    const editor = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
    await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
    await page.keyboard.press('Control+B');
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
    await page.getByTestId('panel-tab-io').click();
    for (const bit of ['I0.1', 'I0.2']) await page.getByTestId(`io-${bit}`).click();
    await page.getByTestId('cpu-run').click();
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
    // The trend records from the moment it has an entry: add them before the motor starts.
    await page.getByTestId('panel-tab-trend').click();
    for (const entry of ['"Start"', '"Motor"']) {
      await page.getByTestId('trend-add-entry').fill(entry);
      await page.getByTestId('trend-add').click();
    }
    await page.getByTestId('panel-tab-io').click();
    await page.getByTestId('io-I0.0').click();
    await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', 'on');
    await page.getByTestId('io-I0.0').click();
    await expect(page.getByTestId('io-I0.0')).toHaveAttribute('aria-checked', 'false');
    // Monitoring in the editor where this build has it (the block's status beside the code).
    const monitor = page.locator('.source-view:not([hidden]) [data-testid="monitor-toggle"]');
    if ((await monitor.count()) > 0) {
      await monitor.click();
      await expect(monitor).toHaveAttribute('aria-pressed', 'true');
      await page.waitForTimeout(500);
    }
    await page.mouse.move(0, 0);
    await shoot(page, language, 'workbench');

    await page.getByTestId('panel-tab-watch').click();
    for (const entry of ['"Start"', '"Stop"', '"Motor"', 'QB4']) {
      await page.getByTestId('watch-add-entry').fill(entry);
      await page.getByTestId('watch-add').click();
    }
    await expect(page.locator('[data-testid="watch-row"][data-entry=\'"Motor"\'] [data-testid="watch-value"]')).toHaveText('TRUE');
    await shoot(page, language, 'watch');

    // A stop pulse, so that the trend shows the motor switching off.
    await page.getByTestId('panel-tab-io').click();
    await page.getByTestId('io-I0.1').click();
    await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', 'off');
    await page.getByTestId('io-I0.1').click();
    await page.getByTestId('panel-tab-trend').click();
    const plot = page.getByTestId('trend-plot');
    await expect.poll(async () => Number(await plot.getAttribute('data-samples'))).toBeGreaterThan(20);
    await shoot(page, language, 'watch-trend');

    expect(watch.consoleErrors).toEqual([]);
    expect(watch.foreignRequests).toEqual([]);
  });
}
