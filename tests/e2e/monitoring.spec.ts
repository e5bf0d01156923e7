/**
 * Online monitoring against the real server: the example project "motor-start-stop" (OB1 with a
 * self-holding contactor; I0.0 start, I0.1 stop NC, I0.2 overload NC, Q4.0 motor) downloaded into
 * a simulated CPU, switched from the I/O panel, watched, forced and plotted.
 */
import type { Page } from '@playwright/test';
import { test, expect } from './fixtures';

async function openTab(page: Page, id: 'io' | 'watch' | 'trend' | 'diagnostics'): Promise<void> {
  await page.getByTestId(`panel-tab-${id}`).click();
}

async function downloadMotorExample(page: Page): Promise<void> {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  await page.getByRole('treeitem', { name: /^motor-start-stop/ }).first().click();
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  // Ctrl+B downloads, as in STEP 7.
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
}

test('download the motor example, switch its inputs, watch, force and plot', async ({ page, watch }) => {
  await downloadMotorExample(page);
  await expect(page.getByTestId('cpu-status')).toHaveAttribute('data-mode', 'stop');

  // The I/O panel: the bytes the program uses, IB0 as switches and QB4 as lamps.
  await openTab(page, 'io');
  const panel = page.getByTestId('io-panel');
  await expect(panel.getByRole('group', { name: 'QB4' })).toBeVisible();
  await expect(panel.getByRole('switch', { name: 'I0.1 Stop' })).toBeVisible();
  // Stop and overload are wired normally closed: healthy means 1.
  for (const bit of ['I0.1', 'I0.2']) {
    await page.getByTestId(`io-${bit}`).click();
    await expect(page.getByTestId(`io-${bit}`)).toHaveAttribute('aria-checked', 'true');
  }

  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect(page.getByTestId('cpu-scans')).toBeVisible();
  const motor = page.getByTestId('io-Q4.0');
  await expect(motor).toHaveAttribute('data-state', 'off');

  // A start pulse: the motor starts and holds itself after start is released.
  await page.getByTestId('io-I0.0').click();
  await expect(motor).toHaveAttribute('data-state', 'on');
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('io-I0.0')).toHaveAttribute('aria-checked', 'false');
  await expect(motor).toHaveAttribute('data-state', 'on');
  await expect(page.getByTestId('io-Q4.1')).toHaveAttribute('data-state', 'on');

  // The watch table: a symbol and an input, with their values from the frames.
  await openTab(page, 'watch');
  for (const entry of ['"Motor"', 'I0.1', 'MW999999']) {
    await page.getByTestId('watch-add-entry').fill(entry);
    await page.getByTestId('watch-add').click();
  }
  const motorRow = page.locator('[data-testid="watch-row"][data-entry=\'"Motor"\']');
  await expect(motorRow.getByTestId('watch-value')).toHaveText('TRUE');
  await expect(motorRow).toContainText('Q4.0');
  const stopRow = page.locator('[data-testid="watch-row"][data-entry="I0.1"]');
  await expect(stopRow.getByTestId('watch-value')).toHaveText('TRUE');
  await expect(stopRow).toContainText('Stop');
  // An entry that names nothing shows its error instead of a value.
  const badRow = page.locator('[data-testid="watch-row"][data-entry="MW999999"]');
  await expect(badRow.getByTestId('watch-error')).toContainText('MON603');

  // Force the stop input to 0 from the watch table: the force marker appears, the motor stops.
  await stopRow.getByTestId('watch-modify-value').fill('FALSE');
  await stopRow.getByTestId('watch-force').click();
  await expect(stopRow.getByTestId('watch-forced')).toBeVisible();
  await expect(stopRow.getByTestId('watch-value')).toHaveText('FALSE');
  await expect(motorRow.getByTestId('watch-value')).toHaveText('FALSE');

  // The I/O panel shows the same force, and can remove it.
  await openTab(page, 'io');
  await expect(page.getByTestId('io-forced-I0.1')).toBeVisible();
  await expect(page.getByTestId('io-force-I0.1')).toHaveAttribute('aria-pressed', 'true');
  await expect(motor).toHaveAttribute('data-state', 'off');
  await page.getByTestId('io-force-I0.1').click();
  await expect(page.getByTestId('io-forced-I0.1')).toHaveCount(0);
  // And force an input from the panel itself: overload forced to its current value (1).
  await page.getByTestId('io-force-I0.2').click();
  await expect(page.getByTestId('io-forced-I0.2')).toBeVisible();
  await page.getByTestId('io-force-I0.2').click();
  await expect(page.getByTestId('io-forced-I0.2')).toHaveCount(0);

  // The trend: record the motor while it starts again, plotted against the simulated time.
  await openTab(page, 'trend');
  await page.getByTestId('trend-add-entry').fill('"Motor"');
  await page.getByTestId('trend-add').click();
  await openTab(page, 'io');
  await page.getByTestId('io-I0.0').click();
  await expect(motor).toHaveAttribute('data-state', 'on');
  await page.getByTestId('io-I0.0').click();
  await openTab(page, 'trend');
  const plot = page.getByTestId('trend-plot');
  await expect(plot.locator('canvas')).toBeVisible();
  await expect.poll(async () => Number(await plot.getAttribute('data-samples'))).toBeGreaterThan(5);
  const csv = await page.getByTestId('trend-export').getAttribute('href');
  expect(csv).toMatch(/^\/api\/sessions\/[^/]+\/trend\.csv\?client=\d+$/);
  const response = await page.request.get(csv!);
  expect(response.ok()).toBe(true);
  const lines = (await response.text()).trim().split('\n');
  expect(lines[0]).toMatch(/^scan,time_ms,/);
  expect(lines.length).toBeGreaterThan(5);

  // STOP from the toolbar.
  await page.getByTestId('cpu-stop').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop');

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.failedRequests).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('single scan steps, the time mode and a download into the running session', async ({ page, watch }) => {
  await downloadMotorExample(page);
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  // One scan at a time: the CPU pauses after it; Continue resumes.
  await page.getByTestId('cpu-step').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'pause');
  const scans = Number(await page.getByTestId('cpu-scans').locator('bdi').textContent());
  await page.getByTestId('cpu-step').click();
  await expect.poll(async () => Number(await page.getByTestId('cpu-scans').locator('bdi').textContent())).toBe(scans + 1);
  await page.getByTestId('cpu-continue').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  await page.getByTestId('cpu-time-mode').selectOption('fast');
  await expect(page.getByTestId('cpu-time-mode')).toHaveValue('fast');
  await page.getByTestId('cpu-cycle-ms').fill('20');
  await page.getByTestId('cpu-cycle-ms').press('Enter');
  await expect(page.getByTestId('cpu-cycle-ms')).toHaveValue('20');
  await page.getByTestId('cpu-time-mode').selectOption('virtual');
  await expect(page.getByTestId('cpu-time-mode')).toHaveValue('virtual');

  // A download into the running session: the CPU is stopped, loaded and warm-restarted.
  const before = Number(await page.getByTestId('cpu-scans').locator('bdi').textContent());
  await page.getByTestId('cpu-download').click();
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect.poll(async () => Number(await page.getByTestId('cpu-scans').locator('bdi').textContent())).toBeLessThan(before);
  await expect(page.getByTestId('cpu-problem')).toHaveCount(0);
  // In STOP, a download leaves the CPU in STOP; a warm restart starts it.
  await page.getByTestId('cpu-stop').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop');
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop');
  await page.getByTestId('cpu-restart').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
