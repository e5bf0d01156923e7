/**
 * The STL/SCL editor: Monaco, bundled and loaded from the Nasaq server only, with the STL and
 * SCL tokenizers, markers with their catalogue code, and left-to-right text in every language.
 */
import type { Page } from '@playwright/test';
import { test, expect, chooseLanguage, newStartSource, visibleEditor } from './fixtures';

type Monaco = typeof import('monaco-editor/editor/editor.api');
/** Monaco's API, which the app puts on `window.monaco` (MonacoEnvironment.globalAPI). Functions
 * passed to page.evaluate run in the page, so each reads it there with this cast. */
type WithMonaco = Window & { monaco: Monaco };

interface Token {
  text: string;
  className: string;
  color: string;
}

/** The editor of the tab in front. */

/**
 * The rendered tokens of the view line that contains `line`. Monaco draws one span per run of
 * tokens with the same style (class `mtk<colour>`), with non-breaking spaces.
 */
async function tokensOf(page: Page, line: string): Promise<Token[]> {
  // Monaco draws only the lines in view: scroll the line there first.
  await page.evaluate((text) => {
    for (const editor of (window as WithMonaco).monaco.editor.getEditors()) {
      const node = editor.getDomNode();
      if (!node || node.offsetParent === null) continue;
      const index = editor.getModel()?.getLinesContent().findIndex((content) => content.includes(text)) ?? -1;
      if (index >= 0) editor.revealLineInCenter(index + 1);
    }
  }, line);
  const row = visibleEditor(page).locator('.view-lines .view-line', { hasText: line }).first();
  await expect(row).toBeVisible();
  return row.locator('span > span').evaluateAll((spans) =>
    spans.map((span) => ({
      text: (span.textContent ?? '').replace(/\u00a0/g, ' '),
      className: span.className,
      color: getComputedStyle(span).color,
    })),
  );
}

function token(tokens: Token[], text: string): Token {
  const found = tokens.find((t) => t.text.trim() === text);
  if (!found) throw new Error(`no token "${text}" in ${JSON.stringify(tokens.map((t) => t.text))}`);
  return found;
}

async function openNewSource(page: Page, language: 'stl' | 'scl'): Promise<void> {
  const editor = await newStartSource(page, language);
  await expect(editor.locator('.monaco-editor .view-lines')).toBeVisible();
}

test('a new STL source opens in Monaco, highlights what is typed, and shows markers', async ({ page, watch }) => {
  const scripts: string[] = [];
  page.on('request', (req) => {
    if (['script', 'stylesheet', 'font'].includes(req.resourceType())) scripts.push(req.url());
  });
  const workers: string[] = [];
  page.on('worker', (worker) => workers.push(worker.url()));
  const warnings: string[] = [];
  page.on('console', (msg) => {
    if (msg.type() === 'warning') warnings.push(msg.text());
  });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  const beforeEditor = scripts.length;
  await openNewSource(page, 'stl');
  // Monaco came in its own chunk, after the page had loaded, from this server.
  expect(scripts.slice(beforeEditor).some((url) => /\/assets\/setup-[\w-]+\.js$/.test(url))).toBe(true);

  const tab = page.getByTestId('editor-tab-source-1');
  await expect(tab).toContainText('Source1.awl');

  // Type at the end of the example, as a learner would (Escape closes the word suggestions,
  // so Enter starts a new line).
  await visibleEditor(page).locator('.view-lines').click();
  await page.keyboard.press('Control+End');
  for (const line of ['NETWORK', '      U     E 1.0          // Eingang: Quittieren', 'L DB1.DBW 2', 'T #count']) {
    await page.keyboard.press('Escape');
    await page.keyboard.press('Enter');
    await page.keyboard.type(line, { delay: 20 });
  }

  // The editor's worker (word ranges for the suggestions) runs as a worker from this server,
  // not in the page (Monaco's fallback warns when it cannot start one).
  await expect.poll(() => workers).toEqual([expect.stringMatching(/^http:\/\/127\.0\.0\.1:\d+\/assets\/editor\.worker-[\w-]+\.js$/)]);
  expect(warnings.filter((text) => /web worker/i.test(text))).toEqual([]);

  const typed = await tokensOf(page, '// Eingang: Quittieren');
  const mnemonic = token(typed, 'U');
  const address = token(typed, 'E 1.0');
  const comment = token(typed, '// Eingang: Quittieren');
  expect(new Set([mnemonic.className, address.className, comment.className]).size).toBe(3);
  expect(new Set([mnemonic.color, address.color, comment.color]).size).toBe(3);
  for (const t of [mnemonic, address, comment]) expect(t.className).toMatch(/\bmtk\d+\b/);

  const load = await tokensOf(page, 'L DB1.DBW 2');
  expect(token(load, 'L').className).toBe(mnemonic.className);
  expect(token(load, 'DB1.DBW 2').className).toBe(address.className);
  const transfer = await tokensOf(page, 'T #count');
  expect(token(transfer, 'T').className).toBe(mnemonic.className);
  expect(token(transfer, '#count').className).not.toBe(address.className);
  // The block keywords of the example differ from instructions too.
  const header = await tokensOf(page, 'ORGANIZATION_BLOCK OB 1');
  expect(token(header, 'ORGANIZATION_BLOCK').className).not.toBe(mnemonic.className);
  expect(token(header, 'OB 1').className).toBe(address.className);

  // A new source is a file of the project from the start: nothing is waiting to be saved.
  await expect(tab).toHaveAttribute('data-save-state', 'saved');
  const model = await page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const [first] = monaco.editor.getModels();
    return { language: first?.getLanguageId(), text: first?.getValue() ?? '' };
  });
  expect(model.language).toBe('stl');
  expect(model.text).toContain('// Eingang: Quittieren');

  // A marker with its catalogue code, as the compiler's diagnostics will set it.
  await page.evaluate(() => {
    const monaco = (window as WithMonaco).monaco;
    const [first] = monaco.editor.getModels();
    if (!first) throw new Error('no model');
    const lines = first.getLinesContent();
    const index = lines.findIndex((text) => text.includes('#count'));
    const column = (lines[index] ?? '').indexOf('#count') + 1;
    monaco.editor.setModelMarkers(first, 'nasaq', [
      {
        startLineNumber: index + 1,
        startColumn: column,
        endLineNumber: index + 1,
        endColumn: column + '#count'.length,
        severity: monaco.MarkerSeverity.Error,
        code: 'STL204',
        message: 'The local variable #count is not declared.',
      },
    ]);
    monaco.editor.getEditors().find((editor) => editor.getModel() === first)?.revealLineInCenter(index + 1);
  });
  const squiggle = visibleEditor(page).locator('.squiggly-error');
  await expect(squiggle).toHaveCount(1);
  // The squiggle lies under the text: point at the word, as a user would.
  await visibleEditor(page).locator('.view-line span > span', { hasText: '#count' }).last().hover();
  const hover = page.locator('.monaco-hover').filter({ hasText: 'is not declared' });
  await expect(hover).toBeVisible();
  await expect(hover).toContainText('STL204');

  expect(watch.consoleErrors).toEqual([]);
  // The text is a project file: a check or a reload that newer typing made stale is cancelled.
  expect(watch.failedRequests.filter((failed) => !failed.endsWith('net::ERR_ABORTED'))).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('SCL keywords, operators, addresses and comments get their own colours', async ({ page, watch }) => {
  await page.goto('/');
  await openNewSource(page, 'scl');
  await expect(page.getByTestId('editor-tab-source-1')).toContainText('Source1.scl');
  const ifLine = await tokensOf(page, 'IF level < low AND NOT pump THEN');
  const keyword = token(ifLine, 'IF');
  const operator = token(ifLine, 'AND');
  expect(token(ifLine, 'THEN').className).toBe(keyword.className);
  expect(token(ifLine, 'NOT').className).toBe(operator.className);
  // Names and symbolic operators are plain text, in one run.
  const plain = token(ifLine, 'level < low');
  expect(new Set([keyword.color, operator.color, plain.color]).size).toBe(3);
  const store = await tokensOf(page, 'MW20 := INT_TO_WORD(level);');
  const address = token(store, 'MW20');
  const fn = token(store, 'INT_TO_WORD');
  expect(new Set([address.color, fn.color, keyword.color]).size).toBe(3);
  const comment = token(await tokensOf(page, '(* how often the pump started *)'), '(* how often the pump started *)');
  expect(new Set([comment.color, keyword.color, address.color]).size).toBe(3);
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('code stays left-to-right in Persian and Arabic, with the bundled code font', async ({ page, baseURL, watch }) => {
  const fonts: string[] = [];
  page.on('request', (req) => {
    if (req.resourceType() === 'font') fonts.push(req.url());
  });
  await page.goto('/');
  await chooseLanguage(page, 'fa');
  await expect(page.locator('html')).toHaveAttribute('dir', 'rtl');
  await openNewSource(page, 'stl');
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('dir', 'ltr');
  const monaco = editor.locator('.monaco-editor');
  expect(await monaco.evaluate((el) => getComputedStyle(el).direction)).toBe('ltr');
  // Line numbers sit at the left edge, the text to their right.
  const number = (await editor.locator('.line-numbers').first().boundingBox())!;
  const text = (await editor.locator('.view-line').first().boundingBox())!;
  expect(number.x).toBeLessThan(text.x);
  const family = await editor.locator('.view-lines').evaluate((el) => getComputedStyle(el).fontFamily);
  expect(family).toMatch(/JetBrains Mono/);
  await expect.poll(() => fonts.some((url) => /jetbrains-mono-latin/.test(url))).toBe(true);
  expect(fonts.every((url) => url.startsWith(baseURL!))).toBe(true);
  // The editor's name for screen readers is in the interface language.
  await expect(editor.getByRole('textbox')).toHaveAttribute('aria-label', /STL/);

  await chooseLanguage(page, 'ar');
  expect(await monaco.evaluate((el) => getComputedStyle(el).direction)).toBe('ltr');
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('closing a source tab disposes its editor; tabs keep their own text', async ({ page, watch }) => {
  await page.goto('/');
  await openNewSource(page, 'stl');
  await page.getByTestId('editor-tab-start').click();
  await openNewSource(page, 'scl');
  const count = () =>
    page.evaluate(
      () => (window as WithMonaco).monaco.editor.getModels().length,
    );
  expect(await count()).toBe(2);
  await page.getByTestId('editor-tab-source-1').click();
  await expect(page.getByTestId('source-view-source-1')).toBeVisible();
  await expect(page.getByTestId('source-view-source-2')).toBeHidden();
  await page.getByTestId('editor-tab-close-source-1').click();
  await page.getByTestId('editor-tab-close-source-2').click();
  await expect.poll(count).toBe(0);
  await expect(page.locator('.monaco-editor')).toHaveCount(0);
  expect(watch.consoleErrors).toEqual([]);
});
