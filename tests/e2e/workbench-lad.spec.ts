/**
 * A LAD source in the workbench, against the real server: created from the tree's menu, edited
 * in its text view with its own highlighting, its problems as markers on their lines, autosaved,
 * and the rung run in the simulated CPU from the I/O panel. (The graphical editor of the same
 * file is tested in lad-editor.spec.ts.)
 */
import type { Page } from '@playwright/test';
import { test, expect, tree, visibleEditor } from './fixtures';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

// Without indentation: Monaco indents each pasted line like the one above it.
const LATCH = `ORGANIZATION_BLOCK OB 1
TITLE = Motor latch in LAD
BEGIN
NETWORK
TITLE = Start sets, stop breaks the holding path
RUNG
PARALLEL
BRANCH Contact(I 0.0) END_BRANCH
BRANCH Contact(Q 4.0) END_BRANCH
END_PARALLEL
ContactNC(I 0.1)
Coil(Q 4.0)
END_RUNG
END_ORGANIZATION_BLOCK
`;

/** The editor in front: its language and markers. */
function editorState(page: Page): Promise<{ language: string; markers: Array<{ code: string; line: number }> }> {
  return page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const editor = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
    const model = editor?.getModel();
    if (!model) return { language: '', markers: [] };
    const markers = monaco.editor.getModelMarkers({ resource: model.uri, owner: 'nasaq' }).map((m) => ({
      code: typeof m.code === 'string' ? m.code : (m.code?.value ?? ''),
      line: m.startLineNumber,
    }));
    return { language: model.getLanguageId(), markers };
  });
}

test('a LAD source is created from the tree, checked while typing, autosaved and run', async ({ page, request, watch }) => {
  const name = `Ladder ${Date.now()}`;
  const created = await request.post('/api/projects', { data: { name } });
  expect(created.status()).toBe(201);
  const projectId = (await created.json()).id as number;

  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const projectRow = tree(page).getByTestId(`project-node-${projectId}`);
  await projectRow.click();
  await projectRow.focus();
  await page.keyboard.press('Shift+F10');
  await page.getByTestId('tree-menu').getByRole('menuitem', { name: 'New LAD/FBD source…' }).click();
  const dialog = page.getByTestId('file-new-dialog');
  await expect(dialog.getByTestId('file-name-input')).toHaveValue('Source1.lad');
  await dialog.getByTestId('file-name-submit').click();
  await expect(dialog).toBeHidden();

  // The new source compiles (an FC without networks); its text view has the LAD text language.
  await expect(tree(page).getByTestId(`block-node-${projectId}-FC1`)).toContainText('LAD');
  await expect(page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]')).toBeVisible({ timeout: 15_000 });
  await page.getByTestId('view-text').click();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect.poll(() => editorState(page)).toEqual({ language: 'lad', markers: [] });
  await expect(editor.locator('.view-line', { hasText: 'FUNCTION FC 1' })).toBeVisible();

  // Replace the text with a rung (pasted), then break it: the marker sits on its line.
  await editor.locator('.view-line').first().click();
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(LATCH.replace('Coil(Q 4.0)', 'Coil(Q 4.0'));
  await expect.poll(() => editorState(page)).toEqual({ language: 'lad', markers: [{ code: 'LAD111', line: 13 }] });
  await expect(editor.locator('.squiggly-error')).toHaveCount(1);
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(LATCH);
  await expect.poll(() => editorState(page)).toEqual({ language: 'lad', markers: [] });
  // The rung's words have their token colours: elements are instructions, I 0.0 an address.
  await expect(editor.locator('.view-line span', { hasText: /^ContactNC$/ })).toHaveCount(1);
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Source1.lad' });
  await expect(tab).toHaveAttribute('data-save-state', 'saved', { timeout: 10_000 });
  await expect
    .poll(async () => (await (await request.get(`/api/projects/${projectId}/files/Source1.lad`)).json()).text as string)
    .toBe(LATCH);
  await expect(tree(page).getByTestId(`block-node-${projectId}-OB1`)).toContainText('LAD');

  // Download (Ctrl+B), RUN, and switch the inputs the rung reads from the I/O panel.
  await page.keyboard.press('Escape');
  await projectRow.click();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('panel-tab-io').click();
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  const motor = page.getByTestId('io-Q4.0');
  await expect(motor).toHaveAttribute('data-state', 'off');
  await page.getByTestId('io-I0.0').click();
  await expect(motor).toHaveAttribute('data-state', 'on');
  await page.getByTestId('io-I0.0').click();
  await expect(motor).toHaveAttribute('data-state', 'on'); // it holds itself
  await page.getByTestId('io-I0.1').click(); // stop (a normally closed contact in the rung)
  await expect(motor).toHaveAttribute('data-state', 'off');

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
