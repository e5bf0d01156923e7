/**
 * The CPU properties page: opened from the project's row menu, its fields checked and saved into
 * the project file cpu.properties (the text the page shows is the file's), kept over a reload,
 * and used by the download: with clock memory MB100 the 1 Hz bit M100.5 toggles in RUN.
 */
import { test, expect, chooseLanguage, fileText, openCpuProperties, openWorkbench, projectWithFiles } from './fixtures';

const OB1 = `ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = The 1 Hz clock bit drives a lamp
      A     M    100.5;
      =     Q      4.0;
END_ORGANIZATION_BLOCK
`;

test.describe.configure({ timeout: 240_000 });
test.use({ viewport: { width: 1440, height: 900 } });

test('set clock memory MB100 and the cycle time, save, reload, download: M100.5 toggles', async ({ page, watch }, testInfo) => {
  const projectId = await projectWithFiles(page.request, 'CPU', { 'OB1.awl': OB1 });
  await openWorkbench(page);
  const props = await openCpuProperties(page, projectId);
  // A project without the file gets the defaults written into a new cpu.properties.
  await expect(props.getByLabel('Cycle time', { exact: true })).toHaveValue('10');
  await expect(props.getByLabel('Cycle monitoring time')).toHaveValue('150');
  await expect(props.getByLabel('Memory bytes from MB 0')).toHaveValue('16');
  await expect(page.getByTestId(`file-node-${projectId}-cpu.properties`)).toBeVisible();

  // A bad value is said beside its field, with its code, and not saved.
  await props.getByLabel('Cycle time', { exact: true }).fill('9000');
  await expect(props.getByTestId('cpu-props-problem-cycle_time')).toContainText('allowed from 1 to 6000');
  await expect(props.getByTestId('cpu-props-problem-cycle_time')).toContainText('PRJ905');
  await expect(props.getByLabel('Cycle time', { exact: true })).toHaveAttribute('aria-invalid', 'true');
  await props.getByLabel('Cycle time', { exact: true }).fill('20');
  await expect(props.getByTestId('cpu-props-problem-cycle_time')).toHaveCount(0);

  await props.getByLabel('Use a memory byte as clock memory').check();
  await props.getByLabel('Memory byte', { exact: true }).fill('100');
  await expect(props.getByRole('columnheader', { name: 'M100.5' })).toBeVisible();
  await props.getByTestId('cpu-props-save').click();
  await expect(props.getByTestId('cpu-props-status')).toHaveText('Saved');

  // The file holds what the page shows, line for line.
  const saved = await fileText(page.request, projectId, 'cpu.properties');
  expect(saved).toContain('clock_memory = MB100\n');
  expect(saved).toContain('cycle_time = 20\n');
  await props.getByText('Text of cpu.properties').click();
  expect(await props.getByTestId('cpu-props-text').textContent()).toBe(saved);

  await props.evaluate((element) => element.scrollTo(0, 0));
  await page.screenshot({ path: testInfo.outputPath('en-cpu-properties.png') });
  await chooseLanguage(page, 'fa');
  await expect(props).toHaveAttribute('dir', 'rtl');
  await expect(props.getByRole('heading', { name: 'ویژگی‌های CPU' })).toBeVisible();
  await page.screenshot({ path: testInfo.outputPath('fa-cpu-properties.png') });
  await chooseLanguage(page, 'en');

  // After a reload the page reads the same values from the file.
  await page.reload();
  await expect(page.getByTestId('server-status')).toHaveAttribute('data-state', 'online');
  await openCpuProperties(page, projectId);
  await expect(props.getByLabel('Cycle time', { exact: true })).toHaveValue('20');
  await expect(props.getByLabel('Use a memory byte as clock memory')).toBeChecked();
  await expect(props.getByLabel('Memory byte', { exact: true })).toHaveValue('100');

  // The download uses the properties: cycle 20 ms, and MB100 is the clock memory.
  await expect(page.getByTestId('cpu-download')).toBeEnabled();
  await page.keyboard.press('Control+B');
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'stop', { timeout: 15_000 });
  await expect(page.getByTestId('cpu-cycle-ms')).toHaveValue('20');
  await page.getByTestId('cpu-run').click();
  await expect(page.getByTestId('cpu-state')).toHaveAttribute('data-mode', 'run');
  // Q4.0 follows M100.5 (1 Hz: half a second on, half a second off): the I/O panel's lamp blinks.
  await page.getByTestId('panel-tab-io').click();
  const lamp = page.getByTestId('io-Q4.0');
  await expect(lamp).toHaveAttribute('data-state', 'on', { timeout: 15_000 });
  await expect(lamp).toHaveAttribute('data-state', 'off', { timeout: 15_000 });
  await expect(lamp).toHaveAttribute('data-state', 'on', { timeout: 15_000 });

  expect(watch.consoleErrors).toEqual([]);
  // The reload cancels the requests the page had in flight (net::ERR_ABORTED): not a failure.
  expect(watch.failedRequests.filter((failed) => !failed.endsWith('net::ERR_ABORTED'))).toEqual([]);
  expect(watch.foreignRequests).toEqual([]);
});
