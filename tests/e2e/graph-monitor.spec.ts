/**
 * The S7-Graph editor online, against the real server: the two-conveyor sequence (Start: belt B,
 * 5 s later belt A; Stop: both off; belt B's start supervised by a jam switch, acknowledgement
 * required) called from OB1, downloaded and run. The active step moves as inputs change on the
 * I/O panel; a jam turns the step red and stops the sequence until it is acknowledged in the
 * Control Sequencer; MAN mode steps on and off by number; a breakpoint on a step's activation
 * holds the CPU. Screenshots of the chart online for the README (docs/screenshots/
 * en-graph-online.png, en-graph-disturbed.png, fa-graph-disturbed.png), the Persian page right
 * to left with the chart left to right.
 */
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import path from 'node:path';
import { test, expect, chooseLanguage, tree } from './fixtures';
import { CONVEYORS, OB1, SYMBOLS } from './graphConveyors';

const folder = path.join(path.resolve(__dirname, '../..'), 'docs', 'screenshots');

/** What changes from one run to the next in a picture: the scan count, the clock, the caret. */
const HIDE_CLOCKS = `
  .cpu-state__details, .stl-status__scan { visibility: hidden !important; }
  .monaco-editor .cursor { visibility: hidden !important; }
`;

async function conveyorProject(request: APIRequestContext, name: string): Promise<number> {
  const created = await request.post('/api/projects', { data: { name, description: 'Two conveyors in S7-Graph' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [file, text] of [['Conveyors.graph', CONVEYORS], ['OB1.awl', OB1], ['symbols.sdf', `${SYMBOLS}\r\n`]] as const) {
    expect((await request.put(`/api/projects/${id}/files/${file}`, { data: { text } })).ok(), file).toBe(true);
  }
  return id;
}

/** The chart of the tab in front. */
const chartOf = (page: Page): Locator => page.locator('.source-view:not([hidden]) [data-testid="graph-chart"]');

/** Opens the sequence in its chart, downloads the project (Ctrl+B), RUN, monitoring on. */
async function runOnline(page: Page, projectId: number, language: 'en' | 'fa'): Promise<Locator> {
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  if (language !== 'en') await chooseLanguage(page, language);
  await page.evaluate(() => document.fonts.ready);
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') await page.getByTestId('lesson-toggle').click();
  const row = tree(page).getByTestId(`project-node-${projectId}`);
  await row.click();
  await expect(row).toHaveAttribute('aria-expanded', 'true');
  await tree(page).getByTestId(`file-node-${projectId}-Conveyors.graph`).dblclick();
  const chart = chartOf(page);
  await expect(chart.getByTestId('graph-step-1')).toBeVisible({ timeout: 15_000 });
  await expect(chart.getByTestId('graph-step-1')).toHaveAttribute('data-initial', 'true');
  await row.click();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  const monitor = page.locator('.source-view:not([hidden]) [data-testid="monitor-toggle"]');
  await monitor.click();
  await expect(monitor).toHaveAttribute('aria-pressed', 'true');
  await page.getByTestId('panel-tab-io').click();
  await expect(chart.getByTestId('graph-step-1')).toHaveAttribute('data-state', 'active', { timeout: 10_000 });
  return chart;
}

/** The seconds of a step's active time as the chart shows them ("3.2 s", "3.2 ثانیه"). */
async function stepSeconds(chart: Locator, step: number): Promise<number> {
  const text = (await chart.getByTestId(`graph-step-time-${step}`).textContent()) ?? '';
  return Number(/\d+(?:\.\d+)?/.exec(text)?.[0] ?? 0);
}

async function shoot(page: Page, name: string): Promise<void> {
  await page.mouse.move(0, 0);
  await page.screenshot({ path: path.join(folder, `${name}.png`), animations: 'disabled', style: HIDE_CLOCKS });
}

test('the sequence online: the active step follows the inputs, a jam stops it until acknowledged, MAN, a step breakpoint', async ({ page, request, watch }) => {
  test.setTimeout(90_000);
  const projectId = await conveyorProject(request, 'Two conveyors (S7-Graph)');
  const chart = await runOnline(page, projectId, 'en');
  const step = (n: number) => chart.getByTestId(`graph-step-${n}`);
  expect(await chart.locator('svg').first().evaluate((svg) => getComputedStyle(svg).direction)).toBe('ltr');
  await expect(page.getByTestId('io-Q0.2')).toHaveAttribute('data-state', 'on'); // N "Ready" while idle
  await expect(step(2)).toHaveAttribute('data-state', 'inactive');

  // Start: belt B at once, the step's time runs (belt A would follow 5 s later, Trans2).
  await page.getByTestId('io-I0.0').click();
  await expect(step(2)).toHaveAttribute('data-state', 'active');
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('io-I0.0')).toHaveAttribute('aria-checked', 'false');
  await expect(step(1)).toHaveAttribute('data-state', 'inactive');
  await expect(page.getByTestId('io-Q0.1')).toHaveAttribute('data-state', 'on');
  await expect(page.getByTestId('io-Q0.2')).toHaveAttribute('data-state', 'off');
  await expect.poll(() => stepSeconds(chart, 2)).toBeGreaterThan(0.5);
  await expect(chart.getByTestId('graph-transition-2')).toHaveAttribute('data-tt', 'false');
  await shoot(page, 'en-graph-online');

  // A jam while belt B starts: the step turns red and the sequence stops there, also once its
  // 5 s are up (Trans2's condition is true), and stays stopped when the jam is cleared, until
  // the error is acknowledged in the Control Sequencer; then it goes on to Step3 (belt A).
  await page.getByTestId('io-I0.3').click();
  await expect(step(2)).toHaveAttribute('data-state', 'disturbed');
  await expect(page.getByTestId('graph-monitor-mode')).toContainText(/ERR_FLT|error/i);
  await page.locator('.source-view:not([hidden]) [data-testid="graph-control"]').click();
  const control = page.getByTestId('graph-control-dialog');
  await expect(control).toBeVisible();
  await expect(control.getByTestId('graph-mode-auto')).toHaveAttribute('aria-pressed', 'true');
  await expect.poll(() => stepSeconds(chart, 2), { timeout: 15_000 }).toBeGreaterThan(5.5);
  await expect(chart.getByTestId('graph-transition-2')).toHaveAttribute('data-tt', 'true');
  await shoot(page, 'en-graph-disturbed');
  await expect(step(3)).toHaveAttribute('data-state', 'inactive');
  await page.getByTestId('io-I0.3').click();
  await expect(page.getByTestId('io-I0.3')).toHaveAttribute('aria-checked', 'false');
  await page.waitForTimeout(300);
  await expect(step(2)).toHaveAttribute('data-state', 'disturbed');
  await expect(step(3)).toHaveAttribute('data-state', 'inactive');
  await control.getByTestId('graph-ack').click();
  await expect(step(3)).toHaveAttribute('data-state', 'active');
  await expect(step(2)).toHaveAttribute('data-state', 'inactive');
  await expect(page.getByTestId('io-Q0.0')).toHaveAttribute('data-state', 'on');

  // MAN: no transition fires; steps on and off by number.
  await control.getByTestId('graph-mode-man').click();
  await expect(control.getByTestId('graph-mode-man')).toHaveAttribute('aria-pressed', 'true');
  await page.getByTestId('io-I0.1').click(); // Stop pressed: Trans3's condition is true ...
  await expect(chart.getByTestId('graph-transition-3')).toHaveAttribute('data-tt', 'true');
  await page.waitForTimeout(200);
  await expect(step(3)).toHaveAttribute('data-state', 'active'); // ... but in MAN nothing switches
  await expect(step(4)).toHaveAttribute('data-state', 'inactive');
  await page.getByTestId('io-I0.1').click();
  await control.getByTestId('graph-step-number').fill('4');
  await control.getByTestId('graph-step-on').click();
  await expect(step(4)).toHaveAttribute('data-state', 'active');
  await expect(page.getByTestId('io-Q0.0')).toHaveAttribute('data-state', 'off'); // R "Belt_A" of step 4
  await control.getByTestId('graph-step-number').fill('3');
  await control.getByTestId('graph-step-off').click();
  await expect(step(3)).toHaveAttribute('data-state', 'inactive');
  await expect(step(4)).toHaveAttribute('data-state', 'active');
  // Back in AUTO the sequence goes on from step 4 (Stop is released): to the initial step.
  await control.getByTestId('graph-mode-auto').click();
  await expect(control.getByTestId('graph-mode-auto')).toHaveAttribute('aria-pressed', 'true');
  await expect(step(1)).toHaveAttribute('data-state', 'active');

  // A breakpoint on step 2's activation: Start holds the CPU before step 2 becomes active.
  await step(2).click();
  await expect(step(2)).toHaveAttribute('aria-selected', 'true');
  await control.getByTestId('graph-break-step').click();
  await expect(control.getByTestId('graph-break-step')).toHaveAttribute('aria-pressed', 'true');
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });
  await expect(control.getByTestId('graph-control-status')).toHaveAttribute('data-held', '2');
  await expect(control.getByTestId('graph-control-held')).toContainText('B_on');
  await expect(step(2)).toHaveAttribute('data-state', 'inactive');
  await page.getByTestId('panel-tab-io').click(); // a hold shows the call stack
  await page.getByTestId('io-I0.0').click();
  await control.getByTestId('graph-break-step').click();
  await expect(control.getByTestId('graph-break-step')).toHaveAttribute('aria-pressed', 'false');
  await control.getByTestId('graph-continue').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect(step(2)).toHaveAttribute('data-state', 'active');

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('Persian: the page right to left, the chart left to right, a disturbed step online', async ({ page, request, watch }) => {
  test.setTimeout(60_000);
  const projectId = await conveyorProject(request, 'دو نوار نقاله (S7-Graph)');
  const chart = await runOnline(page, projectId, 'fa');
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await expect(chart).toHaveAttribute('dir', 'ltr');
  expect(await chart.locator('svg').first().evaluate((svg) => getComputedStyle(svg).direction)).toBe('ltr');
  // The chart is not mirrored: it runs top-down from the initial step, as in English.
  const first = (await chart.getByTestId('graph-step-1').boundingBox())!;
  const second = (await chart.getByTestId('graph-step-2').boundingBox())!;
  expect(second.y).toBeGreaterThan(first.y);
  await page.getByTestId('io-I0.0').click();
  await expect(chart.getByTestId('graph-step-2')).toHaveAttribute('data-state', 'active');
  await page.getByTestId('io-I0.0').click();
  await page.getByTestId('io-I0.3').click();
  await expect(chart.getByTestId('graph-step-2')).toHaveAttribute('data-state', 'disturbed');
  await expect.poll(() => stepSeconds(chart, 2)).toBeGreaterThan(1);
  await page.locator('.source-view:not([hidden]) [data-testid="graph-control"]').click();
  const control = page.getByTestId('graph-control-dialog');
  await expect(control).toBeVisible();
  await expect(control).toHaveAttribute('dir', 'rtl');
  // The dialog leaves the chart's steps visible (the chart stays at the left in both directions).
  const dialogBox = (await control.boundingBox())!;
  const stepBox = (await chart.getByTestId('graph-step-2').boundingBox())!;
  expect(stepBox.x + stepBox.width <= dialogBox.x || stepBox.x >= dialogBox.x + dialogBox.width).toBe(true);
  await shoot(page, 'fa-graph-disturbed');
  expect(watch.consoleErrors).toEqual([]);
});
