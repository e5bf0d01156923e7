/** Projects live in the server's database: create one in the tree, reload, it is still there. */
import { test, expect, chooseLanguage } from './fixtures';

test('create a project from the tree and find it again after a reload', async ({ page, watch }) => {
  const name = `Tank filling ${Date.now()}`;
  await page.goto('/');
  await page.getByTestId('project-new').click();
  await page.getByTestId('project-name-input').fill(name);
  await page.getByTestId('project-description-input').fill('Lesson 3: fill and drain');
  await page.getByTestId('project-create-submit').click();
  const tree = page.getByTestId('block-tree');
  await expect(tree.getByText(name)).toBeVisible();

  await page.reload();
  await expect(page.getByTestId('block-tree').getByText(name)).toBeVisible();
  const stored = await page.request.get('/api/projects');
  expect((await stored.json()).map((p: { name: string }) => p.name)).toContain(name);
  expect(watch.consoleErrors).toEqual([]);
});

test('a duplicate name is refused with the catalogue code, in the UI language', async ({ page, request }) => {
  const name = `Conveyor ${Date.now()}`;
  expect((await request.post('/api/projects', { data: { name } })).status()).toBe(201);
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await page.getByTestId('project-new').click();
  await page.getByTestId('project-name-input').fill(name.toUpperCase());
  await page.getByTestId('project-create-submit').click();
  const dialog = page.getByRole('dialog');
  await expect(dialog.getByText('API105')).toBeVisible();
  await expect(dialog.getByText(name.toUpperCase())).toBeVisible();
  // The message comes from the Persian catalogue, not the server's English text.
  await expect(dialog.getByText('already exists')).toHaveCount(0);
});
