/**
 * Editor help against the real server and the "tank-level" example: completion of symbols and
 * DB members from the project outline, hover help for STL instructions in the interface language
 * (Persian, right to left), and Format Document for SCL.
 */
import type { Locator, Page } from '@playwright/test';
import { test, expect, chooseLanguage, tree, expandProject, newStartSource, openFile } from './fixtures';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

const suggestions = (page: Page) => page.locator('.editor-widget.suggest-widget.visible');

/** The text of the model in the editor in front. */
function textOf(page: Page): Promise<string> {
  return page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    return monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null)?.getModel()?.getValue() ?? '';
  });
}

/** Puts the caret at the end of the line holding `text`. */
async function caretAfter(page: Page, editor: Locator, text: string): Promise<void> {
  await page.evaluate((wanted) => {
    const monaco = (window as WithMonaco).monaco;
    const shown = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const index = shown?.getModel()?.getLinesContent().findIndex((line) => line.includes(wanted)) ?? -1;
    if (index >= 0) shown?.revealLineInCenter(index + 1);
  }, text);
  await editor.locator('.view-line', { hasText: text }).first().click();
  await page.keyboard.press('End');
}

test('completion offers the project symbols and the members of a DB', async ({ page, request, watch }) => {
  await page.goto('/');
  const projectId = await expandProject(page, 'tank-level');
  const original = (await (await request.get(`/api/projects/${projectId}/files/LevelControl.scl`)).json()).text as string;
  const editor = await openFile(page, projectId, 'LevelControl.scl');

  await caretAfter(page, editor, 'Pump := Filling AND NOT Alarm;');
  await page.keyboard.press('Escape');
  await page.keyboard.press('Enter');
  // A symbol: the opening quote, a few letters, Ctrl+Space, Enter.
  await page.keyboard.type('Alarm := "High', { delay: 20 });
  await page.keyboard.press('Control+Space');
  const symbol = suggestions(page).locator('.monaco-list-row', { hasText: '"High level alarm"' });
  await expect(symbol).toBeVisible();
  await expect(symbol).toContainText('Q 4.1');
  await page.keyboard.press('Enter');
  await expect.poll(() => textOf(page)).toContain('\n  Alarm := "High level alarm"\n');

  // A DB member: the dot after the DB's name opens the list by itself.
  await page.keyboard.press('End');
  await page.keyboard.type(' OR Level > "TankSettings".', { delay: 20 });
  const members = suggestions(page).locator('.monaco-list-row');
  await expect(members.filter({ hasText: 'AlarmLevel' })).toBeVisible();
  await expect(members.filter({ hasText: 'LowLevel' })).toBeVisible();
  await page.keyboard.type('Ala', { delay: 20 });
  await page.keyboard.press('Enter');
  await expect.poll(() => textOf(page)).toContain('\n  Alarm := "High level alarm" OR Level > "TankSettings".AlarmLevel\n');

  // Back to the example's text, for the other tests.
  await page.evaluate((text) => {
    const monaco = (window as WithMonaco).monaco;
    monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null)?.getModel()?.setValue(text);
  }, original);
  await expect
    .poll(async () => (await (await request.get(`/api/projects/${projectId}/files/LevelControl.scl`)).json()).text as string, {
      timeout: 10_000,
    })
    .toBe(original);
  expect(watch.consoleErrors).toEqual([]);
});

test('hover help explains an STL instruction in Persian, right to left', async ({ page, watch }) => {
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  const projectId = await expandProject(page, 'tank-level');
  const editor = await openFile(page, projectId, 'OB1.awl');
  const mnemonic = editor.locator('.view-line', { hasText: 'CALL "Scale"' }).locator('span > span', { hasText: /^CALL$/ }).first();
  await mnemonic.hover();
  const hover = page.locator('.monaco-hover:not(.hidden)');
  const text = hover.locator('div[align="right"]', { hasText: 'فرا می‌خواند' });
  await expect(text).toBeVisible({ timeout: 10_000 });
  await expect(text).toHaveCSS('direction', 'rtl');
  // The syntax stays code, left to right; the status bits are named in Persian.
  const syntax = hover.locator('.rendered-markdown', { hasText: 'CALL <FC | FB, instance DB>' }).first();
  await expect(syntax).toBeVisible();
  await expect(syntax).toHaveCSS('direction', 'ltr');
  await expect(hover).toContainText('بیت‌های وضعیتِ تغییرکننده: هیچ');
  expect(watch.consoleErrors).toEqual([]);
});

test('Format Document indents an SCL text', async ({ page, watch }) => {
  await page.goto('/');
  const editor = await newStartSource(page, 'scl');
  const messy = 'FUNCTION FC 5 : INT\nVAR_INPUT\nx : INT;\n      END_VAR\n BEGIN\nIF x > 0 THEN\nFC 5 := x; // positive\n      ELSE\nFC 5 := 0;\n END_IF;\n    END_FUNCTION\n';
  await page.evaluate((text) => {
    const monaco = (window as WithMonaco).monaco;
    monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null)?.getModel()?.setValue(text);
  }, messy);
  await editor.locator('.view-lines').click();
  // Monaco's key for Format Document: Ctrl+Shift+I on Linux (where these tests run), Shift+Alt+F elsewhere.
  await page.keyboard.press(process.platform === 'linux' ? 'Control+Shift+I' : 'Shift+Alt+F');
  await expect
    .poll(() => textOf(page))
    .toBe(
      'FUNCTION FC 5 : INT\nVAR_INPUT\n  x : INT;\nEND_VAR\nBEGIN\n  IF x > 0 THEN\n    FC 5 := x; // positive\n  ELSE\n    FC 5 := 0;\n  END_IF;\nEND_FUNCTION\n',
    );
  expect(watch.consoleErrors).toEqual([]);
});
