/**
 * The CPU properties page over a fake server: the fields show what the server read from the
 * file, a bad value is said beside its field (in the interface language) and not saved, a good
 * one is saved with the file's version, changing only its line.
 */
import { fireEvent, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect } from 'react';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it } from 'vitest';
import { CpuPropertiesTab } from '../../frontend/src/cpuprops/CpuPropertiesTab';
import { EditorTabsProvider, useEditorTabs, type SourceTab } from '../../frontend/src/editor/EditorTabsContext';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { json, mockServer } from './helpers';

const TEXT = '# my CPU\ncycle_time = 10   # scan\nclock_memory = none\n';

/** A fake of the server's parser for the two keys the test changes. */
function check(text: string) {
  const lines = text.split('\n');
  const at = (key: string) => lines.findIndex((line) => line.startsWith(key));
  const cycle = Number(/cycle_time = +(\d+)/.exec(text)?.[1]);
  const clock = /clock_memory = MB(\d+)/.exec(text)?.[1];
  const where = { file: 'cpu.properties', line: at('cycle_time') + 1, column: 14 };
  const diagnostics = Number.isNaN(cycle)
    ? [{ code: 'PRJ904', severity: 'error', key: 'cpu_props_bad_value', message: '', params: { key: 'cycle_time', value: '', expected: '1 … 6000' }, span: where }]
    : cycle > 6000
      ? [
          {
            code: 'PRJ905',
            severity: 'error',
            key: 'cpu_props_out_of_range',
            message: `cycle_time = ${cycle}: must be from 1 to 6000.`,
            params: { key: 'cycle_time', value: String(cycle), low: 1, high: 6000 },
            span: where,
          },
        ]
      : [];
  return {
    properties: {
      profile: /profile = (S7-\d+)/.exec(text)?.[1] ?? 'S7-300',
      cycle_monitoring_time: 150,
      cycle_time: Number.isNaN(cycle) || cycle > 6000 ? 10 : cycle,
      clock_memory: clock === undefined ? null : Number(clock),
      retentive_markers: 16,
      retentive_timers: 0,
      retentive_counters: 8,
      startup: 'warm',
    },
    diagnostics,
  };
}

function OpenPage() {
  const { openSource, tabs } = useEditorTabs();
  useEffect(() => {
    openSource({ name: 'cpu.properties', language: 'cpu', text: TEXT, file: { projectId: 1, path: 'cpu.properties' }, version: 3 });
  }, [openSource]);
  const tab = tabs.find((item): item is SourceTab => item.kind === 'source');
  return tab ? <CpuPropertiesTab tab={tab} active /> : null;
}

/** The page opened in `language` over the fake server; returns the saves it makes, in order. */
function openWithServer(language: Language): Array<{ text: string; base_version: number | null }> {
  const saves: Array<{ text: string; base_version: number | null }> = [];
  mockServer({
    'POST /api/cpu-properties/check': (init) => json(check((JSON.parse(String(init?.body)) as { text: string }).text)),
    'PUT /api/projects/1/files/cpu.properties': (init) => {
      saves.push(JSON.parse(String(init?.body)));
      return json({ name: 'cpu.properties', language: 'cpu', size: 1, version: 4, created_at: '', updated_at: '' });
    },
    'GET /api/projects/1/files': () => json([]),
    'GET /api/projects/1/blocks': () => json({ blocks: [], diagnostics: [] }),
  });
  render(
    <I18nextProvider i18n={createI18n(language)}>
      <EditorTabsProvider>
        <OpenPage />
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return saves;
}

beforeEach(() => projectContents.clear());

describe('the CPU properties page', () => {
  it('shows a bad value with its problem and saves only good values, line by line', async () => {
    const saves = openWithServer('fa');
    const user = userEvent.setup();
    const cycle = (await screen.findByLabelText('زمان سیکل')) as HTMLInputElement;
    await waitFor(() => expect(cycle.value).toBe('10'));
    expect(screen.getByTestId('cpu-props').getAttribute('dir')).toBe('rtl');

    fireEvent.change(cycle, { target: { value: '9000' } }); // as a paste: one change
    const problem = await screen.findByTestId('cpu-props-problem-cycle_time');
    expect(problem.textContent).toContain('مقدار مجاز از 1 تا 6000');
    expect(cycle.value).toBe('9000'); // what the user typed stays, marked
    expect(cycle.getAttribute('aria-invalid')).toBe('true');
    await user.click(screen.getByTestId('cpu-props-save'));
    expect(saves).toEqual([]);

    fireEvent.change(cycle, { target: { value: '20' } });
    await waitFor(() => expect(screen.queryByTestId('cpu-props-problem-cycle_time')).toBeNull());
    await user.click(screen.getByTestId('cpu-props-save'));
    await waitFor(() => expect(saves.length).toBeGreaterThan(0));
    expect(saves.at(-1)).toEqual({ text: '# my CPU\ncycle_time = 20   # scan\nclock_memory = none\n', base_version: 3 });
    expect(screen.getByTestId('cpu-props-text').textContent).toBe(saves.at(-1)!.text);
  }, 30_000);

  it('offers the S7-1200/1500 family as a profile and saves it', async () => {
    const saves = openWithServer('en');
    const user = userEvent.setup();
    const profile = (await screen.findByLabelText('CPU family')) as HTMLSelectElement;
    expect([...profile.options].map((option) => option.textContent)).toEqual(['S7-300', 'S7-400', 'S7-1200/1500']);
    await user.selectOptions(profile, 'S7-1500');
    await waitFor(() => expect(profile.value).toBe('S7-1500'));
    await user.click(screen.getByTestId('cpu-props-save'));
    await waitFor(() => expect(saves.length).toBeGreaterThan(0));
    expect(saves.at(-1)!.text).toContain('profile = S7-1500');
  }, 30_000);
});
