/**
 * The I/O panel as PLCSIM's simulated modules, against the real server and the "tank-level"
 * example: the level transmitter's analog input IW64 moved with the keyboard, the mouse and the
 * value field drives the two-point control (pump Q4.0, alarm Q4.1); at 1280×720 (and 1440×900)
 * the output byte QB4 shows all eight bits with their symbols, nothing cut. Screenshots of the
 * panel for the README: docs/screenshots/en-io-1280.png and fa-io.png.
 */
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');
const example = path.join(root, 'examples', 'projects', 'tank-level');
const NAMES = { en: 'Tank level panel', fa: 'سطح مخزن (ورودی و خروجی)' } as const;

/** The tank example as its own project (other tests may change the imported one). */
async function tankProject(request: APIRequestContext, name: string): Promise<number> {
  const created = await request.post('/api/projects', { data: { name, description: 'Two-point level control' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  // The files the example's scenario names (`sources: [...]` of tank.yaml).
  const listed = /^sources:\s*\[(.*)\]/m.exec(readFileSync(path.join(example, 'tank.yaml'), 'utf8'))![1]!;
  for (const file of listed.split(',').map((name) => name.trim())) {
    const saved = await request.put(`/api/projects/${id}/files/${file}`, {
      data: { text: readFileSync(path.join(example, file), 'utf8') },
    });
    expect(saved.ok()).toBe(true);
  }
  return id;
}

/** Opens the project's OB1, downloads it (Ctrl+B) and shows the I/O panel. */
async function downloadTank(page: Page, projectId: number): Promise<Locator> {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
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
  const panel = page.getByTestId('io-panel');
  await expect(panel.getByRole('group', { name: 'QB4' })).toBeVisible();
  return panel;
}

interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** `inner` lies wholly inside `outer` (1 px of rounding allowed). */
function expectInside(inner: Box, outer: Box, what: string): void {
  expect(inner.left, `${what}: left edge`).toBeGreaterThanOrEqual(outer.left - 1);
  expect(inner.top, `${what}: top edge`).toBeGreaterThanOrEqual(outer.top - 1);
  expect(inner.right, `${what}: right edge`).toBeLessThanOrEqual(outer.right + 1);
  expect(inner.bottom, `${what}: bottom edge`).toBeLessThanOrEqual(outer.bottom + 1);
}

/** QB4's card, its eight bits and its symbols: inside the viewport and inside the panel, uncut. */
async function expectQb4Whole(page: Page): Promise<void> {
  await expect(page.getByTestId('io-symbol-Q4.0')).toHaveText('Pump');
  await expect(page.getByTestId('io-symbol-Q4.1')).toHaveText('High level alarm');
  // One look at the page: the boxes of everything that must show, as the browser lays them out.
  const seen = await page.evaluate(() => {
    const box = (el: Element | null) => {
      if (!el) return null;
      const r = el.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    const ids = ['io-byte-QB4', ...[0, 1, 2, 3, 4, 5, 6, 7].map((bit) => `io-bit-Q4.${bit}`), 'io-symbol-Q4.0', 'io-symbol-Q4.1'];
    const symbols = ['io-symbol-Q4.0', 'io-symbol-Q4.1'].map((id) => document.querySelector(`[data-testid="${id}"]`)!);
    return {
      screen: { left: 0, top: 0, right: window.innerWidth, bottom: window.innerHeight },
      panel: box(document.querySelector('.bottom-panel [role="tabpanel"]:not([hidden])')),
      boxes: ids.map((id) => [id, box(document.querySelector(`[data-testid="${id}"]`))] as const),
      // Wrapped, never cut with an ellipsis or hidden overflow.
      cut: symbols.filter((el) => el.scrollWidth > el.clientWidth + 1).map((el) => el.textContent),
    };
  });
  expect(seen.panel).not.toBeNull();
  for (const [id, inner] of seen.boxes) {
    expect(inner, id).not.toBeNull();
    expectInside(inner!, seen.screen, `${id} in the viewport`);
    expectInside(inner!, seen.panel!, `${id} in the panel`);
  }
  expect(seen.cut).toEqual([]);
}

test('the tank level follows the analog slider and the pump and alarm react', async ({ page, request, watch }) => {
  test.setTimeout(300_000);
  const projectId = await tankProject(request, NAMES.en);
  await page.setViewportSize({ width: 1280, height: 720 });
  const panel = await downloadTank(page, projectId);

  // Only the bytes the program uses: IB0 (Auto) and QB4 (pump, alarm); IW64 as an analog input.
  await expect(panel.getByRole('group', { name: 'IB1' })).toHaveCount(0);
  const level = page.getByTestId('io-analog-IW64');
  await expect(level.getByTestId('io-analog-IW64-symbol')).toHaveText('Level sensor');
  await expect(level.getByTestId('io-analog-IW64-scaled')).toContainText('"Scale"');
  await expect(level.getByTestId('io-analog-IW64-scaled')).toContainText('"Level"');
  const slider = level.getByRole('slider', { name: 'IW64 Level sensor: analog value' });
  const field = level.getByRole('textbox', { name: 'IW64 Level sensor: value' });
  const pump = page.getByTestId('io-Q4.0');
  const alarm = page.getByTestId('io-Q4.1');

  await page.getByRole('switch', { name: 'I0.0 Auto' }).click();
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  // An empty tank (0 %): the pump fills.
  await expect(field).toHaveValue('0');
  await expect(pump).toHaveAttribute('data-state', 'on');
  await expect(alarm).toHaveAttribute('data-state', 'off');

  // The keyboard: nine times Page Up is 90 % (10 % of 27648 each), above the high limit of 80 %.
  for (let i = 0; i < 9; i++) await slider.press('PageUp');
  await expect(field).toHaveValue('24885');
  await expect(level.getByTestId('io-analog-IW64-scaled')).toContainText('= 90.01');
  await expect(level.getByTestId('io-analog-IW64-region')).toHaveAttribute('data-region', 'nominal');
  await expect(pump).toHaveAttribute('data-state', 'off');
  await expect(alarm).toHaveAttribute('data-state', 'off');
  // End: the top of the overrange (117.6 %): the high-level alarm.
  await slider.press('End');
  await expect(field).toHaveValue('32511');
  await expect(level.getByTestId('io-analog-IW64-region')).toHaveAttribute('data-region', 'overrange');
  await expect(alarm).toHaveAttribute('data-state', 'on');

  // The mouse: a click at a fifth of the track (about 10 %): below the low limit, the pump starts.
  const track = (await slider.boundingBox())!;
  await page.mouse.click(track.x + track.width * 0.2, track.y + track.height / 2);
  await expect.poll(async () => Number(await field.inputValue())).toBeLessThan(27648 * 0.2);
  await expect(alarm).toHaveAttribute('data-state', 'off');
  await expect(pump).toHaveAttribute('data-state', 'on');

  // The field takes hex: 16#3600 is 13824, 50 %; inside the hysteresis band the pump keeps filling.
  await field.fill('16#3600');
  await field.press('Enter');
  await expect(field).toHaveValue('13824');
  await expect(level.getByTestId('io-analog-IW64-hint')).toContainText('50 %');
  await expect(pump).toHaveAttribute('data-state', 'on');
  // A value that is no word is refused with a message, not dropped.
  await field.fill('40000');
  await field.press('Enter');
  await expect(level.getByRole('alert')).toContainText('“40000” is not a 16-bit value');
  await field.press('Escape');
  await expect(level.getByRole('alert')).toHaveCount(0);
  await expect(field).toHaveValue('13824');

  // Words and bytes in hex.
  await page.getByTestId('io-format').selectOption('hex');
  await expect(field).toHaveValue('W#16#3600');
  await expect(page.getByTestId('io-value-QB4')).toHaveText('B#16#01');

  // QB4 whole at 1280×720 and at 1440×900.
  await page.mouse.move(0, 0);
  await expectQb4Whole(page);
  await page.screenshot({ path: path.join(root, 'docs', 'screenshots', 'en-io-1280.png'), animations: 'disabled' });
  await page.setViewportSize({ width: 1440, height: 900 });
  await expectQb4Whole(page);

  // All bytes on request.
  await page.getByTestId('io-show-all').check();
  await expect(panel.getByRole('group', { name: 'IB3' })).toBeVisible();

  await page.getByTestId('cpu-stop').click();
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('the I/O panel in Persian at 1280×720: QB4 whole, the analog input moves the level', async ({ page, request, watch }) => {
  test.setTimeout(300_000);
  const projectId = await tankProject(request, NAMES.fa);
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await page.evaluate(() => document.fonts.ready);
  await downloadTank(page, projectId);
  await page.getByTestId('io-I0.0').click();
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  for (let i = 0; i < 5; i++) await page.getByTestId('io-analog-IW64-slider').press('PageUp');
  await expect(page.getByTestId('io-analog-IW64-field')).toHaveValue('13825');
  await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', 'on');
  await page.mouse.move(0, 0);
  await expectQb4Whole(page);
  await page.screenshot({ path: path.join(root, 'docs', 'screenshots', 'fa-io.png'), animations: 'disabled' });
  await page.getByTestId('cpu-stop').click();
  expect(watch.consoleErrors).toEqual([]);
});
