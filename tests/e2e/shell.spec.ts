/**
 * The IDE shell as a user meets it: the main controls, the four languages with right-to-left
 * layout for Arabic and Persian, and no console error or outside request along the way.
 */
import fs from 'node:fs';
import path from 'node:path';
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage } from './fixtures';

type Catalogue = Record<string, unknown>;
const locales = path.resolve(__dirname, '../../frontend/src/i18n/locales');
const catalogue = (code: string): Catalogue =>
  JSON.parse(fs.readFileSync(path.join(locales, `${code}.json`), 'utf8')) as Catalogue;
const text = (cat: Catalogue, key: string): string =>
  key.split('.').reduce<unknown>((node, part) => (node as Catalogue)[part], cat) as string;

const MAIN_CONTROLS = [
  'block-tree',
  'editor-area',
  'cpu-run',
  'cpu-stop',
  'cpu-step',
  'lang-switch',
] as const;

async function openBottomTab(page: Page, name: RegExp | string): Promise<void> {
  await page.getByRole('tab', { name }).click();
}

test('the shell shows every main control with a name', async ({ page, watch }) => {
  await page.goto('/');
  for (const id of MAIN_CONTROLS) await expect(page.getByTestId(id)).toBeVisible();
  await expect(page.getByTestId('diagnostics')).toBeVisible();
  await openBottomTab(page, text(catalogue('en'), 'panels.watch'));
  // Watch tables are files of a project: before one is chosen the tab says where they live.
  const watchTables = path.resolve(__dirname, '../../frontend/src/watchtables/locales/en.json');
  const noProject = text(JSON.parse(fs.readFileSync(watchTables, 'utf8')) as Catalogue, 'watchTables.noProject');
  await expect(page.getByText(noProject)).toBeVisible();
  await expect(page.getByTestId('lesson-pane')).toBeVisible();

  // The simulator is not there yet: the CPU buttons are present, named, and honestly disabled.
  for (const id of ['cpu-run', 'cpu-stop', 'cpu-step']) {
    const button = page.getByTestId(id);
    await expect(button).toBeDisabled();
    await expect(button).toHaveAccessibleName(/\S/);
  }
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('Persian and Arabic turn the page right-to-left, English turns it back', async ({ page, watch }) => {
  await page.goto('/');
  await expect(page.locator('html')).toHaveAttribute('dir', 'ltr');
  const treeLtr = (await page.getByTestId('block-tree').boundingBox())!;
  const editorLtr = (await page.getByTestId('editor-area').boundingBox())!;
  expect(treeLtr.x).toBeLessThan(editorLtr.x);

  for (const code of ['fa', 'ar'] as const) {
    const cat = catalogue(code);
    await chooseLanguage(page, code);
    await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
    await expect(page.getByTestId('cpu-run')).toHaveAccessibleName(text(cat, 'cpu.run.label'));
    await expect(page.getByRole('heading', { name: text(cat, 'projects.title'), exact: true })).toBeVisible();
    await expect(page).toHaveTitle(text(cat, 'app.documentTitle'));
    // The layout mirrors: the project tree moves to the right of the editor...
    const tree = (await page.getByTestId('block-tree').boundingBox())!;
    const editor = (await page.getByTestId('editor-area').boundingBox())!;
    expect(tree.x).toBeGreaterThan(editor.x);
    // ...while the editor area, where code lives, stays left-to-right.
    await expect(page.getByTestId('editor-area')).toHaveAttribute('dir', 'ltr');
    expect(await page.getByTestId('editor-area').evaluate((el) => getComputedStyle(el).direction)).toBe('ltr');
  }

  await chooseLanguage(page, 'en');
  await expect(page.locator('html')).toHaveAttribute('dir', 'ltr');
  await expect(page.getByTestId('cpu-run')).toHaveAccessibleName(text(catalogue('en'), 'cpu.run.label'));
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.failedRequests).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('Vietnamese stays left-to-right with its own labels', async ({ page }) => {
  await page.goto('/');
  await chooseLanguage(page, 'vi');
  await expect(page.locator('html')).toHaveAttribute('dir', 'ltr');
  await expect(page.getByTestId('cpu-run')).toHaveAccessibleName(text(catalogue('vi'), 'cpu.run.label'));
});

test('the chosen language is kept across a reload', async ({ page }) => {
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await page.reload();
  await expect(page.locator('html')).toHaveAttribute('lang', 'fa');
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await expect(page.getByTestId('lang-switch')).toHaveValue('fa');
});

test('Persian text is drawn with the bundled Vazirmatn font, fetched from this server', async ({ page, baseURL }) => {
  const fontRequests: string[] = [];
  page.on('request', (req) => {
    if (req.resourceType() === 'font') fontRequests.push(req.url());
  });
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  const family = await page.getByTestId('block-tree').evaluate((el) => getComputedStyle(el).fontFamily);
  expect(family).toMatch(/Vazirmatn/);
  await page.evaluate(() => document.fonts.ready);
  await expect.poll(() => fontRequests.some((url) => /vazirmatn-arabic/.test(url))).toBe(true);
  expect(fontRequests.every((url) => url.startsWith(baseURL!))).toBe(true);
});

test('the lesson pane sits beside the editor, and stays closed once closed', async ({ page }) => {
  await page.goto('/');
  const pane = (await page.getByTestId('lesson-pane').boundingBox())!;
  const editor = (await page.getByTestId('editor-area').boundingBox())!;
  expect(pane.x).toBeGreaterThanOrEqual(editor.x + editor.width - 1);

  await page.getByTestId('lesson-close').click();
  await expect(page.getByTestId('lesson-pane')).toHaveCount(0);
  const wider = (await page.getByTestId('editor-area').boundingBox())!;
  expect(wider.width).toBeGreaterThan(editor.width);
  await page.reload();
  await expect(page.getByTestId('editor-area')).toBeVisible();
  await expect(page.getByTestId('lesson-pane')).toHaveCount(0);

  await page.getByTestId('lesson-toggle').click();
  await expect(page.getByTestId('lesson-pane')).toBeVisible();
});
