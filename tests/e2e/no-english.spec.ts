/**
 * No English left for Arabic, Persian and Vietnamese users: Monaco's context menu and find
 * widget, a server error's detail, and the example projects' comments.
 */
import type { Locator, Page } from '@playwright/test';
import { test, expect, chooseLanguage, visibleEditor } from './fixtures';

// Monaco loads once per page, in the page's language: on a busy machine that takes a while.
test.describe.configure({ timeout: 120_000 });

/** Latin-script words in `text` that are not code: key names in a keybinding hint
 * ("(Shift+Enter)"), addresses, codes and file names are code. */
function englishWords(text: string): string[] {
  const withoutKeys = text.replace(/\((?:[A-Za-z0-9]+\+)*[A-Za-z0-9]+\)/g, '');
  const words = withoutKeys.match(/[A-Za-z][A-Za-z0-9_.:#]*/g) ?? [];
  return words.filter((word) => !/^[A-Z0-9_.:#]+$/.test(word) && !/^\w+\.(awl|scl|sdf)(:\d+)*$/.test(word));
}

async function openMotorExample(page: Page): Promise<Locator> {
  const example = page.getByTestId('example-motor-start-stop');
  await example.getByRole('button').click();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 60_000 });
  return editor;
}

/** Right-click in the code: Monaco's context menu, its item labels once shown. */
async function contextMenuLabels(page: Page, editor: Locator): Promise<{ menu: Locator; labels: string[] }> {
  await editor.locator('.view-lines').click({ button: 'right', position: { x: 120, y: 30 } });
  const menu = page.locator('.monaco-menu').first();
  await expect(menu).toBeVisible();
  const labels = (await menu.locator('.action-label').allTextContents()).map((label) => label.trim()).filter(Boolean);
  expect(labels.length).toBeGreaterThan(4);
  return { menu, labels };
}

test('Persian: the motor example, the context menu and the find widget speak Persian', async ({
  page,
  watch,
}, testInfo) => {
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  const examples = page.getByTestId('example-projects');
  await expect(examples.getByTestId('example-motor-start-stop')).toContainText('راه‌اندازی و توقف موتور');
  expect(englishWords(await examples.innerText())).toEqual([]);

  // The example opens as a Persian project: Persian comments, the code and symbols unchanged.
  const editor = await openMotorExample(page);
  await expect(page.getByRole('treeitem', { name: 'راه‌اندازی-و-توقف-موتور', exact: true })).toBeVisible();
  const code = editor.locator('.view-lines');
  await expect(code).toContainText('شستی راه‌اندازی فشرده شده');
  await expect(code).toContainText('"Start"');
  await expect(code).toContainText('"Motor"');
  await expect(editor).toHaveAttribute('dir', 'ltr');
  await page.screenshot({ path: testInfo.outputPath('fa-motor-example.png') });

  // Monaco's context menu: Persian labels on a background of their own.
  const { menu, labels } = await contextMenuLabels(page, editor);
  expect(labels).toContain('برش');
  expect(labels).toContain('فهرست فرمان‌ها');
  for (const label of labels) expect(englishWords(label), label).toEqual([]);
  const background = await menu.evaluate((node) => getComputedStyle(node.closest('.monaco-scrollable-element') ?? node).backgroundColor);
  expect(background).not.toMatch(/rgba\(0, 0, 0, 0\)|transparent/);
  await page.screenshot({ path: testInfo.outputPath('fa-context-menu.png') });
  await page.keyboard.press('Escape');
  await expect(menu).toBeHidden();

  // The find widget: its placeholder, buttons and "no results" in Persian.
  await editor.locator('.view-lines').click();
  await page.keyboard.press('Control+F');
  const find = editor.locator('.find-widget');
  await expect(find).toBeVisible();
  await page.keyboard.type('ژژژ');
  await expect(find.locator('.matchesCount')).toHaveText('نتیجه‌ای نیست');
  await expect(find.locator('textarea').first()).toHaveAttribute('placeholder', 'جستجو');
  const titles = await find.locator('[title], [aria-label]').evaluateAll((nodes) =>
    nodes.map((node) => node.getAttribute('title') ?? node.getAttribute('aria-label') ?? ''),
  );
  expect(titles.length).toBeGreaterThan(4);
  for (const title of titles) expect(englishWords(title), title).toEqual([]);
  await page.keyboard.press('Control+A');
  await page.keyboard.type('Motor');
  await expect(find.locator('.matchesCount')).toHaveText(/^1 از \d+$/);
  await page.screenshot({ path: testInfo.outputPath('fa-find-widget.png') });
  expect(watch.consoleErrors).toEqual([]);
});

test('Persian: a download the server refuses explains itself in Persian', async ({ page, request }, testInfo) => {
  const made = await request.post('/api/projects', { data: { name: `broken ${Date.now()}` } });
  const project = (await made.json()) as { id: number; name: string };
  const source = 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      CALL  FC 77\nEND_ORGANIZATION_BLOCK\n';
  expect((await request.put(`/api/projects/${project.id}/files/OB1.awl`, { data: { text: source } })).ok()).toBe(true);

  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await page.getByRole('treeitem', { name: project.name, exact: true }).click();
  await page.getByTestId('cpu-download').click();
  const problem = page.locator('.cpu-problem__text');
  await expect(problem).toContainText('FC 77');
  const text = await problem.innerText();
  expect(text).toMatch(/[\u0600-\u06FF]/);
  expect(englishWords(text), text).toEqual([]);
  await page.screenshot({ path: testInfo.outputPath('fa-download-refused.png') });
});

test('Vietnamese and Arabic: the context menu in the language, RTL page with LTR code', async ({ page }, testInfo) => {
  await page.goto('/');
  await chooseLanguage(page, 'vi');
  let editor = await openMotorExample(page);
  await expect(editor.locator('.view-lines')).toContainText('nút chạy đang được nhấn');
  const { labels } = await contextMenuLabels(page, editor);
  expect(labels).toEqual(expect.arrayContaining(['Cắt', 'Sao chép', 'Dán', 'Bảng lệnh', 'Định dạng tài liệu']));
  for (const english of ['Cut', 'Copy', 'Paste', 'Command Palette', 'Format Document', 'Change All Occurrences']) {
    expect(labels).not.toContain(english);
  }
  await page.screenshot({ path: testInfo.outputPath('vi-context-menu.png') });
  await page.keyboard.press('Escape');

  // Arabic: Monaco reads its texts when it loads, so a language switch applies at a reload.
  await chooseLanguage(page, 'ar');
  await page.reload();
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  editor = await openMotorExample(page);
  await expect(editor.locator('.view-lines')).toContainText('زر التشغيل مضغوط');
  await expect(editor).toHaveAttribute('dir', 'ltr');
  const arabic = await contextMenuLabels(page, editor);
  expect(arabic.labels).toContain('لصق');
  for (const label of arabic.labels) expect(englishWords(label), label).toEqual([]);
  await page.screenshot({ path: testInfo.outputPath('ar-context-menu.png') });
});
