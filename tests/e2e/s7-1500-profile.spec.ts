/**
 * The S7-1200/1500 profile chosen on the CPU properties page: a project whose SCL uses LREAL and
 * UINT is refused for the S7-300 with SCL500 ("LREAL needs the S7-1200/1500 profile"); with the
 * family chosen and saved, it compiles without a problem and downloads.
 */
import { test, expect, chooseLanguage, fileText, openCpuProperties, openWorkbench, projectWithFiles } from './fixtures';

const MAIN = `DATA_BLOCK "Data"
STRUCT
  total : LREAL;
  count : UINT;
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK Main
BEGIN
  "Data".total := "Data".total + LREAL#0.25;
  "Data".count := "Data".count + 1;
END_ORGANIZATION_BLOCK
`;

test.describe.configure({ timeout: 180_000 });
test.use({ viewport: { width: 1440, height: 900 } });

test('choose the S7-1200/1500 family: LREAL and UINT compile and download', async ({ page, watch }, testInfo) => {
  const projectId = await projectWithFiles(page.request, 'S7-1500', { 'Main.scl': MAIN });
  await openWorkbench(page);
  const props = await openCpuProperties(page, projectId);
  const family = props.getByLabel('CPU family');
  await expect(family).toHaveValue('S7-300');

  // For the S7-300 the S7-1500 types are refused with the profile's code.
  await page.keyboard.press('Control+F7');
  const list = page.getByTestId('diagnostics');
  const refused = list.getByTestId('diagnostic').filter({ hasText: 'SCL500' });
  await expect(refused.first()).toContainText('LREAL needs the S7-1200/1500 profile', { timeout: 30_000 });
  await expect(refused).toHaveCount(3); // LREAL and UINT at their declarations, LREAL#0.25

  await family.selectOption('S7-1500');
  await props.getByTestId('cpu-props-save').click();
  await expect(props.getByTestId('cpu-props-status')).toHaveText('Saved');
  expect(await fileText(page.request, projectId, 'cpu.properties')).toContain('profile = S7-1500');

  await page.keyboard.press('Control+F7');
  await expect(list.getByTestId('diagnostic').filter({ hasText: 'SCL500' })).toHaveCount(0, { timeout: 30_000 });
  await expect(page.getByTestId('compile-status')).toHaveText(/^Compiled — errors: 0, warnings: \d+$/);
  await props.evaluate((element) => element.scrollTo(0, 0));
  await page.screenshot({ path: testInfo.outputPath('en-s7-1500-profile.png') });

  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');

  await chooseLanguage(page, 'fa');
  await expect(props).toHaveAttribute('dir', 'rtl');
  const familyFa = props.getByLabel('خانوادهٔ CPU');
  await expect(familyFa).toHaveValue('S7-1500');
  await expect(familyFa).toHaveAttribute('dir', 'ltr'); // names of CPUs stay left to right
  await page.screenshot({ path: testInfo.outputPath('fa-s7-1500-profile.png') });
  expect(watch.consoleErrors).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
