/**
 * Keyboard shortcuts against the real server: the shortcuts dialog (F1, the top bar's "?"),
 * compile with Ctrl+F7 (saves, checks, shows the Diagnostics panel and announces the result)
 * and renaming a project from the tree with the server's refusal shown translated.
 */
import type { APIRequestContext, Page } from '@playwright/test';
import { test, expect, chooseLanguage } from './fixtures';

async function makeProject(request: APIRequestContext, name: string, files: Record<string, string>): Promise<number> {
  const created = await request.post('/api/projects', { data: { name, description: '' } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  for (const [file, text] of Object.entries(files)) {
    expect((await request.put(`/api/projects/${id}/files/${file}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

async function expand(page: Page, projectId: number): Promise<void> {
  const node = page.getByTestId(`project-node-${projectId}`);
  await node.click();
  await expect(node).toHaveAttribute('aria-expanded', 'true');
}

test('F1 and the ? button list the shortcuts; Escape closes the list', async ({ page, watch }) => {
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  await page.keyboard.press('F1');
  const dialog = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
  await expect(dialog).toBeVisible();
  await expect(dialog.getByTestId('shortcut-compile')).toContainText('F7');
  await expect(dialog.getByTestId('shortcut-download')).toContainText('B');
  await expect(dialog.getByTestId('shortcut-rename')).toContainText('F2');
  await page.keyboard.press('Escape');
  await expect(dialog).toHaveCount(0);

  await chooseLanguage(page, 'ar');
  await page.getByTestId('shortcuts-button').click();
  const arabic = page.getByRole('dialog', { name: 'اختصارات لوحة المفاتيح' });
  await expect(arabic.getByRole('heading', { name: 'في محرر الشيفرة' })).toBeVisible();
  expect(await arabic.getByTestId('shortcut-format').locator('td').first().getAttribute('dir')).toBe('ltr');
  await page.keyboard.press('Escape');
  await expect(page.getByTestId('shortcuts-button')).toBeFocused();
  expect(watch.consoleErrors).toEqual([]);
});

test('Ctrl+F7 saves the editor, compiles the project and shows its diagnostics', async ({ page, request, watch }) => {
  const ob1 = 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      A     I 0.0;\n      =     Q 4.0;\nEND_ORGANIZATION_BLOCK\n';
  const id = await makeProject(request, 'Compile with Ctrl+F7', { 'OB1.awl': ob1 });
  await page.goto('/');
  await expand(page, id);
  await page.getByTestId(`file-node-${id}-OB1.awl`).dblclick();
  const editor = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await page.getByTestId('panel-tab-watch').click();

  // A typo typed in the editor and compiled at once, before the autosave's second is up.
  await editor.locator('.view-lines').click();
  await page.keyboard.press('Control+End');
  await page.keyboard.type('\nXYZ 1;');
  await page.keyboard.press('Control+F7');
  await expect(page.getByTestId('panel-tab-diagnostics')).toHaveAttribute('aria-selected', 'true');
  const status = page.getByTestId('compile-status');
  await expect(status).toHaveText(/^Compiled — errors: [1-9]\d*, warnings: \d+$/);
  await expect(page.getByTestId('diagnostics').getByTestId('diagnostic').first()).toContainText('OB1.awl');
  // The server compiled the saved text: the typo is in the file.
  const saved = (await (await request.get(`/api/projects/${id}/files/OB1.awl`)).json()) as { text: string };
  expect(saved.text).toContain('XYZ 1;');

  // Fixed and compiled with the toolbar's button: no errors.
  await request.put(`/api/projects/${id}/files/OB1.awl`, { data: { text: ob1 } });
  await page.getByTestId(`file-node-${id}-OB1.awl`).click();
  await page.getByTestId('editor-tab-start').click();
  await page.getByTestId('cpu-compile').click();
  await expect(status).toHaveText('Compiled — errors: 0, warnings: 0');
  expect(watch.foreignRequests).toEqual([]);
});

test('a project is renamed from the tree; a taken name is refused in the interface language', async ({ page, request, watch }) => {
  const id = await makeProject(request, 'Rename me', { 'OB1.awl': 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      NOP 0;\nEND_ORGANIZATION_BLOCK\n' });
  await makeProject(request, 'Taken name', {});
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await expand(page, id);
  await page.getByTestId(`file-node-${id}-OB1.awl`).dblclick();
  await expect(page.locator('.source-view:not([hidden]) [data-testid="code-editor"]')).toHaveAttribute('data-state', 'ready', {
    timeout: 15_000,
  });

  await page.getByTestId(`project-node-${id}`).focus();
  await page.keyboard.press('F2');
  const dialog = page.getByTestId('project-rename-dialog');
  await expect(dialog).toBeVisible();
  await dialog.getByTestId('project-rename-input').fill('taken NAME');
  await dialog.getByTestId('project-rename-input').press('Enter');
  await expect(dialog.getByTestId('project-rename-error')).toContainText('API105');
  await expect(dialog.getByTestId('project-rename-error')).toContainText('پروژه');

  await dialog.getByTestId('project-rename-input').fill('Renamed project');
  await dialog.getByTestId('project-rename-submit').click();
  await expect(dialog).toHaveCount(0);
  await expect(page.getByTestId(`project-node-${id}`)).toContainText('Renamed project');
  const stored = (await (await request.get('/api/projects')).json()) as Array<{ id: number; name: string }>;
  expect(stored.find((p) => p.id === id)?.name).toBe('Renamed project');
  // The open tab still belongs to the project: it saves into it.
  await page.locator('.source-view:not([hidden]) .view-lines').click();
  await page.keyboard.press('Control+End');
  await page.keyboard.type('\n// after the rename');
  await expect
    .poll(async () => ((await (await request.get(`/api/projects/${id}/files/OB1.awl`)).json()) as { text: string }).text)
    .toContain('// after the rename');
  // The one refused request is the browser's own log line of the 409, nothing else.
  expect(watch.consoleErrors).toEqual(['Failed to load resource: the server responded with a status of 409 (Conflict)']);
});
