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

/** A conveyor in LAD with symbols: a latch, an on-delay timer, a counter, a compare and a MOVE. */
const CONVEYOR = `ORGANIZATION_BLOCK OB 1
TITLE = Conveyor
BEGIN
NETWORK
TITLE = Start/stop with a delayed second motor
COMMENT = The second motor follows the first after 2 s.
RUNG
  PARALLEL
    BRANCH Contact("Start") END_BRANCH
    BRANCH Contact("Motor") END_BRANCH
  END_PARALLEL
  ContactNC("Stop")
  OUTPUTS
    BRANCH Coil("Motor") END_BRANCH
    BRANCH Box(S_ODT, INSTANCE T 1, TV := S5T#2S, BI => MW 10) Coil("Motor2") END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = Parts counted on the conveyor
RUNG
  Contact("Part")
  Box(S_CU, INSTANCE C 1, S := "Reset", PV := C#5, CV => MW 20)
  Coil("Full")
END_RUNG
NETWORK
TITLE = Speed set point once three parts passed
RUNG
  Box(CMP>=I, IN1 := MW 20, IN2 := 3)
  Box(MOVE, IN := 100, OUT => MW 30)
END_RUNG
END_ORGANIZATION_BLOCK
`;
const CONVEYOR_SYMBOLS = [
  ['Start', 'I      0.0', 'Start button'],
  ['Stop', 'I      0.1', 'Stop button (normally closed)'],
  ['Part', 'I      0.2', 'Part sensor'],
  ['Reset', 'I      0.3', 'Counter reset'],
  ['Motor', 'Q      4.0', 'Conveyor motor'],
  ['Motor2', 'Q      4.1', 'Second motor'],
  ['Full', 'Q      4.2', 'Five parts counted'],
]
  .map(([name, address, comment]) => `"${name}","${address}","BOOL","${comment}"`)
  .join('\r\n');

for (const language of ['en', 'fa'] as const) {
  test(`screenshots of the LAD and FBD editor online in ${language === 'en' ? 'English' : 'Persian'}`, async ({ page, request, watch }) => {
    test.setTimeout(90_000);
    const created = await request.post('/api/projects', { data: { name: `Conveyor ${language}` } });
    const projectId = (await created.json()).id as number;
    for (const [name, text] of [['Conveyor.lad', CONVEYOR], ['symbols.sdf', `${CONVEYOR_SYMBOLS}\r\n`]] as const) {
      expect((await request.put(`/api/projects/${projectId}/files/${name}`, { data: { text } })).ok()).toBe(true);
    }
    await page.setViewportSize({ width: 1440, height: 900 });
    await page.goto('/');
    await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
    if (language !== 'en') await chooseLanguage(page, language);
    await page.evaluate(() => document.fonts.ready);
    if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') await page.getByTestId('lesson-toggle').click();
    await page.getByTestId(`project-node-${projectId}`).click();
    await page.getByTestId(`file-node-${projectId}-Conveyor.lad`).dblclick();
    const editor = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
    await expect(editor.getByTestId('lad-1-1-e2')).toBeVisible({ timeout: 15_000 });
    await page.keyboard.press('Control+B');
    await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
    await page.getByTestId('cpu-run').click();
    await page.locator('.source-view:not([hidden]) [data-testid="monitor-toggle"]').click();
    await page.getByTestId('panel-tab-io').click();
    // The motor started and held, two parts counted.
    await page.getByTestId('io-I0.0').click();
    await expect(editor.getByTestId('lad-1-1-e5')).toHaveAttribute('data-flow-in', 'on');
    await page.getByTestId('io-I0.0').click();
    for (let part = 0; part < 2; part += 1) {
      await page.getByTestId('io-I0.2').click();
      await expect(editor.getByTestId('lad-1-2-e1')).toHaveAttribute('data-contact', 'on');
      await page.getByTestId('io-I0.2').click();
      await expect(editor.getByTestId('lad-1-2-e1')).toHaveAttribute('data-contact', 'off');
    }
    await editor.getByTestId('lad-1-1-e2').click();
    await page.mouse.move(0, 0);
    await shoot(page, language, 'lad-online');
    await page.getByTestId('view-FBD').click();
    await expect(editor.getByTestId('fbd-1-2-diagram')).toBeVisible({ timeout: 10_000 });
    await page.mouse.move(0, 0);
    await shoot(page, language, 'fbd-online');
    await page.getByTestId('view-LAD').click();
    expect(watch.consoleErrors).toEqual([]);
  });
}
