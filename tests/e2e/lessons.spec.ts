/**
 * The lesson pane against the real server and the real lessons (examples/lessons): in the
 * Persian interface a Persian lesson is opened, its solution built in the LAD editor as a user
 * builds it, "Check" passes; one rung broken again, "Check" fails and its failing rung opens
 * from the results; the progress survives a reload. The served JavaScript and CSS hold no line
 * of any lesson's reference solution. Screenshots of a lesson in English and Persian.
 */
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage } from './fixtures';

const root = path.resolve(__dirname, '../..');
const lessons = path.join(root, 'examples', 'lessons');
const screenshots = path.join(root, 'docs', 'screenshots');

/** The lesson built here: network 4 of its OB1 needs a BR status contact after OS (seed 002, E-fa-12). */
const LESSON = 'fa2-06';

const ladEditor = (page: Page) => page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');

async function waitSaved(page: Page, name = 'OB1.lad'): Promise<void> {
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: name });
  await expect(tab).toHaveAttribute('data-save-state', 'saved', { timeout: 10_000 });
}

/** Opens a lesson from the course outline and waits for its project's first file in the LAD editor. */
async function openLesson(page: Page, id: string): Promise<void> {
  const pane = page.getByTestId('lesson-pane');
  if ((await pane.getByTestId('lesson-view').count()) > 0) await pane.getByTestId('lesson-back').click();
  await pane.getByTestId(`lesson-open-${id}`).click({ timeout: 30_000 });
  await expect(pane.getByTestId('lesson-view')).toHaveAttribute('data-lesson', id);
  await expect(ladEditor(page)).toBeVisible({ timeout: 20_000 });
}

async function check(page: Page): Promise<string> {
  const pane = page.getByTestId('lesson-pane');
  await pane.getByTestId('lesson-check').click();
  const results = pane.getByTestId('lesson-results');
  await expect(pane.getByTestId('lesson-check')).toBeEnabled({ timeout: 30_000 });
  await expect(results).toBeVisible();
  return (await results.getAttribute('data-status')) ?? '';
}

test('a Persian lesson in the Persian UI: built in LAD, checked, broken, pointed at, and remembered', async ({ page, watch }) => {
  test.setTimeout(120_000);
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  await chooseLanguage(page, 'fa');
  const pane = page.getByTestId('lesson-pane');
  await expect(pane.getByTestId('course-unit-fa2')).toHaveAttribute('open', '', { timeout: 30_000 });
  await openLesson(page, LESSON);

  // The text is Persian, right to left, with its code and addresses left to right.
  const text = pane.getByTestId('lesson-text');
  await expect(text).toHaveAttribute('dir', 'rtl');
  await expect(text).toHaveAttribute('lang', 'fa');
  const address = text.locator('code').first();
  await expect(address).toHaveAttribute('dir', 'ltr');

  // The start program fails: an unfinished program never passes.
  expect(await check(page)).toBe('failed');

  // Build the solution as a user does: select OS in network 4, insert a BR status contact after it.
  const editor = ladEditor(page);
  await editor.getByTestId('lad-1-4-e1').click();
  await editor.getByTestId('lad-catalogue-search').fill('BR');
  await editor.getByTestId('catalogue-status:BR').click();
  await expect(editor.getByTestId('network-1-4').locator('[data-kind="status"]')).toHaveCount(2);
  // "Check" right away: the pane saves the editor's change first.
  expect(await check(page)).toBe('passed');
  await expect(pane.getByTestId('lesson-verdict')).toBeVisible();
  await waitSaved(page);

  // Break the rung again (delete the BR contact): the check fails and points at network 4.
  const br = editor.getByTestId('network-1-4').locator('[data-kind="status"]').nth(1);
  await br.click();
  await page.keyboard.press('Delete');
  await expect(editor.getByTestId('network-1-4').locator('[data-kind="status"]')).toHaveCount(1);
  expect(await check(page)).toBe('failed');
  const failure = pane.getByTestId('lesson-failure').filter({ hasText: /Q ?2\.1/ }).first();
  await expect(failure).toBeVisible();
  const where = failure.getByTestId('lesson-where');
  await expect(where).toContainText('NW 4');
  // Something else selected first, so the click has to move the selection to the failing rung.
  await editor.getByTestId('lad-1-1-e1').click();
  await where.click();
  const focused = editor.locator(':focus');
  await expect(focused).toHaveAttribute('id', /^lad-1-4-/);
  await expect(focused).toBeInViewport();

  // A reload comes back to the lesson, with the progress the server kept.
  await page.reload();
  await expect(pane.getByTestId('lesson-view')).toHaveAttribute('data-lesson', LESSON, { timeout: 15_000 });
  const progress = pane.getByTestId('lesson-view').getByTestId('lesson-progress').first();
  await expect(progress).toHaveAttribute('data-status', 'passed');
  await pane.getByTestId('lesson-back').click();
  const row = pane.getByTestId(`lesson-open-${LESSON}`).locator('xpath=..');
  await expect(row.getByTestId('lesson-progress')).toHaveAttribute('data-status', 'passed');
  // Attempts up to the pass: the start program and the solution (a pass is kept; later checks change nothing).
  await expect(row.getByTestId('lesson-progress')).toHaveAttribute('data-attempts', '2');

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

/** Every line of the files under `dir` (recursively), trimmed. */
function linesUnder(dir: string, into: Set<string>): Set<string> {
  if (!existsSync(dir)) return into;
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const where = path.join(dir, entry.name);
    if (entry.isDirectory()) linesUnder(where, into);
    else for (const line of readFileSync(where, 'utf8').split('\n')) into.add(line.trim());
  }
  return into;
}

/**
 * What would give a reference solution away if a served file held it: each solution line of its
 * own (in no lesson's start/ or wrong/ files and in no example project) that is long enough to
 * be unmistakable (30 characters: comments, whole statements), and every two consecutive lines
 * of a solution of which one is its own (as a bundle would hold them: a newline or `\n`). Short
 * lines alone (`T MW 20`) are in any STL program.
 */
function solutionProbes(): Map<string, string> {
  const out = new Map<string, string>();
  if (!existsSync(lessons)) return out;
  const folders = readdirSync(lessons, { withFileTypes: true })
    .filter((entry) => entry.isDirectory())
    .flatMap((unit) =>
      readdirSync(path.join(lessons, unit.name), { withFileTypes: true })
        .filter((entry) => entry.isDirectory())
        .map((lesson) => ({ id: `${unit.name}/${lesson.name}`, folder: path.join(lessons, unit.name, lesson.name) })),
    );
  const common = new Set<string>();
  for (const { folder } of folders) for (const given of ['start', 'wrong']) linesUnder(path.join(folder, given), common);
  linesUnder(path.join(root, 'examples', 'projects'), common);
  for (const { id, folder } of folders) {
    const dir = path.join(folder, 'solution');
    if (!existsSync(dir)) continue;
    for (const file of readdirSync(dir)) {
      const where = `${id}/solution/${file}`;
      const raw = readFileSync(path.join(dir, file), 'utf8').split('\n').filter((line) => line.trim() !== '');
      const own = raw.map((line) => !common.has(line.trim()) && !/^[A-Z_]+$/.test(line.trim()));
      raw.forEach((line, k) => {
        if (own[k] && line.trim().length >= 30) out.set(line.trim(), where);
        const next = raw[k + 1];
        if (next !== undefined && (own[k] || own[k + 1])) {
          out.set(`${line}\n${next}`, where);
          out.set(JSON.stringify(`${line}\n${next}`).slice(1, -1), where);
        }
      });
    }
  }
  return out;
}

test('the course outline is accessible, and the served scripts and styles hold no part of any reference solution', async ({ page, request }) => {
  const lines = solutionProbes();
  expect(lines.size).toBeGreaterThan(20);
  // The rung this lesson's learner builds is among them.
  expect(lines.get('  Status(OS)\n  Status(BR)')).toBe(`fa2/${LESSON}/solution/OB1.lad`);
  // The probes find a solution as a bundle would hold it: as text, or as a string literal.
  const solution = readFileSync(path.join(lessons, 'fa2', LESSON, 'solution', 'OB1.lad'), 'utf8');
  for (const held of [solution, JSON.stringify(solution)]) expect([...lines.keys()].some((probe) => held.includes(probe))).toBe(true);
  await page.goto('/');
  await expect(page.getByTestId('lesson-pane').getByTestId('course-outline')).toBeVisible({ timeout: 30_000 });
  // The course outline itself is accessible too.
  const axe = await new AxeBuilder({ page }).include('[data-testid="lesson-pane"]').withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
  expect(axe.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
  // Every script and style the page loaded (and the ones they load later: the whole assets folder is listed in index.html's graph).
  const assets = await page.evaluate(() =>
    performance
      .getEntriesByType('resource')
      .map((entry) => entry.name)
      .filter((url) => /\.(js|mjs|css)(\?|$)/.test(url)),
  );
  const html = await (await request.get('/')).text();
  for (const match of html.matchAll(/(?:src|href)="([^"]+\.(?:js|css))"/g)) assets.push(new URL(match[1]!, page.url()).toString());
  const unique = [...new Set(assets)];
  expect(unique.length).toBeGreaterThan(1);
  const found: string[] = [];
  for (const url of unique) {
    const body = await (await request.get(url)).text();
    for (const [line, where] of lines) if (body.includes(line)) found.push(`${where}: "${line}" in ${url}`);
  }
  expect(found).toEqual([]);
});

for (const language of ['en', 'fa'] as const) {
  test(`a lesson checked in ${language === 'en' ? 'English' : 'Persian'}: accessible, and its screenshot`, async ({ page, watch }) => {
    test.setTimeout(90_000);
    await page.setViewportSize({ width: 1440, height: 900 });
    await page.goto('/');
    await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
    if (language !== 'en') await chooseLanguage(page, language);
    await openLesson(page, LESSON);
    await expect(page.getByTestId('lesson-text')).toHaveAttribute('lang', language);
    await check(page);
    await expect(page.getByTestId('lesson-verdict')).toBeInViewport();
    const axe = await new AxeBuilder({ page }).include('[data-testid="lesson-pane"]').withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
    expect(axe.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
    await page.evaluate(() => document.fonts.ready);
    await page.screenshot({ path: path.join(screenshots, `${language}-lesson.png`), animations: 'disabled' });
    expect(watch.consoleErrors).toEqual([]);
  });
}
