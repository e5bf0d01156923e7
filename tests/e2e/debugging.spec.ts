/**
 * Monitoring and debugging inside the code editor, against the real server: the STL status
 * columns of the motor example follow its inputs; a breakpoint in the SCL function "Scale" of the
 * tank example holds the CPU, the held line is highlighted, the debug panel shows the locals,
 * a step and a continue move on.
 */
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage, visibleEditor, tree, expandProject, openFile, lineOf, caretTo } from './fixtures';

async function download(page: Page): Promise<void> {
  await page.getByTestId('cpu-download').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
}

test('the STL status columns follow the inputs of the motor example', async ({ page, watch }) => {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const projectId = await expandProject(page, 'motor-start-stop');
  const editor = await openFile(page, projectId, 'OB1.awl');
  await download(page);

  await page.getByTestId('panel-tab-io').click();
  for (const bit of ['I0.1', 'I0.2']) await page.getByTestId(`io-${bit}`).click();
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  const toggle = page.locator('.source-view:not([hidden])').getByTestId('monitor-toggle');
  await expect(toggle).toHaveAttribute('aria-pressed', 'false');
  await toggle.click();
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
  const pane = editor.getByTestId('stl-status');
  await expect(pane).toBeVisible();
  await expect(editor.getByTestId('stl-status-bar')).toContainText('OB1');
  await expect(pane.getByTestId('stl-status-head-rlo')).toHaveText('RLO');

  // The row of `= "Motor"`: RLO 0 while the motor is off, 1 once start was pressed.
  const assign = await lineOf(page, '=     "Motor"');
  expect(assign).toBeGreaterThan(0);
  // Only the lines in view have rows.
  await caretTo(page, assign);
  const rlo = pane.locator(`.stl-status__row[data-line="${assign}"] [data-column="rlo"]`);
  await expect(rlo).toHaveText('0');
  await expect(pane.locator(`.stl-status__row[data-line="${assign}"] [data-column="stw"]`)).toHaveText(/^[01]{9}$/);
  await page.getByTestId('io-I0.0').click();
  await expect(page.getByTestId('io-Q4.0')).toHaveAttribute('data-state', 'on');
  await expect(rlo).toHaveText('1');
  // A comment line did not run: no row.
  const comment = await lineOf(page, '// Stop wins');
  await caretTo(page, comment);
  await expect(pane.locator(`.stl-status__row[data-line="${comment}"]`)).toHaveCount(0);

  // ACCU values in hexadecimal on request.
  await caretTo(page, assign);
  await editor.getByTestId('stl-status-format').click();
  await expect(pane.locator(`.stl-status__row[data-line="${assign}"] [data-column="accu1"]`)).toHaveText(/^16#[0-9A-F]{4}_[0-9A-F]{4}$/);
  await editor.getByTestId('stl-status-format').click();

  // Monitoring off: the pane goes.
  await toggle.click();
  await expect(toggle).toHaveAttribute('aria-pressed', 'false');
  await expect(pane).toHaveCount(0);

  await page.getByTestId('cpu-stop').click();
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

async function breakpointFlow(page: Page, persian: boolean): Promise<void> {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  if (persian) await chooseLanguage(page, 'fa');
  const projectId = await expandProject(page, 'tank-level');
  const editor = await openFile(page, projectId, 'Scale.scl');
  const statement = await lineOf(page, 'Scale := Low');
  expect(statement).toBeGreaterThan(0);

  // F9 sets a breakpoint at the caret's line: a red dot in the glyph margin.
  await caretTo(page, statement);
  await page.keyboard.press('F9');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(1);

  await download(page);
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });

  // The held line is highlighted, the panel shows the call stack and the local Raw.
  await expect(editor.locator('.nasaq-hold-line')).toHaveCount(1);
  const panel = page.getByTestId('debug-panel');
  await expect(panel).toHaveAttribute('data-holding', 'true');
  await expect(page.getByTestId('panel-tab-debug')).toHaveAttribute('aria-selected', 'true');
  await expect(panel.getByTestId('debug-frame-0')).toContainText('FC');
  await expect(panel.getByTestId('debug-frame-1')).toContainText('OB1');
  await expect(panel.getByTestId('debug-local-Raw').getByTestId('debug-local-value')).toHaveText(/^-?\d+$/);
  await expect(panel.getByTestId('debug-register-ACCU1')).toContainText('16#');

  await expect(panel).toHaveAttribute('data-reason', 'breakpoint');

  // F9 again removes the breakpoint. A step by statement goes to the function's end (on the
  // same line), the next one returns to the caller: OB1.awl opens with the held line.
  await caretTo(page, statement);
  await page.keyboard.press('F9');
  await expect(editor.locator('.nasaq-bp')).toHaveCount(0);
  await page.getByTestId('cpu-step-by').selectOption('statement');
  await page.getByTestId('cpu-step').click();
  await expect(panel).toHaveAttribute('data-reason', 'step');
  await expect(panel.getByTestId('debug-frame-0')).toContainText('FC10');
  await page.getByTestId('cpu-step').click();
  await expect(panel.getByTestId('debug-frame-0')).toContainText('OB1');
  await expect(page.locator('[data-testid^="editor-tab-source-"][aria-current="true"]')).toContainText('OB1.awl');
  await expect(visibleEditor(page).locator('.nasaq-hold-line')).toHaveCount(1);
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold');

  await page.getByTestId('cpu-continue').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect(panel).toHaveAttribute('data-holding', 'false');
  await page.getByTestId('cpu-stop').click();
}

test('a breakpoint in an SCL function holds the CPU; step, inspect a local, continue', async ({ page, watch }) => {
  await breakpointFlow(page, false);
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('the same in Persian, and a breakpoint on a line without code offers the next line', async ({ page, watch }) => {
  await breakpointFlow(page, true);
  // A condition on the comment line above the header: MON604 in Persian, with the move offer.
  const editor = visibleEditor(page);
  await download(page);
  const comment = await lineOf(page, 'Low and High are');
  await caretTo(page, comment);
  await page.evaluate(() => {
    const ed = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    void ed?.getAction('nasaq.editBreakpointCondition')?.run();
  });
  const dialog = page.getByTestId('breakpoint-dialog');
  await expect(dialog).toBeVisible();
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await dialog.getByTestId('breakpoint-save').click();
  await expect(dialog.getByTestId('breakpoint-error')).toContainText('MON604');
  await dialog.getByTestId('breakpoint-move').click();
  await expect(dialog).toBeHidden();
  await expect(editor.locator('.nasaq-bp')).toHaveCount(1);
  expect(watch.consoleErrors).toEqual([]);
});

/**
 * A 500-network OB1 and a 5,000-line SCL source of 50 functions that OB1 calls. (One 5,000-line
 * function would do as well here, but the CPU compiles such a block for about a minute at its
 * first call: see the report of this change.)
 */
function bigProgram(): { stl: string; scl: string } {
  const networks = Array.from({ length: 500 }, (_, k) => {
    const byte = k % 100;
    return [
      'NETWORK',
      `TITLE = Network ${k + 1}`,
      `      A     M ${byte}.0;`,
      `      AN    M ${byte}.1;`,
      `      =     M ${(byte + 1) % 100}.2;`,
      `      L     MW ${200 + (k % 50) * 2};`,
      `      L     ${k};`,
      '      +I    ;',
      `      T     MW ${200 + (k % 50) * 2};`,
    ].join('\n');
  });
  const calls = Array.from({ length: 50 }, (_, k) => `      CALL FC ${21 + k};`);
  const stl = ['ORGANIZATION_BLOCK OB 1', 'BEGIN', ...networks, 'NETWORK', ...calls, 'END_ORGANIZATION_BLOCK', ''].join('\n');
  const functions = Array.from({ length: 50 }, (_, f) => {
    const body = Array.from({ length: 92 }, (_, k) => (k % 2 === 0 ? `  x := x + ${(k + f) % 7};` : `  y := x > ${k % 50};`));
    return [`FUNCTION FC ${21 + f} : VOID`, 'VAR_TEMP', '  x : INT;', '  y : BOOL;', 'END_VAR', 'BEGIN', '  x := 0;', ...body, 'END_FUNCTION'].join('\n');
  });
  const scl = `${functions.join('\n')}\n`;
  return { stl, scl };
}

/** Scrolls the editor in front from top to bottom in steps, inside the page (no test driver work). */
async function scrollThrough(page: Page): Promise<void> {
  await page.evaluate(async () => {
    const editor = (window as WithMonaco).monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null)!;
    const height = editor.getScrollHeight();
    for (let top = 0; top <= height; top += 1500) {
      editor.setScrollTop(top);
      await new Promise((resolve) => setTimeout(resolve, 30));
    }
  });
}

/*
 * How long the main thread's tasks get while these files scroll under monitoring is measured by
 * `make bench` (tests/e2e/bench/editor-perf.bench.ts), not here: a timing depends on the machine.
 */
test('a 500-network STL block and a 5,000-line SCL source monitor only their visible lines', async ({ page, request, watch }) => {
  test.setTimeout(120_000);
  const created = await request.post('/api/projects', { data: { name: `big-${Date.now()}` } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  const { stl, scl } = bigProgram();
  expect(scl.split('\n').length).toBeGreaterThan(5000);
  for (const [name, text] of [['OB1.awl', stl], ['Big.scl', scl]] as const) {
    expect((await request.put(`/api/projects/${id}/files/${name}`, { data: { text } })).ok()).toBe(true);
  }
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  await page.getByTestId(`project-node-${id}`).click();
  const sclEditor = await openFile(page, id, 'Big.scl');
  const editor = await openFile(page, id, 'OB1.awl');
  const tab = (name: string) => page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: name });
  await download(page);
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run', { timeout: 15_000 });

  // STL: monitoring on while the frames of 3,500 instructions come in, scrolled from top to bottom.
  await tab('OB1.awl').click();
  await page.locator('.source-view:not([hidden])').getByTestId('monitor-toggle').click();
  const body = editor.getByTestId('stl-status-body');
  await expect(body).toHaveAttribute('data-rows', /^[1-9]\d*$/, { timeout: 10_000 });
  await scrollThrough(page);
  // Only the visible lines have rows, however long the block.
  expect(Number(await body.getAttribute('data-rows'))).toBeLessThan(60);
  expect(await body.locator('.stl-status__row').count()).toBeLessThan(60);

  // SCL: the 5,000-line source monitored (the block of the first visible line) and scrolled through.
  await tab('Big.scl').click();
  await page.locator('.source-view:not([hidden])').getByTestId('monitor-toggle').click();
  await expect(sclEditor.locator('.scl-inline-value').first()).toContainText('x =', { timeout: 10_000 });
  await scrollThrough(page);
  await expect(sclEditor.locator('.scl-inline-value').first()).toBeVisible();
  expect(await sclEditor.locator('.scl-inline-value').count()).toBeLessThan(60);

  await page.getByTestId('cpu-stop').click();
  expect(watch.consoleErrors).toEqual([]);
});
