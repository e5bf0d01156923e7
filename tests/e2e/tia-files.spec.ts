/**
 * Sources as TIA Portal exports them, in the workbench against the real server: a PLC data type
 * (`.udt`), an optimized DB (`.db`) and OBs named only by their event, in an S7-1500 project. The
 * tree shows the blocks with the numbers TIA gives them (Startup OB 100, Cyclic interrupt OB 30,
 * the DB and UDT numbered from 1), and the `.db` file opens in the SCL editor, coloured as SCL.
 * In English and in Arabic (right to left: the source stays left to right).
 */
import type { APIRequestContext } from '@playwright/test';
import { test, expect, chooseLanguage, tree, expandProject, openFile } from './fixtures';

const UDT = `TYPE "Tank_Data"
VERSION : 0.1
   STRUCT
      level { ExternalAccessible := 'False'; ExternalVisible := 'False'; ExternalWritable := 'False'} : Int;
      full : Bool;
   END_STRUCT;

END_TYPE
`;

const DB = `DATA_BLOCK "Plant"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      tank : "Tank_Data";
      ticks : Int;
   END_VAR

BEGIN
   // initial values as TIA writes them
   tank.level := 40;
END_DATA_BLOCK
`;

const OBS = `ORGANIZATION_BLOCK "Startup"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Plant".ticks := 0;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Cyclic interrupt"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    REGION Count the interrupts
        "Plant".ticks := "Plant".ticks + 1;
    END_REGION Count the interrupts
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Plant".tank.full := "Plant".tank.level > 90;
END_ORGANIZATION_BLOCK
`;

async function makeProject(request: APIRequestContext, name: string): Promise<number> {
  const created = await request.post('/api/projects', { data: { name } });
  expect(created.status()).toBe(201);
  const { id } = (await created.json()) as { id: number };
  const files: Record<string, string> = {
    'cpu.properties': 'profile = S7-1500\n',
    'Tank_Data.udt': UDT,
    'Plant.db': DB,
    'Program.scl': OBS,
  };
  for (const [file, text] of Object.entries(files)) {
    expect((await request.put(`/api/projects/${id}/files/${file}`, { data: { text } })).ok()).toBe(true);
  }
  return id;
}

test.describe.configure({ timeout: 180_000 });

for (const language of ['en', 'ar'] as const) {
  test(`TIA Portal .db and .udt exports compile with TIA's numbers and open as SCL (${language})`, async ({ page, watch }, info) => {
    const name = `TIA export ${language} ${Date.now()}`;
    const projectId = await makeProject(page.request, name);
    await page.goto('/');
    await chooseLanguage(page, language);
    await expandProject(page, name);

    // The blocks carry the numbers TIA gives them: OBs by their event, DB and UDT from 1.
    for (const block of ['OB1', 'OB30', 'OB100', 'DB1', 'UDT1']) {
      await expect(tree(page).getByTestId(`block-node-${projectId}-${block}`)).toBeVisible({ timeout: 30_000 });
    }
    await expect(tree(page).getByTestId(`block-node-${projectId}-OB30`)).toContainText('Cyclic interrupt');
    await expect(tree(page).getByTestId(`block-node-${projectId}-DB1`)).toContainText('Plant');

    // The DB export opens in the SCL editor: SCL's language, its keywords coloured.
    const editor = await openFile(page, projectId, 'Plant.db');
    await expect(editor).toContainText('S7_Optimized_Access');
    const modelLanguage = await page.evaluate(() => {
      const monaco = (window as Window & { monaco: typeof import('monaco-editor/editor/editor.api') }).monaco;
      const shown = monaco.editor.getEditors().find((e) => e.getDomNode()?.offsetParent !== null);
      return shown?.getModel()?.getLanguageId();
    });
    expect(modelLanguage).toBe('scl');
    await expect(editor.locator('.view-line span span').filter({ hasText: /^DATA_BLOCK$/ }).first()).toBeVisible();
    const classes = await editor
      .locator('.view-line span span')
      .evaluateAll((spans) => spans.map((span) => [span.textContent ?? '', span.className] as const));
    const keyword = classes.find(([text]) => text === 'DATA_BLOCK')?.[1];
    const comment = classes.find(([text]) => text.replace(/\u00a0/g, ' ').startsWith('// initial values'))?.[1];
    expect(keyword).toBeTruthy();
    expect(comment).toBeTruthy();
    expect(keyword).not.toEqual(comment);
    await expect(editor).toHaveCSS('direction', 'ltr');
    await expect(page.locator('html')).toHaveAttribute('dir', language === 'ar' ? 'rtl' : 'ltr');
    await page.screenshot({ path: info.outputPath(`tia-files-${language}.png`) });
    expect(watch.consoleErrors).toEqual([]);
  });
}
