/**
 * The S7-Graph editor against the real server, as a user drives it: the two-conveyor sequence
 * built from a new source in the chart by mouse and keyboard (steps and transitions inserted,
 * renumbered, undo/redo), its actions (N, S, R), transition conditions (LAD contacts and a
 * compare) and a supervision filled in the step view, and the saved text read back as the same
 * sequence as tests/e2e/graphConveyors.ts. Bad input: a file with syntax errors opens in the text
 * view with markers and the chart says why it cannot draw; an illegal event/qualifier pair typed
 * in the actions table is marked on its cell.
 */
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import { test, expect, lineOf, tree, visibleEditor } from './fixtures';
import { CONVEYORS, SYMBOLS } from './graphConveyors';

type Monaco = typeof import('monaco-editor/editor/editor.api');
type WithMonaco = Window & { monaco: Monaco };

async function newProject(request: APIRequestContext, files: Record<string, string> = {}): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: `Graph ${Date.now()}-${Math.random()}` } });
  expect(created.status()).toBe(201);
  const id = (await created.json()).id as number;
  for (const [name, text] of Object.entries({ 'symbols.sdf': `${SYMBOLS}\r\n`, ...files })) {
    expect((await request.put(`/api/projects/${id}/files/${name}`, { data: { text } })).ok(), name).toBe(true);
  }
  return id;
}

async function savedText(request: APIRequestContext, projectId: number, name: string): Promise<string> {
  return (await (await request.get(`/api/projects/${projectId}/files/${name}`)).json()).text as string;
}

/** What a `.graph` text means, without element ids and comments: the sequencers and settings. */
async function meaning(request: APIRequestContext, text: string): Promise<unknown> {
  const read = await request.post('/api/graph/read', { data: { name: 'x.graph', text } });
  expect(read.ok()).toBe(true);
  const body = (await read.json()) as { blocks: Array<{ settings: unknown; sequencers: unknown }>; diagnostics: unknown[]; problems: Array<{ code: string }> };
  expect(body.diagnostics).toEqual([]);
  const strip = (value: unknown): unknown =>
    Array.isArray(value)
      ? value.map(strip)
      : value && typeof value === 'object'
        ? Object.fromEntries(Object.entries(value).filter(([key]) => key !== 'id' && key !== 'comment').map(([key, v]) => [key, strip(v)]))
        : value;
  // Renumbering keeps a transition's name (the inserted Trans3 is number 2 now): names aside.
  const sequencers = (strip(body.blocks[0]?.sequencers) as Array<{ transitions: Array<Record<string, unknown>> }>).map((seq) => ({
    ...seq,
    transitions: seq.transitions.map(({ name: _name, ...rest }) => rest),
  }));
  return { settings: body.blocks[0]?.settings, sequencers, problems: body.problems.map((p) => p.code) };
}

/** The workbench at a desk's size, without the lessons beside it. */
async function openWorkbench(page: Page): Promise<void> {
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/');
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  if ((await page.getByTestId('lesson-toggle').getAttribute('aria-pressed')) === 'true') await page.getByTestId('lesson-toggle').click();
}

const view = (page: Page): Locator => page.locator('.source-view:not([hidden])');

/** Types into the operand field that opened on a LAD element (or a box's type) and takes it. */
async function typeOperand(page: Page, text: string): Promise<void> {
  const input = page.locator('[data-testid="operand-input"]:focus');
  await expect(input).toHaveCount(1);
  await input.fill(text);
  await input.press('Enter');
  await expect(input).toHaveCount(0);
}

/** The LAD element `e<k>` of the first network of a step-view section. */
const element = (section: Locator, k: number): Locator => section.locator(`[data-testid^="lad-"][data-testid$="-e${k}"]`).first();

/** Fills the actions table's row k (added when missing). */
async function action(stepView: Locator, k: number, cells: { event?: string; qualifier?: string; operand?: string; time?: string }): Promise<void> {
  const row = stepView.getByTestId(`graph-action-${k}`);
  if ((await row.count()) === 0) {
    await stepView.getByTestId('graph-action-add').click();
    await expect(row).toBeVisible();
  }
  for (const [label, value] of [['Event', cells.event], ['Qualifier', cells.qualifier], ['Operand', cells.operand], ['Time', cells.time]] as const) {
    if (value === undefined) continue;
    const input = row.getByLabel(label, { exact: true });
    await input.fill(value);
    await input.press('Enter');
    await expect(input).toHaveValue(value);
  }
}

/** Shows a step in the step view through its picker. */
async function pickStep(stepView: Locator, name: string): Promise<void> {
  await stepView.getByTestId('graph-step-picker').selectOption(name);
  await expect(stepView.getByTestId('graph-step-name')).toHaveValue(name);
}

test('the two-conveyor sequence built in the chart and the step view, by mouse and keyboard', async ({ page, request, watch }) => {
  test.setTimeout(90_000);
  const projectId = await newProject(request);
  await openWorkbench(page);
  const row = tree(page).getByTestId(`project-node-${projectId}`);
  await row.click();
  await row.focus();
  await page.keyboard.press('Shift+F10');
  await page.getByTestId('tree-menu').getByRole('menuitem', { name: 'New S7-Graph sequencer…' }).click();
  const dialog = page.getByTestId('file-new-dialog');
  await dialog.getByTestId('file-name-input').fill('Conveyors.graph');
  await dialog.getByTestId('file-name-submit').click();
  await expect(dialog).toBeHidden();

  // The new source opens as a chart: Step1 (initial) -Trans1-> Step2 -Trans2-> jump to Step1.
  const chart = view(page).getByTestId('graph-chart');
  await expect(chart).toBeVisible({ timeout: 15_000 });
  await expect(page.getByTestId('graph-view-chart')).toHaveAttribute('aria-pressed', 'true');
  const step = (n: number) => chart.getByTestId(`graph-step-${n}`);
  await expect(step(1)).toHaveAttribute('data-initial', 'true', { timeout: 15_000 }); // laid out in the worker
  await expect(step(2)).toHaveAttribute('data-initial', 'false');
  await expect(chart.getByTestId('graph-jump-2')).toBeVisible();

  // By mouse: a step+transition after Step2 (the jump now leaves from the new step).
  await step(2).click();
  await expect(step(2)).toHaveAttribute('aria-selected', 'true');
  await view(page).getByTestId('graph-insert-step').click();
  await expect(step(3)).toHaveAttribute('aria-selected', 'true');
  // By keyboard: arrows along the chart, Insert for the next pair.
  await step(3).click();
  await page.keyboard.press('ArrowUp'); // the transition into Step3
  await expect(chart.locator('[data-testid^="graph-transition-"][aria-selected="true"]')).toHaveCount(1);
  await expect(step(3)).toHaveAttribute('aria-selected', 'false');
  await page.keyboard.press('ArrowDown');
  await expect(step(3)).toHaveAttribute('aria-selected', 'true');
  await page.keyboard.press('Insert');
  await expect(step(4)).toHaveAttribute('aria-selected', 'true');
  await expect(chart.locator('[data-testid^="graph-step-"][data-state]')).toHaveCount(4);
  // Renumber in chart order (the jump back to Step1 gets number 4); undo and redo it.
  await view(page).getByTestId('graph-renumber').click();
  await expect(chart.getByTestId('graph-jump-4')).toBeVisible();
  await chart.getByTestId('graph-step-1').click();
  await page.keyboard.press('Control+Z');
  await expect(chart.getByTestId('graph-jump-2')).toBeVisible();
  await page.keyboard.press('Control+Y');
  await expect(chart.getByTestId('graph-jump-4')).toBeVisible();

  // F2 renames the selected step (an inline dialog: name and number).
  await step(2).click();
  await page.keyboard.press('F2');
  const rename = chart.getByTestId('graph-rename-name');
  await expect(rename).toBeFocused();
  await rename.fill('B_on');
  await rename.press('Enter');
  await expect(step(2)).toHaveAttribute('aria-label', /B_on/);

  // The step view of Step1 (Enter on the selected step): the ready lamp, Start as the condition.
  await step(1).click();
  await page.keyboard.press('Enter');
  const stepView = view(page).getByTestId('graph-step-view');
  await expect(stepView).toBeVisible();
  await expect(page.getByTestId('graph-view-step')).toHaveAttribute('aria-pressed', 'true');
  await expect(stepView.getByRole('table')).toBeVisible();
  await action(stepView, 1, { qualifier: 'N', operand: '"Ready"' });
  const transitions = stepView.getByTestId('graph-step-transitions');
  await element(transitions, 1).dblclick();
  await typeOperand(page, '"Start"');

  // B_on: belt B set, supervised by the jam switch, belt A 5 s later (a compare box).
  await pickStep(stepView, 'B_on');
  await action(stepView, 1, { qualifier: 'S', operand: '"Belt_B"' });
  const supervision = stepView.getByTestId('graph-supervision');
  await supervision.getByTestId('graph-supervision-add').click();
  await supervision.locator('[data-testid$="-header"]').first().click();
  await supervision.getByTestId('favourite-contact').click();
  await typeOperand(page, '"Jam"');
  await transitions.locator('[data-testid$="-header"]').first().click();
  await page.keyboard.press('Shift+F5');
  await typeOperand(page, 'CMP>=D');
  const compare = element(transitions, 1);
  await expect(compare).toHaveAttribute('data-kind', 'box');
  await transitions.locator('[data-testid$="-e1-pin-IN1"]').dblclick();
  await typeOperand(page, 'B_on.T');
  await transitions.locator('[data-testid$="-e1-pin-IN2"]').dblclick();
  await typeOperand(page, 'T#5S');

  // Step3: belt A set; Stop leaves it.
  await pickStep(stepView, 'Step3');
  await action(stepView, 1, { qualifier: 'S', operand: '"Belt_A"' });
  await transitions.locator('[data-testid$="-header"]').first().click();
  await page.keyboard.press('Shift+F2');
  await typeOperand(page, '"Stop"');

  // Step4: both belts reset; back to Step1 once Stop is released (a normally closed contact).
  await pickStep(stepView, 'Step4');
  await action(stepView, 1, { qualifier: 'R', operand: '"Belt_A"' });
  await action(stepView, 2, { qualifier: 'R', operand: '"Belt_B"' });
  await element(transitions, 1).click();
  await page.keyboard.press('Delete');
  await expect(element(transitions, 1)).toHaveCount(0);
  await transitions.locator('[data-testid$="-header"]').first().click();
  await page.keyboard.press('Shift+F3');
  await typeOperand(page, '"Stop"');

  // Saved: the text reads as the course's sequence, with nothing else changed or lost.
  const tab = page.locator('[data-testid^="editor-tab-source-"]').filter({ hasText: 'Conveyors.graph' });
  await expect(tab).toHaveAttribute('data-save-state', 'saved', { timeout: 10_000 });
  const wanted = await meaning(request, CONVEYORS);
  await expect.poll(async () => meaning(request, await savedText(request, projectId, 'Conveyors.graph'))).toEqual(wanted);
  const text = await savedText(request, projectId, 'Conveyors.graph');
  expect(text).toContain('COMMENT = the initial step: active after the first call'); // the template's comment stays
  expect(text).toMatch(/SUPERVISION\s+Contact\("Jam"\)\s+END_SUPERVISION/);

  // Back in the chart: the conditions are drawn beside their transitions.
  await page.getByTestId('graph-view-chart').click();
  await expect(chart.getByTestId('graph-transition-1')).toContainText('Start');
  // And the text view shows the same text.
  await page.getByTestId('graph-view-text').click();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(editor.locator('.view-line', { hasText: 'INITIAL_STEP Step1 (1)' })).toBeVisible();
  expect(await lineOf(page, 'Box(CMP>=D, IN1 := B_on.T, IN2 := T#5S)')).toBeGreaterThan(0);

  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});

test('bad input: syntax errors open in the text view and the chart says why; an illegal event/qualifier pair is marked on its cell', async ({ page, request, watch }) => {
  const broken = CONVEYORS.replace('TRANSITION Trans3 (3) FROM Step3 TO Step4', 'TRANSITION Trans3 (3) FROM Step3 TO');
  const projectId = await newProject(request, { 'Broken.graph': broken, 'Conveyors.graph': CONVEYORS });
  await openWorkbench(page);
  await tree(page).getByTestId(`project-node-${projectId}`).click();
  await tree(page).getByTestId(`file-node-${projectId}-Broken.graph`).dblclick();
  const editor = visibleEditor(page);
  await expect(editor).toHaveAttribute('data-state', 'ready', { timeout: 15_000 });
  await expect(page.getByTestId('graph-view-text')).toHaveAttribute('aria-pressed', 'true');
  // The syntax error is a marker on its line (GRA120: the step after TO is missing).
  const markers = () =>
    page.evaluate(() => {
      const monaco = (window as unknown as WithMonaco).monaco;
      const shown = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
      const model = shown?.getModel();
      if (!model) return [];
      return monaco.editor.getModelMarkers({ resource: model.uri, owner: 'nasaq' }).map((m) => ({ code: typeof m.code === 'string' ? m.code : (m.code?.value ?? ''), line: m.startLineNumber }));
    });
  const line = broken.split('\n').findIndex((l) => l.startsWith('TRANSITION Trans3')) + 2;
  await expect.poll(markers).toContainEqual({ code: 'GRA120', line });
  await page.getByTestId('graph-view-chart').click();
  const why = view(page).getByTestId('graph-cannot-draw');
  await expect(why).toBeVisible();
  await expect(why).toHaveAttribute('role', 'alert');
  await expect(why).toContainText('GRA120');
  await expect(why).toContainText(String(line));
  await expect(view(page).getByTestId('graph-chart')).toHaveCount(0);
  await why.getByTestId('graph-show-text').click();
  await expect(editor).toBeVisible();
  expect(await savedText(request, projectId, 'Broken.graph')).toBe(broken); // nothing rewritten

  // A good file: in Step4's actions table, S1 before D (D acts on the step's time: no event).
  await tree(page).getByTestId(`file-node-${projectId}-Conveyors.graph`).dblclick();
  const chart = view(page).getByTestId('graph-chart');
  await expect(chart.getByTestId('graph-step-4')).toBeVisible({ timeout: 15_000 });
  await chart.getByTestId('graph-step-4').click();
  await page.keyboard.press('Enter');
  const stepView = view(page).getByTestId('graph-step-view');
  await action(stepView, 2, { qualifier: 'D', time: 'T#2S' });
  const row = stepView.getByTestId('graph-action-2');
  await expect(row.locator('[aria-invalid="true"]')).toHaveCount(0);
  await action(stepView, 2, { event: 'S1' });
  // The cell is marked (aria-invalid, its title names the problem) and the row's problem list says why.
  const marked = row.locator('input[aria-invalid="true"]');
  await expect(marked).toHaveCount(1);
  await expect(marked).toHaveAttribute('title', /GRA231/);
  await expect(stepView.getByTestId('graph-action-problems-2')).toContainText('GRA231');
  // What was typed is kept (and saved) as typed, with the marker; removing the event clears it.
  await expect.poll(() => savedText(request, projectId, 'Conveyors.graph')).toContain('S1 D "Belt_B", T#2S;');
  await action(stepView, 2, { event: '' });
  await expect(row.locator('[aria-invalid="true"]')).toHaveCount(0);
  await expect(stepView.getByTestId('graph-action-problems-2')).toHaveCount(0);
  expect(watch.consoleErrors).toEqual([]);
});
