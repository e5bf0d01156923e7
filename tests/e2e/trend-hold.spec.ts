/**
 * The trend as a logic analyser and the values at a hold, against the real server with the
 * tank example (I0.0 "Auto", Q4.0 "Pump", IW64 "Level sensor", MD10 "Level" REAL): BOOLs in
 * lanes of their own, the word and the REAL against their own axes, a plot resized by keyboard
 * and mouse; at an SCL breakpoint the editor's inline values are the Locals panel's values.
 */
import type { Page, TestInfo } from '@playwright/test';
import { test, expect, chooseLanguage, expandProject, openFile } from './fixtures';

// A download starts a worker process: on a busy machine the first one takes a while.
test.setTimeout(180_000);
// Room for the trend panel to show its lanes and axes.
test.use({ viewport: { width: 1440, height: 900 } });

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

async function download(page: Page): Promise<void> {
  await page.getByTestId('cpu-download').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 40_000 });
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
}

async function openTankExample(page: Page, language: 'en' | 'fa', file: string) {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online', { timeout: 20_000 });
  if (language !== 'en') await chooseLanguage(page, language);
  const projectId = await expandProject(page, 'tank-level');
  return openFile(page, projectId, file);
}

async function trendFlow(page: Page, language: 'en' | 'fa', testInfo: TestInfo): Promise<void> {
  await openTankExample(page, language, 'OB1.awl');
  await download(page);
  await page.getByTestId('panel-tab-trend').click();
  for (const entry of ['"Auto"', '"Pump"', '"Level sensor"', '"Level"']) {
    await page.getByTestId('trend-add-entry').fill(entry);
    await page.getByTestId('trend-add').click();
  }
  await expect(page.getByTestId('trend-entry')).toHaveCount(4);
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  // Auto on and off again: the pump follows (the tank is empty), two pulses in two lanes.
  await page.getByTestId('panel-tab-io').click();
  for (let k = 0; k < 2; k += 1) {
    await page.getByTestId('io-I0.0').click();
    await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', k === 0 ? 'on' : 'off');
    await page.waitForTimeout(400);
  }
  await page.getByTestId('panel-tab-trend').click();

  const plot = page.getByTestId('trend-plot');
  await expect(plot).toHaveAttribute('data-lanes', '"Auto"\n"Pump"');
  await expect(plot).toHaveAttribute('data-axes', 'int real');
  await expect(plot.locator('canvas')).toHaveCount(1);
  await expect.poll(async () => Number(await plot.getAttribute('data-samples'))).toBeGreaterThan(50);
  // The chips give the last values as the watch table writes them.
  await expect(page.getByTestId('trend-entry').filter({ hasText: '"Pump"' })).toContainText('FALSE');
  await expect(page.getByTestId('trend-entry').filter({ hasText: '"Level"' })).toContainText(/\b0\b/);

  // The plot's height: it fills the panel; the handle makes it taller (keys) and lower (drag).
  const handle = page.getByTestId('trend-resize');
  await expect(handle).toHaveAttribute('role', 'separator');
  const fitted = Number(await plot.getAttribute('data-height'));
  // Fitted to the panel, but never lower than two lanes and the axes need (the panel scrolls).
  expect(fitted).toBeGreaterThanOrEqual(60 + 2 * 30 + 90);
  await handle.focus();
  for (let k = 0; k < 3; k += 1) await page.keyboard.press('ArrowDown');
  await expect(handle).toHaveAttribute('aria-valuenow', String(fitted + 60));
  await expect(plot).toHaveAttribute('data-height', String(fitted + 60));
  expect(Math.round((await plot.boundingBox())!.height)).toBe(fitted + 60);
  await handle.scrollIntoViewIfNeeded();
  const box = (await handle.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2 - 50, { steps: 5 });
  await page.mouse.up();
  await expect(plot).toHaveAttribute('data-height', String(fitted + 10));
  await handle.focus();
  await page.keyboard.press('Home');
  await expect(plot).toHaveAttribute('data-height', String(fitted));

  // The tooltip: every entry's value at the cursor.
  const over = plot.locator('.u-over');
  await over.scrollIntoViewIfNeeded();
  const area = (await over.boundingBox())!;
  await page.mouse.move(area.x + area.width * 0.6, area.y + area.height * 0.3);
  const tip = page.getByTestId('trend-tooltip');
  await expect(tip).toBeVisible();
  await expect(tip).toContainText('"Pump"');
  await expect(tip).toContainText(/"Auto"\s*(TRUE|FALSE)/);
  await expect(tip).toContainText(/"Level"\s*0\b/);

  // The plot stays left to right on a right-to-left page.
  await expect(page.locator('.trend-chart')).toHaveAttribute('dir', 'ltr');
  await plot.scrollIntoViewIfNeeded();
  await page.screenshot({ path: testInfo.outputPath(`trend-${language}.png`) });
  await page.getByTestId('cpu-stop').click();
}

test('the trend: BOOL lanes, one axis per unit, a resizable plot', async ({ page, watch }, testInfo) => {
  await trendFlow(page, 'en', testInfo);
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('the trend in Persian: the page right to left, the plot left to right', async ({ page, watch }, testInfo) => {
  await trendFlow(page, 'fa', testInfo);
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  expect(watch.consoleErrors).toEqual([]);
});

/** The SCL inline values of the editor in front, by line: `{name: text}`. */
function inlineValues(page: Page): Promise<Record<number, Record<string, string>>> {
  return page.evaluate(() => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const out: Record<number, Record<string, string>> = {};
    for (const decoration of editor?.getModel()?.getAllDecorations() ?? []) {
      const after = decoration.options.after;
      if (after?.inlineClassName !== 'scl-inline-value') continue;
      const values: Record<string, string> = {};
      for (const pair of after.content.trim().split(/\s{2,}/)) {
        const [name, value] = pair.split(' = ');
        if (name && value !== undefined) values[name] = value;
      }
      out[decoration.range.startLineNumber] = values;
    }
    return out;
  });
}

async function caretTo(page: Page, text: string): Promise<number> {
  return page.evaluate((wanted) => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const line = (editor?.getModel()?.getLinesContent().findIndex((content) => content.includes(wanted)) ?? -1) + 1;
    editor?.setPosition({ lineNumber: line, column: 1 });
    editor?.revealLineInCenter(line);
    editor?.focus();
    return line;
  }, text);
}

async function localsOf(page: Page): Promise<Record<string, string>> {
  const rows = page.getByTestId('debug-panel').locator('[data-testid^="debug-local-"]:not([data-testid="debug-local-value"])');
  const out: Record<string, string> = {};
  for (const row of await rows.all()) {
    const name = (await row.getAttribute('data-testid'))!.replace('debug-local-', '');
    out[name] = (await row.getByTestId('debug-local-value').innerText()).trim();
  }
  return out;
}

test('at an SCL breakpoint the inline values are the Locals panel’s values', async ({ page, watch }) => {
  const editor = await openTankExample(page, 'en', 'LevelControl.scl');
  await download(page);
  const toggle = page.locator('.source-view:not([hidden])').getByTestId('monitor-toggle');
  await toggle.click();
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  // Auto is off: the scans leave Filling FALSE.
  const pumpLine = await caretTo(page, 'Pump := Filling AND NOT Alarm;');
  await expect.poll(async () => (await inlineValues(page))[pumpLine]?.Filling).toBe('FALSE');

  // A breakpoint on the last statement; at the hold switch Auto on and continue: the next scan
  // starts filling (Filling TRUE, one more start) and holds at the same line.
  await page.keyboard.press('F9');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(1);
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });
  const panel = page.getByTestId('debug-panel');
  await expect(panel.getByTestId('debug-local-Filling').getByTestId('debug-local-value')).toHaveText('FALSE');
  await page.getByTestId('panel-tab-io').click();
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('io-I0.0')).toHaveAttribute('aria-checked', 'true');
  await page.getByTestId('cpu-continue').click();
  await expect(panel.getByTestId('debug-local-Filling').getByTestId('debug-local-value')).toHaveText('TRUE', { timeout: 10_000 });
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold');

  // The state at the hold, not the previous scan's: every inline value equals its local.
  const locals = await localsOf(page);
  expect(locals.Filling).toBe('TRUE');
  await expect.poll(async () => (await inlineValues(page))[pumpLine]?.Filling).toBe('TRUE');
  const shown = await inlineValues(page);
  const compared: string[] = [];
  for (const [line, values] of Object.entries(shown)) {
    for (const [name, value] of Object.entries(values)) {
      expect(`${line}: ${name} = ${value}`).toBe(`${line}: ${name} = ${locals[name]}`);
      compared.push(name);
    }
  }
  expect(compared).toEqual(expect.arrayContaining(['Filling', 'Starts', 'Level', 'Enable']));
  // The inline value of the held line is on screen, after the line.
  await expect(editor.locator('.scl-inline-value').filter({ hasText: 'Filling = TRUE' }).first()).toBeVisible();

  await caretTo(page, 'Pump := Filling AND NOT Alarm;');
  await page.keyboard.press('F9');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(0);
  await page.getByTestId('cpu-continue').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await page.getByTestId('cpu-stop').click();
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
