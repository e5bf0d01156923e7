/**
 * The graphical LAD/FBD editor against the real server, as a user drives it: a start/stop latch
 * with an on-delay timer built by mouse, a second network by keyboard alone, undo/redo, the saved
 * text, LAD -> FBD -> STL -> LAD, program status in RUN, a network breakpoint, Persian, and
 * accessibility.
 */
import AxeBuilder from '@axe-core/playwright';
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import fs from 'node:fs';
import path from 'node:path';
import { test, expect, chooseLanguage, tree } from './fixtures';

const EMPTY_OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Conveyor
BEGIN
END_ORGANIZATION_BLOCK
`;

/** The whole text the editor is expected to have saved after both networks are built. */
const BUILT = `ORGANIZATION_BLOCK OB 1
TITLE = Conveyor
BEGIN
NETWORK
TITLE = Start/stop with a delayed second motor
RUNG
  PARALLEL
    BRANCH Contact(I 0.0) END_BRANCH
    BRANCH Contact(Q 4.0) END_BRANCH
  END_PARALLEL
  ContactNC(I 0.1)
  OUTPUTS
    BRANCH Coil(Q 4.0) END_BRANCH
    BRANCH Box(S_ODT, INSTANCE T 1, TV := S5T#2S) Coil(Q 4.1) END_BRANCH
  END_OUTPUTS
END_RUNG
NETWORK
TITLE = Lamp
RUNG
  PARALLEL
    BRANCH Contact(I 0.2) END_BRANCH
    BRANCH Contact(I 0.3) END_BRANCH
  END_PARALLEL
  Coil(Q 4.2)
END_RUNG
END_ORGANIZATION_BLOCK
`;

async function newProject(request: APIRequestContext, text = EMPTY_OB1): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: `Ladder ${Date.now()}-${Math.random()}` } });
  expect(created.status()).toBe(201);
  const id = (await created.json()).id as number;
  const saved = await request.put(`/api/projects/${id}/files/Main.lad`, { data: { text } });
  expect(saved.ok()).toBe(true);
  return id;
}

async function openLad(page: Page, projectId: number, name = 'Main.lad'): Promise<Locator> {
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: name });
  if ((await tab.count()) > 0) await tab.click();
  else {
    const row = tree(page).getByTestId(`project-node-${projectId}`);
    if ((await row.getAttribute('aria-expanded')) !== 'true') await row.click();
    await tree(page).getByTestId(`file-node-${projectId}-${name}`).dblclick();
  }
  const editor = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
  await expect(editor).toBeVisible({ timeout: 15_000 });
  return editor;
}

async function savedText(request: APIRequestContext, projectId: number, name = 'Main.lad'): Promise<string> {
  return (await (await request.get(`/api/projects/${projectId}/files/${name}`)).json()).text as string;
}

/** Types into the operand field that opened on an element and takes it. */
async function typeOperand(page: Page, text: string): Promise<void> {
  const input = page.getByTestId('operand-input');
  await expect(input).toBeFocused();
  await input.fill(text);
  await input.press('Enter');
  await expect(input).toBeHidden();
}

async function waitSaved(page: Page): Promise<void> {
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Main.lad' });
  await expect(tab).toHaveAttribute('data-save-state', 'saved', { timeout: 10_000 });
}

test('a latch with an on-delay timer by mouse, a second network by keyboard, undo/redo, reload, the text', async ({ page, request, watch }) => {
  const projectId = await newProject(request);
  await page.goto('/');
  const editor = await openLad(page, projectId);

  // -- network 1 by mouse ---------------------------------------------------------------------
  await editor.getByTestId('lad-insert-network').click();
  await expect(editor.getByTestId('network-1-1')).toBeVisible();
  await editor.getByTestId('network-1-1-header').dblclick();
  const title = editor.getByTestId('network-1-1-title-input');
  await title.fill('Start/stop with a delayed second motor');
  await title.press('Enter');
  await editor.getByTestId('favourite-contact').click();
  await typeOperand(page, 'I 0.0');
  await editor.getByTestId('favourite-contactNC').click();
  await typeOperand(page, 'I 0.1');
  await editor.getByTestId('favourite-coil:=').click();
  await typeOperand(page, 'Q 4.0');
  // The holding contact: a branch under the start button.
  await editor.getByTestId('lad-1-1-e1').click();
  await editor.getByTestId('favourite-openBranch').click();
  await typeOperand(page, 'Q 4.0');
  // A second output under the coil, and the timer dragged onto the wire before its coil.
  await editor.getByTestId('lad-1-1-e5').click();
  await editor.getByTestId('favourite-openBranch').click();
  await typeOperand(page, 'Q 4.1');
  await editor.getByTestId('lad-catalogue-search').fill('S_ODT');
  await editor.getByTestId('catalogue-box:S_ODT').dragTo(editor.getByTestId('lad-1-1-drop-c1-0'));
  await typeOperand(page, 'T 1');
  await editor.getByTestId('lad-1-1-e6-pin-TV').dblclick();
  await typeOperand(page, 'S5T#2S');
  await expect(editor.getByTestId('lad-1-1-e6')).toHaveAttribute('data-kind', 'box');

  // -- network 2 by keyboard alone -----------------------------------------------------------
  await expect(editor.getByTestId('lad-1-1-e6')).toBeFocused();
  await page.keyboard.press('Control+R');
  await expect(editor.getByTestId('network-1-2-header')).toBeFocused();
  await page.keyboard.press('Enter');
  await page.keyboard.type('Lamp');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Shift+F2');
  await typeOperand(page, 'I 0.2');
  await page.keyboard.press('Shift+F7');
  await typeOperand(page, 'Q 4.2');
  await page.keyboard.press('ArrowLeft');
  await expect(editor.getByTestId('lad-1-2-e1')).toBeFocused();
  await page.keyboard.press('Shift+F8');
  await typeOperand(page, 'I 0.3');
  await waitSaved(page);
  await expect.poll(() => savedText(request, projectId)).toBe(BUILT);

  // -- undo and redo ----------------------------------------------------------------------------
  await page.keyboard.press('Control+Z');
  await expect(editor.getByTestId('lad-1-2-e3')).toHaveAttribute('aria-label', /<\?\?\.\?>/);
  await page.keyboard.press('Control+Z');
  await expect(editor.getByTestId('lad-1-2-e1')).toHaveAttribute('data-kind', 'contact');
  await expect(editor.getByTestId('lad-1-2-e3')).toHaveCount(0);
  await page.keyboard.press('Control+Y');
  await page.keyboard.press('Control+Y');
  await waitSaved(page);
  await expect.poll(() => savedText(request, projectId)).toBe(BUILT);

  // -- reload: the same networks ------------------------------------------------------------------
  await page.reload();
  const again = await openLad(page, projectId);
  await expect(again.getByTestId('network-1-2-title')).toHaveText('Lamp');
  await expect(again.getByTestId('lad-1-2-e3')).toHaveAttribute('aria-label', /I 0\.3/);

  // -- the saved text in the text view --------------------------------------------------------------
  await page.getByTestId('view-text').click();
  const text = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
  await expect(text).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(text.locator('.view-line', { hasText: 'Box(S_ODT, INSTANCE T 1, TV := S5T#2S)' })).toBeVisible();
  await page.getByTestId('view-LAD').click();
  await expect(again.getByTestId('lad-1-1-e6')).toBeVisible();

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('LAD -> FBD -> STL -> LAD, then program status in RUN and a network breakpoint', async ({ page, request, watch }) => {
  const projectId = await newProject(request, BUILT);
  await page.goto('/');
  const editor = await openLad(page, projectId);

  await page.getByTestId('view-FBD').click();
  await expect(editor).toHaveAttribute('data-mode', 'FBD');
  await expect(editor.getByTestId('fbd-1-1-diagram')).toBeVisible({ timeout: 10_000 });
  await expect.poll(() => savedText(request, projectId)).toContain('LANGUAGE FBD');
  await page.getByTestId('view-STL').click();
  const stl = page.getByTestId('stl-view-editor');
  await expect(stl).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(stl.locator('.view-line', { hasText: /AN\s+I\s0\.1/ })).toBeVisible();
  await page.getByTestId('view-LAD').click();
  await expect(editor).toHaveAttribute('data-mode', 'LAD');
  await expect(editor.getByTestId('lad-1-1-e2')).toBeVisible();
  await expect.poll(() => savedText(request, projectId)).toBe(BUILT);

  // Download, RUN, monitor: the power flow follows the inputs.
  await editor.getByTestId('lad-1-1-e2').click();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  await page.getByTestId('monitor-toggle').click();
  await expect(editor).toHaveAttribute('data-online', 'true');
  const start = editor.getByTestId('lad-1-1-e2');
  const stop = editor.getByTestId('lad-1-1-e4');
  const motor = editor.getByTestId('lad-1-1-e5');
  await expect(start).toHaveAttribute('data-contact', 'off');
  await expect(stop).toHaveAttribute('data-contact', 'on'); // normally closed, its bit is 0
  await expect(motor).toHaveAttribute('data-flow-in', 'off');
  await page.getByTestId('panel-tab-io').click();
  await page.getByTestId('io-I0.0').click();
  await expect(start).toHaveAttribute('data-contact', 'on');
  await expect(motor).toHaveAttribute('data-flow-in', 'on');
  await expect(editor.getByTestId('lad-1-1-e7')).toHaveAttribute('data-flow-in', 'on', { timeout: 5_000 }); // Q 4.1 after 2 s
  await page.getByTestId('io-I0.0').click();
  await expect(start).toHaveAttribute('data-contact', 'off');
  await expect(motor).toHaveAttribute('data-flow-in', 'on'); // it holds itself
  await page.getByTestId('io-I0.1').click();
  await expect(stop).toHaveAttribute('data-contact', 'off');
  await expect(motor).toHaveAttribute('data-flow-in', 'off');
  await page.getByTestId('io-I0.1').click();

  // A breakpoint on network 2 holds there; a network step goes on; continue runs again.
  await editor.getByTestId('network-1-2-header').click();
  await page.keyboard.press('F9');
  await expect(editor.getByTestId('network-1-2-breakpoint')).toBeVisible();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'hold', { timeout: 10_000 });
  await expect(editor.getByTestId('network-1-2')).toHaveAttribute('data-held', 'true');
  await page.getByTestId('cpu-step-by').selectOption('network');
  await page.getByTestId('cpu-step').click();
  await expect(editor.getByTestId('network-1-1')).toHaveAttribute('data-held', 'true');
  await editor.getByTestId('network-1-2-header').click();
  await page.keyboard.press('F9');
  await expect(editor.getByTestId('network-1-2-breakpoint')).toHaveCount(0);
  await page.getByTestId('cpu-continue').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  expect(watch.consoleErrors).toEqual([]);
});

test('Persian keeps the diagram left to right; axe finds no WCAG A/AA violation in the editor', async ({ page, request }) => {
  const projectId = await newProject(request, BUILT);
  await page.goto('/');
  for (const code of ['en', 'fa'] as const) {
    await chooseLanguage(page, code);
    const editor = await openLad(page, projectId);
    await editor.getByTestId('lad-1-1-e2').click();
    const rung = editor.getByTestId('lad-1-1-rung');
    expect(await rung.evaluate((svg) => getComputedStyle(svg).direction)).toBe('ltr');
    const results = await new AxeBuilder({ page }).include('[data-testid="lad-editor"]').withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']).analyze();
    expect(results.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
  }
  expect(await page.locator('html').getAttribute('dir')).toBe('rtl');
});

test('a file with syntax errors opens in the text view with its markers; the diagram says why', async ({ page, request }) => {
  const projectId = await newProject(request, EMPTY_OB1.replace('BEGIN', 'BEGIN\nNETWORK\nRUNG\n  Contact(I 0.0\n  Coil(Q 4.0)\nEND_RUNG'));
  await page.goto('/');
  await tree(page).getByTestId(`project-node-${projectId}`).click();
  await tree(page).getByTestId(`file-node-${projectId}-Main.lad`).dblclick();
  const text = page.locator('.source-view:not([hidden]) [data-testid="code-editor"]');
  await expect(text).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(page.getByTestId('view-text')).toHaveAttribute('aria-pressed', 'true');
  await expect(text.locator('.squiggly-error').first()).toBeVisible({ timeout: 10_000 });
  await page.getByTestId('view-LAD').click();
  const why = page.getByTestId('lad-cannot-draw');
  await expect(why).toBeVisible();
  await expect(why).toContainText('LAD111');
  await why.getByTestId('lad-show-text').click();
  await expect(text).toBeVisible();
  // Corrected in the text view, the file draws again.
  await text.locator('.view-line', { hasText: 'Contact(I 0.0' }).click();
  await page.keyboard.press('End');
  await page.keyboard.type(')');
  await page.getByTestId('view-LAD').click();
  await expect(page.locator('.source-view:not([hidden]) [data-testid="lad-1-1-e1"]')).toBeVisible({ timeout: 10_000 });
});

test('an operand of the wrong type on a contact is marked on the element', async ({ page, request }) => {
  const projectId = await newProject(request, EMPTY_OB1.replace('BEGIN', 'BEGIN\nNETWORK\nRUNG\n  Contact(MW 10)\n  Coil(Q 4.0)\nEND_RUNG'));
  await page.goto('/');
  const editor = await openLad(page, projectId);
  await expect(editor.getByTestId('lad-1-1-e1')).toHaveAttribute('data-problem', 'error', { timeout: 10_000 });
  await expect(editor.getByTestId('network-1-1-problems')).toBeVisible();
});

test('every program of examples/lad opens in the graphical editor, draws every network and stays unchanged', async ({ page, request, watch }) => {
  test.setTimeout(180_000);
  const folder = path.join(__dirname, '..', '..', 'examples', 'lad');
  const files = fs.readdirSync(folder).filter((name) => /\.(lad|fbd)$/.test(name)).sort();
  expect(files.length).toBeGreaterThan(20);
  const created = await request.post('/api/projects', { data: { name: `Examples ${Date.now()}` } });
  const projectId = (await created.json()).id as number;
  const texts = new Map<string, string>();
  for (const name of files) {
    const text = fs.readFileSync(path.join(folder, name), 'utf8');
    texts.set(name, text);
    expect((await request.put(`/api/projects/${projectId}/files/${name}`, { data: { text } })).ok(), name).toBe(true);
  }
  await page.goto('/');
  await tree(page).getByTestId(`project-node-${projectId}`).click();
  for (const name of files) {
    await tree(page).getByTestId(`file-node-${projectId}-${name}`).dblclick();
    const editor = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
    await expect(editor, name).toBeVisible({ timeout: 15_000 });
    await expect(page.locator('.source-view:not([hidden]) [data-testid="lad-cannot-draw"]')).toHaveCount(0);
    const networks = (texts.get(name)!.match(/^\s*NETWORK\b/gm) ?? []).length;
    for (let n = 1; n <= Math.min(networks, 3); n += 1) {
      const drawn = editor.locator(`[data-testid="lad-1-${n}-rung"], [data-testid="fbd-1-${n}-diagram"], [data-testid="network-1-${n}-stl"]`);
      await expect(drawn.first(), `${name} network ${n}`).toBeVisible({ timeout: 10_000 });
    }
    await page.locator('li.editor-tab', { hasText: name }).locator('[data-testid^="editor-tab-close-"]').click();
  }
  for (const name of files) expect(await savedText(request, projectId, name), name).toBe(texts.get(name));
  expect(watch.consoleErrors).toEqual([]);
});

test('an STL source shown as LAD without changing it, then converted to a LAD source', async ({ page, request }) => {
  const created = await request.post('/api/projects', { data: { name: `Convert ${Date.now()}` } });
  const projectId = (await created.json()).id as number;
  const stl = fs.readFileSync(path.join(__dirname, '..', '..', 'examples', 'projects', 'motor-start-stop', 'OB1.awl'), 'utf8');
  expect((await request.put(`/api/projects/${projectId}/files/OB1.awl`, { data: { text: stl } })).ok()).toBe(true);
  await page.goto('/');
  await tree(page).getByTestId(`project-node-${projectId}`).click();
  await tree(page).getByTestId(`file-node-${projectId}-OB1.awl`).dblclick();
  await page.getByTestId('view-LAD').click();
  const editor = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
  await expect(editor.getByTestId('lad-1-1-rung')).toBeVisible({ timeout: 15_000 });
  await expect(page.getByTestId('stl-as-diagram-note')).toContainText('1');
  await expect(editor.getByTestId('network-1-2-stl')).toContainText('LAD3');
  expect(await savedText(request, projectId, 'OB1.awl')).toBe(stl);
  await page.getByTestId('convert-file').click();
  await expect(tree(page).getByTestId(`file-node-${projectId}-OB1.lad`)).toBeVisible({ timeout: 10_000 });
  await expect(tree(page).getByTestId(`file-node-${projectId}-OB1.awl`)).toHaveCount(0);
  const converted = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
  await expect(converted.getByTestId('lad-1-1-rung')).toBeVisible({ timeout: 15_000 });
});

test('nothing typed in the diagram is lost when the server refuses a save or cannot read the file', async ({ page, request }) => {
  const projectId = await newProject(request, BUILT);
  await page.goto('/');
  // The server cannot read the diagram: the editor says so, keeps the text, and tries again.
  await page.route('**/api/lad/read', (route) => route.fulfill({ status: 503, body: '' }));
  await tree(page).getByTestId(`project-node-${projectId}`).click();
  await tree(page).getByTestId(`file-node-${projectId}-Main.lad`).dblclick();
  const why = page.getByTestId('lad-cannot-draw');
  await expect(why).toBeVisible({ timeout: 15_000 });
  await expect(why).toContainText('NET000');
  await page.unroute('**/api/lad/read');
  await why.getByRole('button', { name: 'Try again' }).click();
  const editor = page.locator('.source-view:not([hidden]) [data-testid="lad-editor"]');
  await expect(editor.getByTestId('lad-1-1-e2')).toBeVisible({ timeout: 10_000 });

  // A save refused by the server: the edit stays in the diagram and goes through later.
  await page.route(`**/api/projects/${projectId}/files/Main.lad`, (route) =>
    route.request().method() === 'PUT'
      ? route.fulfill({ status: 500, contentType: 'application/json', body: JSON.stringify({ error: { code: 'API100', key: 'internal_error', message: 'boom', params: {} } }) })
      : route.continue(),
  );
  await editor.getByTestId('network-1-2-header').click();
  await page.keyboard.press('Control+R');
  await page.keyboard.press('Shift+F2');
  await typeOperand(page, 'I 1.7');
  await expect(page.getByTestId('save-failed')).toBeVisible({ timeout: 10_000 });
  await expect(editor.getByTestId('lad-1-3-e1')).toHaveAttribute('aria-label', /I 1\.7/);
  expect(await savedText(request, projectId)).toBe(BUILT);
  await page.unroute(`**/api/projects/${projectId}/files/Main.lad`);
  await page.getByTestId('save-failed').getByRole('button').click();
  await expect.poll(() => savedText(request, projectId)).toContain('Contact(I 1.7)');
  await expect(page.getByTestId('save-failed')).toHaveCount(0);
});

test('what is typed in the STL view goes back to the block network by network', async ({ page, request }) => {
  const projectId = await newProject(request, BUILT);
  await page.goto('/');
  const editor = await openLad(page, projectId);
  await page.getByTestId('view-STL').click();
  const stl = page.getByTestId('stl-view-editor');
  await expect(stl).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  // Two networks more at the end: one with a LAD shape, one that stays STL (exclusive OR).
  await stl.locator('.view-lines').click();
  await page.keyboard.press('Control+End');
  await page.keyboard.press('ArrowUp'); // END_ORGANIZATION_BLOCK
  await page.keyboard.press('ArrowUp'); // the last line of the last network
  await page.keyboard.press('End');
  await page.keyboard.press('Enter');
  await page.keyboard.insertText('NETWORK\nTITLE = Added in STL\nA I 1.0\n= Q 5.0\nNETWORK\nTITLE = Kept as STL\nA I 1.1\nX I 1.2\n= Q 5.1\n');
  await page.getByTestId('view-LAD').click();
  await expect(editor).toHaveAttribute('data-mode', 'LAD');
  await expect(editor.getByTestId('network-1-3-title')).toHaveText('Added in STL');
  await expect(editor.getByTestId('lad-1-3-e1')).toHaveAttribute('aria-label', /I 1\.0/);
  await expect(editor.getByTestId('network-1-4-stl')).toContainText('LAD305');
  await expect.poll(() => savedText(request, projectId)).toContain('TITLE = Added in STL');
  const saved = await savedText(request, projectId);
  expect(saved).toContain('Contact(I 1.0)');
  expect(saved).toContain('STL REASON LAD305');
  // The networks not touched in the STL are written as they were.
  expect(saved.startsWith(BUILT.slice(0, BUILT.indexOf('END_ORGANIZATION_BLOCK')))).toBe(true);
});
