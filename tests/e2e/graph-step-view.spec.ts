/**
 * S7-Graph's step view and permanent instructions against the real server, as a user drives
 * them: the two-conveyor sequence opened, its step 2 picked, its actions and supervision shown; a row
 * added with an event/qualifier pair that does not go together is kept (saved as typed) and
 * marked on its cell with its GRA code; the interlock added and drawn in the LAD editor; a
 * permanent network added. In English and in Persian (the page right to left, the diagrams and
 * operands left to right).
 */
import type { APIRequestContext, Locator, Page } from '@playwright/test';
import { test, expect, chooseLanguage, tree } from './fixtures';
import { CONVEYORS, SYMBOLS } from './graphConveyors';

async function newProject(request: APIRequestContext): Promise<number> {
  const created = await request.post('/api/projects', { data: { name: `Graph step ${Date.now()}-${Math.random()}` } });
  expect(created.status()).toBe(201);
  const id = (await created.json()).id as number;
  for (const [name, text] of Object.entries({ 'symbols.sdf': `${SYMBOLS}\r\n`, 'Conveyors.graph': CONVEYORS })) {
    expect((await request.put(`/api/projects/${id}/files/${name}`, { data: { text } })).ok(), name).toBe(true);
  }
  return id;
}

const view = (page: Page): Locator => page.locator('.source-view:not([hidden])');

async function savedText(request: APIRequestContext, projectId: number): Promise<string> {
  return (await (await request.get(`/api/projects/${projectId}/files/Conveyors.graph`)).json()).text as string;
}

for (const language of ['en', 'fa'] as const) {
  test(`the step view edits a step's actions and conditions (${language})`, async ({ page, request, watch }, info) => {
    test.setTimeout(60_000);
    const projectId = await newProject(request);
    await page.setViewportSize({ width: 1600, height: 1200 });
    await page.goto('/');
    await chooseLanguage(page, language);
    await tree(page).getByTestId(`project-node-${projectId}`).click();
    await tree(page).getByTestId(`file-node-${projectId}-Conveyors.graph`).dblclick();
    await expect(view(page).getByTestId('graph-chart')).toBeVisible({ timeout: 15_000 });
    await page.getByTestId('graph-view-step').click();
    const stepView = view(page).getByTestId('graph-step-view');
    await expect(stepView).toBeVisible();

    // Step 2 (its name is the course's; the option says `S2 <name>`).
    await stepView.getByTestId('graph-step-picker').selectOption({ index: 1 });
    await expect(stepView.getByTestId('graph-step-number-field')).toHaveValue('2');
    const table = stepView.getByRole('table');
    const row = (k: number) => stepView.getByTestId(`graph-action-${k}`);
    const cell = (k: number, label: string) => row(k).getByLabel(label, { exact: true });
    await expect(cell(1, language === 'en' ? 'Qualifier' : 'نوع فرمان')).toHaveValue('S');
    await expect(cell(1, language === 'en' ? 'Operand' : 'عملوند')).toHaveValue('"Belt_B"');
    await expect(table.getByRole('row')).toHaveCount(2);
    // The supervision is drawn in the LAD editor: the Jam contact and the pseudo coil V.
    const supervision = stepView.getByTestId('graph-supervision');
    await expect(supervision.getByTestId('lad-editor')).toBeVisible();
    await expect(supervision.getByTestId('lad-1-1-graph-out')).toBeVisible();
    await expect(supervision.getByTestId('lad-1-1-e1')).toContainText('Jam');

    // A new row: D after S1 does not go together (D works on the step's time): kept and marked.
    const labels = language === 'en' ? { event: 'Event', qualifier: 'Qualifier', operand: 'Operand', time: 'Time' } : { event: 'رخداد', qualifier: 'نوع فرمان', operand: 'عملوند', time: 'زمان' };
    await stepView.getByTestId('graph-action-add').click();
    // The operand completes from the symbol table, as on a LAD element.
    const operand = cell(2, labels.operand);
    await operand.fill('"Rea');
    await expect(row(2).getByRole('option', { name: /Ready/ })).toBeVisible();
    await operand.press('Tab');
    await expect(operand).toHaveValue('"Ready"');
    for (const [label, value] of [[labels.event, 'S1'], [labels.qualifier, 'D'], [labels.time, 'T#2S']] as const) {
      await cell(2, label).fill(value);
      await cell(2, label).press('Enter');
    }
    const qualifier = cell(2, labels.qualifier);
    await expect(qualifier).toHaveAttribute('aria-invalid', 'true');
    await expect(qualifier).toHaveAttribute('title', /^GRA231: /);
    await expect(stepView.getByTestId('graph-action-problems-2')).toContainText('GRA231');
    await expect.poll(() => savedText(request, projectId), { timeout: 10_000 }).toContain('S1 D "Ready", T#2S;');

    // The interlock added and drawn: an empty condition ending in C.
    const interlock = stepView.getByTestId('graph-interlock');
    await interlock.getByTestId('graph-interlock-add').click();
    await expect(interlock.getByTestId('lad-1-1-graph-out')).toBeVisible();
    await expect(page.locator('html')).toHaveAttribute('dir', language === 'fa' ? 'rtl' : 'ltr');
    await stepView.getByTestId('graph-step-picker').scrollIntoViewIfNeeded();
    await page.screenshot({ path: info.outputPath(`graph-step-view-${language}.png`) });

    // The permanent instructions: a network added before the sequencer.
    await page.getByTestId('graph-view-permanent').click();
    const pre = view(page).getByTestId('graph-permanent-pre');
    await expect(pre.getByTestId('lad-editor')).toBeVisible();
    await pre.getByTestId('lad-add-network-1').click();
    await expect(pre.getByTestId('network-1-1-header')).toBeVisible();
    // Saved and checked: a permanent network without a coil does nothing, said on the network.
    await expect(pre.getByTestId('network-1-1-problems')).toBeVisible({ timeout: 15_000 });
    await expect(pre.getByTestId('network-1-1-problems')).toHaveAttribute('title', /GRA265/);
    await page.screenshot({ path: info.outputPath(`graph-permanent-${language}.png`) });
    expect(watch.consoleErrors).toEqual([]);
  });
}
