/**
 * An S7-Graph source in the workbench, against the real server: the project tree creates one
 * (an FB with a sequencer that compiles), it opens in its chart, and its text view shows it with
 * the Graph keywords coloured, and the tree shows its FB as GRAPH. In English and in Persian (right to left: the
 * source stays left to right).
 */
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage, tree, expandProject, visibleEditor } from './fixtures';

async function createGraph(page: Page, projectId: number, action: string, name: string): Promise<void> {
  await tree(page).getByTestId(`project-node-${projectId}`).focus();
  await page.keyboard.press('Shift+F10');
  const menu = page.getByTestId('tree-menu');
  await menu.getByRole('menuitem', { name: action }).click();
  const dialog = page.getByTestId('file-new-dialog');
  await expect(dialog.getByTestId('file-name-input')).toHaveValue(/^Source\d+\.graph$/);
  await dialog.getByTestId('file-name-input').fill(name);
  await dialog.getByTestId('file-name-submit').click();
  await expect(dialog).toBeHidden();
}

for (const language of ['en', 'fa'] as const) {
  test(`a new S7-Graph source opens in its chart, its text coloured, and its FB is in the tree (${language})`, async ({ page, watch }, info) => {
    await page.goto('/');
    await chooseLanguage(page, language);
    const projectId = await expandProject(page, 'traffic-light');
    const action = language === 'en' ? 'New S7-Graph sequencer…' : 'ترتیب‌دهندهٔ S7-Graph جدید…';
    const name = `Mixer${language}.graph`;
    const graphBlocks = tree(page).locator(`[data-testid^="block-node-${projectId}-FB"]`).filter({ hasText: 'GRAPH' });
    await expect(tree(page).getByTestId(`block-node-${projectId}-OB1`)).toBeVisible(); // the tree is loaded
    const before = await graphBlocks.count();
    await createGraph(page, projectId, action, name);

    await expect(tree(page).getByTestId(`file-node-${projectId}-${name}`)).toBeVisible();
    // It opens in its sequencer chart (issue 19); the text is one view away.
    await expect(page.locator('.source-view:not([hidden]) [data-testid="graph-step-1"]')).toBeVisible({ timeout: 30_000 });
    await page.locator('.source-view:not([hidden])').getByTestId('graph-view-text').click();
    const editor = visibleEditor(page);
    await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 30_000 });
    await expect(editor).toContainText('INITIAL_STEP Step1 (1)');
    const modelLanguage = await page.evaluate(() => {
      const monaco = (window as Window & { monaco: typeof import('monaco-editor/editor/editor.api') }).monaco;
      const shown = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
      return shown?.getModel()?.getLanguageId();
    });
    expect(modelLanguage).toBe('graph');
    // The Graph tokenizer colours the structure: INITIAL_STEP is a keyword, Step1 a label.
    // (The editor was just shown by the view switch: its lines are tokenized a moment later.)
    await expect(editor.locator('.view-line span span').filter({ hasText: /^INITIAL_STEP$/ }).first()).toBeVisible();
    const classes = await editor
      .locator('.view-line span span')
      .evaluateAll((spans) => spans.map((span) => [span.textContent ?? '', span.className] as const));
    const keyword = classes.find(([text]) => text === 'INITIAL_STEP')?.[1];
    const label = classes.find(([text]) => text === 'Step1')?.[1];
    expect(keyword).toBeTruthy();
    expect(label).toBeTruthy();
    expect(keyword).not.toEqual(label);

    // The template compiles (with the first free FB number): its FB joins the tree, in GRAPH.
    await expect(graphBlocks).toHaveCount(before + 1);
    await expect(page.locator('html')).toHaveAttribute('dir', language === 'fa' ? 'rtl' : 'ltr');
    await page.screenshot({ path: info.outputPath(`graph-source-${language}.png`) });
    expect(watch.consoleErrors).toEqual([]);
  });
}
