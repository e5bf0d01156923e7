/**
 * A virtual plant in the workbench, as a user meets it: a project with a small STL program
 * (the pump latches on the "Pump on" button, the NC stop button or the full switch stop it) gets
 * the tank attached through "Attach a plant…" (the usual wiring prefilled), is downloaded and
 * run; pressing the panel's button starts the pump, the water rises in the drawing and the low
 * level switch's lamp lights, then the full switch stops the pump. The same plant in Persian:
 * the page is right to left, the drawing and its addresses stay left to right.
 * Screenshots: docs/screenshots/en-plant-tank.png and fa-plant-tank.png.
 */
import path from 'node:path';
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');

const OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Tank filling: latch the pump
BEGIN
NETWORK
TITLE = Pump on until stop or full
      A(    ;
      O     I      0.0;
      O     Q      4.0;
      )     ;
      A     I      0.1;
      AN    I      0.3;
      =     Q      4.0;
END_ORGANIZATION_BLOCK
`;

/** Level shown in the drawing, in %. */
async function levelOf(page: Page): Promise<number> {
  const text = (await page.getByTestId('plant-level-text').textContent()) ?? '';
  return Number(text.replace(/[^\d]/g, ''));
}

test('attach the tank, run the program and watch it fill', async ({ page, request, watch }) => {
  test.setTimeout(180_000);
  const created = await request.post('/api/projects', { data: { name: 'Tank plant', description: '' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  expect((await request.put(`/api/projects/${id}/files/OB1.awl`, { data: { text: OB1 } })).ok()).toBe(true);

  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') {
    await page.getByTestId('lesson-toggle').click();
  }
  const node = page.getByTestId(`project-node-${id}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
  await page.getByTestId(`file-node-${id}-OB1.awl`).dblclick();
  await expect(page.locator('.source-view:not([hidden]) [data-testid="code-editor"]')).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });

  // The Plant tab: no plant yet; attach the tank with its usual wiring.
  await page.getByTestId('panel-tab-plant').click();
  const panel = page.getByTestId('plant-panel');
  await expect(panel).toContainText('This project has no plant');
  await panel.getByRole('button', { name: 'Attach a plant…' }).click();
  const dialog = page.getByRole('dialog', { name: 'Attach a plant' });
  await dialog.getByLabel('Plant', { exact: true }).selectOption('tank');
  await expect(dialog.getByLabel('Address of Pump on')).toHaveValue('I0.0');
  await expect(dialog.getByLabel('Address of Low level')).toHaveValue('I0.2');
  await expect(dialog.getByLabel('Address of Pump', { exact: true })).toHaveValue('Q4.0');
  // A wire to the wrong side is refused at once.
  await dialog.getByLabel('Address of Low level').fill('Q4.7');
  await expect(dialog.getByTestId('attach-wire-error-ls_low')).toBeVisible();
  await expect(dialog.getByRole('button', { name: 'Attach' })).toBeDisabled();
  await dialog.getByLabel('Address of Low level').fill('I0.2');
  await dialog.getByRole('button', { name: 'Attach' }).click();
  await expect(dialog).toBeHidden();
  await expect(page.getByTestId(`file-node-${id}-tank.plant`)).toBeVisible();
  await expect(panel.getByTestId('plant-drawing-tank')).toBeVisible();
  await expect(panel.getByTestId('plant-still')).toBeVisible();
  await expect(panel.getByTestId('plant-address-ls_low')).toHaveText('I0.2');

  // Download (Ctrl+B) and run: the drawing comes alive.
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 30_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await expect(panel).toHaveAttribute('data-live', '1', { timeout: 15_000 });
  const start = await levelOf(page);
  expect(start).toBeLessThan(20);
  await expect(panel.getByTestId('plant-lamp-ls_low')).toHaveAttribute('data-on', '0');

  // Press "Pump on" (a momentary button: held for a moment, then released): the program latches the pump.
  const pumpOn = panel.getByRole('button', { name: /Pump on/ });
  await pumpOn.hover();
  await page.mouse.down();
  await expect(panel.getByTestId('plant-pump')).toHaveAttribute('data-running', '1', { timeout: 5_000 });
  await page.mouse.up();
  await expect(pumpOn).toHaveAttribute('aria-pressed', 'false');
  // The water rises in the drawing and the low level switch's lamp lights (at 20 %).
  await expect(panel.getByTestId('plant-lamp-ls_low')).toHaveAttribute('data-on', '1', { timeout: 20_000 });
  expect(await levelOf(page)).toBeGreaterThanOrEqual(20);
  await page.screenshot({ path: path.join(root, 'docs', 'screenshots', 'en-plant-tank.png'), animations: 'disabled' });

  // The full switch (90 %) stops the pump: the level stays below the top, no overflow.
  await expect(panel.getByTestId('plant-lamp-ls_high')).toHaveAttribute('data-on', '1', { timeout: 40_000 });
  await expect(panel.getByTestId('plant-pump')).toHaveAttribute('data-running', '0', { timeout: 5_000 });
  const full = await levelOf(page);
  expect(full).toBeGreaterThanOrEqual(89);
  expect(full).toBeLessThan(100);
  await expect(panel.getByTestId('plant-fault-overflow')).toHaveCount(0);

  // Persian: the page mirrors, the drawing keeps its left-to-right layout and its addresses.
  await chooseLanguage(page, 'fa');
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await expect(page.getByTestId('panel-tab-plant')).toHaveText('فرایند');
  await expect(panel.getByRole('button', { name: /توقف/ })).toBeVisible();
  await expect(panel.locator('figure.plant-drawing')).toHaveAttribute('dir', 'ltr');
  await expect(panel.getByTestId('plant-address-ls_high')).toHaveText('I0.3');
  // A fault injected from the panel shows in red, in Persian.
  await panel.getByTestId('plant-faults-button').click();
  await panel.getByTestId('plant-inject-level_wire_break').check();
  await expect(panel.getByTestId('plant-fault-level_wire_break')).toContainText('ترانسمیتر');
  await page.keyboard.press('Escape');
  await page.screenshot({ path: path.join(root, 'docs', 'screenshots', 'fa-plant-tank.png'), animations: 'disabled' });

  // The plant panel (drawing, operator panel, fault) meets WCAG A/AA in the right-to-left page.
  const axe = await new AxeBuilder({ page }).include('[data-testid="plant-panel"]').withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
  expect(axe.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
