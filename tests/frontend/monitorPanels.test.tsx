/**
 * The CPU toolbar and the monitoring panels over a fake server (fetch) and a fake socket: the
 * download makes a session, commands go out on the socket, frames show in the I/O panel, the
 * watch table, the trend and the CPU diagnostic buffer, and errors appear translated.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect } from 'react';
import { I18nextProvider } from 'react-i18next';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { CpuStatus } from '../../frontend/src/cpu/CpuStatus';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { BottomPanel } from '../../frontend/src/panels/BottomPanel';
import { DiagnosticsList } from '../../frontend/src/panels/DiagnosticsList';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { apiError, json, mockServer, requestsOf } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

vi.mock('../../frontend/src/panels/TrendChart', () => ({
  default: ({ entries, samples }: { entries: readonly string[]; samples: readonly unknown[] }) => (
    <div data-testid="trend-plot" data-entries={entries.join(',')} data-samples={samples.length} />
  ),
}));

const OB1 = `ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A(    ;
      O     "Start";
      O     "Motor";
      )     ;
      A     "Stop";
      =     "Motor";
END_ORGANIZATION_BLOCK
`;
const SYMBOLS = `"Start","I 0.0","BOOL","start push button"
"Stop","I 0.1","BOOL","stop push button, NC"
"Motor","Q 4.0","BOOL","motor contactor"
`;

const fileInfo = (name: string, version = 1) => ({
  name,
  language: name.endsWith('.sdf') ? 'symbols' : name.endsWith('.vat') ? 'watch' : 'stl',
  size: 1,
  version,
  created_at: '2025-01-01T00:00:00Z',
  updated_at: '2025-01-01T00:00:00Z',
});

const SESSION = { id: 's1', blocks: ['OB1'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' };

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;

/** The watch table files the panel saves, by name, with their text and version. */
let tables = new Map<string, { text: string; version: number }>();

function server(overrides: Record<string, (init: RequestInit | undefined) => Response | Promise<Response>> = {}) {
  tables = new Map();
  const table = (name: string) => ({
    [`PUT /api/projects/1/files/${name}`]: (init: RequestInit | undefined) => {
      const text = (JSON.parse(String(init?.body)) as { text: string }).text;
      const version = (tables.get(name)?.version ?? 0) + 1;
      tables.set(name, { text, version });
      return json({ ...fileInfo(name, version), text }, version === 1 ? 201 : 200);
    },
    [`GET /api/projects/1/files/${name}`]: () => json({ ...fileInfo(name, tables.get(name)!.version), text: tables.get(name)!.text }),
  });
  return mockServer({
    ...table('VAT_1.vat'),
    'POST /api/projects/1/sessions': () => json(SESSION, 201),
    'GET /api/projects/1/files': () => json([fileInfo('OB1.awl'), fileInfo('symbols.sdf')]),
    'GET /api/projects/1/files/OB1.awl': () => json({ ...fileInfo('OB1.awl'), text: OB1 }),
    'GET /api/projects/1/files/symbols.sdf': () => json({ ...fileInfo('symbols.sdf'), text: SYMBOLS }),
    'GET /api/sessions/s1/diagnostics': () => json([]),
    'PUT /api/sessions/s1/program': () => json({ changed: ['OB1'] }),
    'DELETE /api/sessions/s1': () => new Response(null, { status: 204 }),
    ...overrides,
  });
}

function ChooseProject({ id }: { id: number | null }) {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(id), [id, setProjectId]);
  return null;
}

function renderMonitor({ project = 1, language = 'en' }: { project?: number | null; language?: Language } = {}) {
  const user = userEvent.setup();
  const i18n = createI18n(language);
  const view = render(
    <I18nextProvider i18n={i18n}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <ChooseProject id={project} />
          <SessionProvider>
            <CpuToolbar />
            <BottomPanel />
            <CpuStatus />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return { user, i18n, ...view };
}

/** Downloads, connects the fake socket and answers its first messages. */
async function downloadAndConnect(user: ReturnType<typeof userEvent.setup>, cpu = cpuState()) {
  await user.click(screen.getByTestId('cpu-download'));
  await waitFor(() => expect(sockets).toHaveLength(1));
  act(() => {
    socket().open();
    socket().receive(hello(3));
    socket().receive(frame({ seq: 1, cpu }));
  });
}

const messages = (type: string) => socket().sent.filter((message) => message.type === type);

beforeEach(() => {
  sockets = [];
  vi.stubGlobal(
    'WebSocket',
    class extends FakeSocket {
      constructor(url: string) {
        super(url);
        sockets.push(this);
      }
    },
  );
});

afterEach(() => {
  sockets = [];
});

describe('CPU toolbar', () => {
  it('downloads the active project into a new session and connects its socket on this host', async () => {
    const fetchMock = server();
    const { user } = renderMonitor();
    expect(screen.getByTestId('cpu-state').textContent).toBe('No program downloaded');
    expect((screen.getByTestId('cpu-run') as HTMLButtonElement).disabled).toBe(true);
    await downloadAndConnect(user);
    expect(requestsOf(fetchMock)).toContain('POST /api/projects/1/sessions');
    expect(socket().url).toMatch(/^ws:\/\/[^/]+\/api\/sessions\/s1\/ws$/);
    expect(screen.getByTestId('cpu-state').getAttribute('data-mode')).toBe('stop');
    expect(screen.getByTestId('cpu-status').textContent).toContain('STOP');
    expect(messages('subscribe_cpu')).toHaveLength(1);

    await user.click(screen.getByTestId('cpu-run'));
    expect(messages('run')).toHaveLength(1);
    act(() => {
      socket().ackAll();
      socket().receive(
        frame({ seq: 2, cpu: cpuState({ mode: 'RUN', scans: 42, time_ms: 420, cycle: { last_ms: 0.05, min_ms: 0.04, max_ms: 0.2, avg_ms: 0.06 } }) }),
      );
    });
    expect(screen.getByTestId('cpu-state').getAttribute('data-mode')).toBe('run');
    expect(screen.getByTestId('cpu-scans').textContent).toBe('Scans 42');
    expect(screen.getByTestId('cpu-time').textContent).toBe('Time 0.420 s');
    expect(screen.getByTestId('cpu-cycle').textContent).toBe('Cycle 0.060 ms');
    expect((screen.getByTestId('cpu-run') as HTMLButtonElement).disabled).toBe(true);

    await user.click(screen.getByTestId('cpu-stop'));
    await user.click(screen.getByTestId('cpu-restart'));
    await user.click(screen.getByTestId('cpu-step'));
    expect(socket().sent.slice(-3).map(({ type, ...rest }) => ({ type, cold: rest.cold, by: rest.by }))).toEqual([
      { type: 'stop', cold: undefined, by: undefined },
      { type: 'restart', cold: false, by: undefined },
      { type: 'step', cold: undefined, by: 'scan' },
    ]);
  });

  it('downloads with Ctrl+B, and into the running session with PUT program in STOP', async () => {
    const fetchMock = server();
    const { user } = renderMonitor();
    await user.keyboard('{Control>}b{/Control}');
    await waitFor(() => expect(sockets).toHaveLength(1));
    act(() => {
      socket().open();
      socket().receive(hello());
      socket().receive(frame({ seq: 1, cpu: cpuState() }));
    });
    await user.keyboard('{Control>}b{/Control}');
    await waitFor(() => expect(requestsOf(fetchMock)).toContain('PUT /api/sessions/s1/program'));
    const put = fetchMock.mock.calls.find(([, init]) => init?.method === 'PUT')!;
    expect(JSON.parse(String(put[1]!.body))).toEqual({
      sources: [
        { name: 'OB1.awl', text: OB1 },
        { name: 'symbols.sdf', text: SYMBOLS },
      ],
    });
    expect(sockets).toHaveLength(1);
  });

  it('offers instruction, statement and network steps while the CPU holds, and continue', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    const stepBy = screen.getByTestId('cpu-step-by') as HTMLSelectElement;
    expect([...stepBy.options].filter((option) => !option.disabled).map((option) => option.value)).toEqual(['scan']);
    expect((screen.getByTestId('cpu-continue') as HTMLButtonElement).disabled).toBe(true);
    act(() => socket().receive(frame({ seq: 2, cpu: cpuState({ mode: 'HOLD' }) })));
    expect(screen.getByTestId('cpu-state').getAttribute('data-mode')).toBe('hold');
    expect([...stepBy.options].every((option) => !option.disabled)).toBe(true);
    await user.selectOptions(stepBy, 'instruction');
    await user.click(screen.getByTestId('cpu-step'));
    expect(messages('step').at(-1)).toMatchObject({ by: 'instruction' });
    await user.click(screen.getByTestId('cpu-continue'));
    expect(messages('continue')).toHaveLength(1);
  });

  it('sets the time mode and the cycle time', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.selectOptions(screen.getByTestId('cpu-time-mode'), 'fast');
    expect(messages('set_time').at(-1)).toMatchObject({ mode: 'fast', cycle_ms: null });
    const cycle = screen.getByTestId('cpu-cycle-ms');
    await user.clear(cycle);
    await user.type(cycle, '25{Enter}');
    expect(messages('set_time').at(-1)).toMatchObject({ mode: 'virtual', cycle_ms: 25 });
  });

  it('shows a compile error of the download translated, with its code', async () => {
    server({
      'POST /api/projects/1/sessions': () =>
        apiError(422, 'MON611', 'mon_program_has_errors', 'The program does not compile: 1 error(s); the first is OB1.awl:3:7', {
          count: 1,
          first: 'OB1.awl:3:7: STL101',
        }),
    });
    const { user, i18n } = renderMonitor({ language: 'fa' });
    await user.click(screen.getByTestId('cpu-download'));
    const problem = await screen.findByTestId('cpu-problem');
    expect(problem.getAttribute('role')).toBe('alert');
    expect(problem.textContent).toContain('MON611');
    expect(problem.textContent).toContain(
      i18n.t('problems.mon_program_has_errors', { count: 1, first: 'OB1.awl:3:7: STL101' }),
    );
    expect(sockets).toHaveLength(0);
    await user.click(within(problem).getByRole('button'));
    expect(screen.queryByTestId('cpu-problem')).toBeNull();
  });

  it('shows a refused command with the catalogue text', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.click(screen.getByTestId('cpu-step'));
    const ref = messages('step')[0]!.ref;
    act(() =>
      socket().receive({
        type: 'error',
        ref,
        code: 'MON607',
        key: 'mon_not_now',
        message: 'A single step is not possible now: the CPU is in STOP',
        params: { action: 'A single step', reason: 'the CPU is in STOP' },
      }),
    );
    expect((await screen.findByTestId('cpu-problem')).textContent).toContain(
      'MON607A single step is not possible now: the CPU is in STOP',
    );
  });

  it('keeps Download disabled until a project is chosen', () => {
    server();
    renderMonitor({ project: null });
    expect((screen.getByTestId('cpu-download') as HTMLButtonElement).disabled).toBe(true);
  });
});

describe('I/O panel', () => {
  it('shows the bytes the program uses (IB0 switches, QB4 lamps, all on request), switches inputs and forces bits', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.click(screen.getByTestId('panel-tab-io'));
    await waitFor(() => expect(screen.getByRole('group', { name: 'QB4' })).toBeTruthy());
    expect(screen.queryByRole('group', { name: 'QB5' })).toBeNull();
    expect(screen.queryByRole('group', { name: 'IB3' })).toBeNull();
    await waitFor(() => expect(messages('watch').length).toBeGreaterThan(0));
    expect(messages('watch').at(-1)!.entries).toEqual(['PIB0', 'QB4']);
    // The symbols stand beside their bits.
    expect(screen.getByTestId('io-symbol-Q4.0').textContent).toBe('Motor');
    await user.click(screen.getByTestId('io-show-all'));
    expect(screen.getByRole('group', { name: 'IB3' })).toBeTruthy();
    await waitFor(() =>
      expect(messages('watch').at(-1)!.entries).toEqual(['PIB0', 'PIB1', 'PIB2', 'PIB3', 'QB0', 'QB1', 'QB2', 'QB3', 'QB4']),
    );

    act(() =>
      socket().receive(
        frame({
          seq: 2,
          watch: { PIB0: { value: 2, forced: false, error: null }, QB4: { value: 1, forced: false, error: null } },
        }),
      ),
    );
    const stop = screen.getByRole('switch', { name: 'I0.1 Stop' });
    expect(stop.getAttribute('aria-checked')).toBe('true');
    expect(screen.getByTestId('io-I0.0').getAttribute('aria-checked')).toBe('false');
    expect(screen.getByTestId('io-Q4.0').getAttribute('data-state')).toBe('on');
    expect(screen.getByRole('img', { name: 'Q4.0 Motor: on' })).toBeTruthy();
    expect(screen.getByTestId('io-Q4.1').getAttribute('data-state')).toBe('off');

    await user.click(screen.getByTestId('io-I0.0'));
    expect(messages('set_input').at(-1)).toMatchObject({ address: 'I0.0', value: true });
    await user.click(screen.getByTestId('io-force-I0.1'));
    expect(messages('force').at(-1)).toMatchObject({ address: 'I0.1', value: true });

    act(() => socket().receive(frame({ seq: 3, cpu: cpuState({ mode: 'RUN', forced: [{ address: 'I0.1', value: 1 }] }) })));
    expect(screen.getByTestId('io-forced-I0.1')).toBeTruthy();
    expect(screen.getByTestId('io-force-I0.1').getAttribute('aria-pressed')).toBe('true');
    // A forced switch changes the forced value; F again removes the force.
    await user.click(stop);
    expect(messages('force').at(-1)).toMatchObject({ address: 'I0.1', value: false });
    await user.click(screen.getByTestId('io-force-I0.1'));
    expect(messages('unforce').at(-1)).toMatchObject({ address: 'I0.1' });
  });
});

describe('watch table', () => {
  it('is a real table with the five column headers, an actions column and an empty row', async () => {
    server();
    const { user } = renderMonitor();
    await user.click(screen.getByTestId('panel-tab-watch'));
    const table = await screen.findByTestId('watch-table');
    const headers = within(table).getAllByRole('columnheader').map((th) => th.textContent);
    expect(headers).toEqual(['Address', 'Symbol', 'Display format', 'Monitor value', 'Modify value', 'Actions']);
    const rows = within(table).getAllByRole('row');
    expect(rows).toHaveLength(2);
    expect(rows[1]!.textContent).toContain('add an address or a symbol');
    expect(rows[1]!.querySelector('td')!.colSpan).toBe(6);
  });

  it('adds entries, shows values in the chosen format, modifies, forces, and shows errors', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.click(screen.getByTestId('panel-tab-watch'));
    for (const entry of ['"Motor"', 'MW10', 'MW99999']) {
      await user.type(screen.getByTestId('watch-add-entry'), entry);
      await user.click(screen.getByTestId('watch-add'));
    }
    // The table's entries join the I/O panel's in the one watch list of this socket.
    const tableEntries = () => (messages('watch').at(-1)!.entries as string[]).filter((entry) => !/^(PIB|QB)\d$/.test(entry));
    await waitFor(() => expect(tableEntries()).toEqual(['"Motor"', 'MW10', 'MW99999']));
    await act(async () => {
      socket().ackAll({
        watch: {
          entries: [
            { entry: '"Motor"', type: 'BOOL' },
            { entry: 'MW10', type: 'WORD' },
            { entry: 'MW99999', code: 'MON603', error: 'MW99999: the S7-300 has MB0 to MB2047' },
          ],
        },
      });
      socket().receive(
        frame({
          seq: 2,
          watch: {
            '"Motor"': { value: true, forced: true, error: null },
            MW10: { value: 0x1234, forced: false, error: null },
            MW99999: { value: null, forced: false, error: 'MW99999: the S7-300 has MB0 to MB2047' },
          },
        }),
      );
    });
    const rows = screen.getAllByTestId('watch-row');
    const [motor, word, bad] = rows as [HTMLElement, HTMLElement, HTMLElement];
    expect(within(motor).getByTestId('watch-value').textContent).toBe('TRUE');
    expect(within(motor).getByTestId('watch-forced')).toBeTruthy();
    // The symbol table names the address of a symbol, and the symbol of an address.
    expect(motor.textContent).toContain('Q4.0');
    expect(within(word).getByTestId('watch-value').textContent).toBe('W#16#1234');
    await user.selectOptions(within(word).getByTestId('watch-format'), 'dec');
    expect(within(word).getByTestId('watch-value').textContent).toBe('4660');
    await user.selectOptions(within(word).getByTestId('watch-format'), 'bin');
    expect(within(word).getByTestId('watch-value').textContent).toBe('2#0001_0010_0011_0100');
    expect(within(bad).getByTestId('watch-error').textContent).toContain('MON603');
    expect(within(bad).queryByTestId('watch-value')).toBeNull();

    await user.type(within(word).getByTestId('watch-modify-value'), '16#FF');
    await user.click(within(word).getByTestId('watch-modify'));
    expect(messages('modify').at(-1)).toMatchObject({ target: 'MW10', value: '16#FF' });
    // Only inputs and outputs can be forced: the memory word has no force button.
    expect(within(word).queryByTestId('watch-force')).toBeNull();
    await user.click(within(motor).getByTestId('watch-unforce'));
    expect(messages('unforce').at(-1)).toMatchObject({ address: '"Motor"' });

    await user.click(within(bad).getByTestId('watch-remove'));
    expect(screen.getAllByTestId('watch-row')).toHaveLength(2);
    await waitFor(() => expect(tableEntries()).toEqual(['"Motor"', 'MW10']));
    // The rows are kept in the project, in its first watch table file.
    await waitFor(() => {
      const rows = tables.get('VAT_1.vat')!.text.split('\n').filter((line) => line.trim() && !line.startsWith('//'));
      expect(rows.map((line) => line.split('|').map((cell) => cell.trim()).slice(0, 2))).toEqual([
        ['"Motor"'],
        ['MW10', 'BIN'],
      ]);
    });
  });
});

describe('trend', () => {
  it('records the chosen entries, plots their samples and links the CSV of this client', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.click(screen.getByTestId('panel-tab-trend'));
    await user.type(screen.getByTestId('trend-add-entry'), 'Q4.0');
    await user.click(screen.getByTestId('trend-add'));
    await waitFor(() => expect(messages('trend').at(-1)).toMatchObject({ entries: ['Q4.0'] }));
    act(() => {
      socket().ackAll({ trend: { entries: [{ entry: 'Q4.0', type: 'BOOL' }] } });
    });
    act(() =>
      socket().receive(
        frame({
          seq: 2,
          trend: [
            { scan: 1, time_ms: 10, values: [false] },
            { scan: 2, time_ms: 20, values: [true] },
          ],
        }),
      ),
    );
    const plot = await screen.findByTestId('trend-plot');
    expect(plot.getAttribute('data-samples')).toBe('2');
    expect(plot.getAttribute('data-entries')).toBe('Q4.0');
    expect(screen.getByTestId('trend-export').getAttribute('href')).toBe('/api/sessions/s1/trend.csv?client=3');
  });

  it('drops an entry the server cannot record and says why', async () => {
    server();
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await user.click(screen.getByTestId('panel-tab-trend'));
    await user.type(screen.getByTestId('trend-add-entry'), 'XY9');
    await user.click(screen.getByTestId('trend-add'));
    await waitFor(() => expect(messages('trend')).toHaveLength(1));
    act(() =>
      socket().receive({
        type: 'error',
        ref: messages('trend')[0]!.ref,
        code: 'MON603',
        key: 'mon_unknown_target',
        message: 'XY9: not an address',
        params: { target: 'XY9', reason: 'not an address' },
      }),
    );
    expect((await screen.findByRole('alert')).textContent).toContain('XY9: not an address');
    await waitFor(() => expect(screen.queryAllByTestId('trend-entry')).toHaveLength(0));
  });
});

describe('CPU diagnostic buffer', () => {
  it('lists the entries of the frames, newest first, with block, network and line', async () => {
    server({
      'GET /api/sessions/s1/diagnostics': () =>
        json([
          { time_ms: 10, code: 'SIM527', message: 'Stopped in a hold', block: null, network: null, line: null, key: '', params: {} },
        ]),
    });
    const { user } = renderMonitor();
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    await waitFor(() => expect(screen.getAllByTestId('cpu-diagnostic')).toHaveLength(1));
    act(() =>
      socket().receive(
        frame({
          seq: 2,
          diagnostics: [
            {
              time_ms: 1500,
              code: 'SIM501',
              message: 'Cycle time exceeded the watchdog of 150 ms.',
              block: 'OB1',
              network: 2,
              line: 7,
              key: 'sim_watchdog',
              params: { limit_ms: 150 },
            },
          ],
        }),
      ),
    );
    const entries = screen.getAllByTestId('cpu-diagnostic');
    expect(entries).toHaveLength(2);
    expect(entries[0]!.textContent).toContain('SIM501');
    expect(entries[0]!.textContent).toContain('OB1 NW 2 L 7 · 1.500 s');
    expect(entries[1]!.textContent).toContain('SIM527');
    // Without a key the server's English text shows; with one, the catalogue's text.
    expect(entries[1]!.textContent).toContain('Stopped in a hold');
  });

  it('says each entry in the interface language from its key and params', async () => {
    server();
    const { user } = renderMonitor({ language: 'fa' });
    await downloadAndConnect(user, cpuState({ mode: 'RUN' }));
    act(() =>
      socket().receive(
        frame({
          seq: 2,
          diagnostics: [
            {
              time_ms: 20,
              code: 'SIM503',
              message: 'Area length error reading MW 6.',
              block: 'OB1',
              network: 1,
              line: 3,
              key: 'sim_area_length_read',
              params: { address: 'MW 6' },
            },
          ],
        }),
      ),
    );
    const entry = await screen.findByTestId('cpu-diagnostic');
    const persian = createI18n('fa').t('problems.sim_area_length_read', { address: 'MW 6' });
    expect(persian).not.toContain('Area length');
    expect(entry.textContent).toContain(persian);
  });
});

describe('diagnostics list with the project’s compiler diagnostics', () => {
  it('shows them after the reported ones and opens a diagnostic’s file at its line', async () => {
    const user = userEvent.setup();
    const onOpen = vi.fn(() => true);
    const diagnostic = {
      code: 'STL101',
      severity: 'error' as const,
      key: 'unknown_instruction',
      message: 'Unknown instruction',
      params: {},
      span: { file: 'OB1.awl', line: 3, column: 7 },
    };
    render(
      <I18nextProvider i18n={createI18n('en')}>
        <DiagnosticsList project={[diagnostic, { ...diagnostic, code: 'API106', span: null }]} onOpen={onOpen} />
      </I18nextProvider>,
    );
    expect(screen.getAllByTestId('diagnostic')).toHaveLength(2);
    const open = screen.getByRole('button', { name: 'Go to OB1.awl:3:7' });
    await user.click(open);
    expect(onOpen).toHaveBeenCalledWith(diagnostic);
    expect(screen.getAllByTestId('diagnostic-open')).toHaveLength(1);
  });
});
