/**
 * The debug panel (Call stack tab) over a fake socket: empty while the CPU runs; at a hold the
 * call stack innermost first (a click opens the place), the locals and the registers, in the
 * interface language.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect } from 'react';
import { I18nextProvider } from 'react-i18next';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { HoldState } from '../../frontend/src/api/monitor';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { EditorTabsProvider, useEditorTabs } from '../../frontend/src/editor/EditorTabsContext';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { BottomPanel } from '../../frontend/src/panels/BottomPanel';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { json, mockServer, requestsOf } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

const SESSION = { id: 's1', blocks: ['OB1', 'FC10'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' };
const file = (name: string, text: string) => ({
  name,
  language: name.endsWith('.scl') ? 'scl' : 'stl',
  size: text.length,
  version: 1,
  created_at: '2025-01-01T00:00:00Z',
  updated_at: '2025-01-01T00:00:00Z',
  text,
});

const HOLD: HoldState = {
  reason: 'breakpoint',
  breakpoint: 1,
  location: { block: 'FC10', instruction: 0, line: 17, file: 'Scale.scl', network: 1 },
  registers: { accu1: 0xffffffff, accu2: 5, ar1: 16, ar2: 0, stw: 0x104, rlo: 0, sta: 1 },
  locals: [
    { name: 'Raw', type: 'INT', value: 13824 },
    { name: 'High', type: 'REAL', value: 100.5 },
    { name: 'On', type: 'BOOL', value: true },
  ],
  call_stack: [
    { block: 'FC10', instruction: 0, line: 17, file: 'Scale.scl', network: 1 },
    { block: 'OB1', instruction: 4, line: 14, file: 'OB1.awl', network: 1 },
  ],
  graph_step: null,
  graph_block: null,
};

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;

function ChooseProject() {
  const { setProjectId } = useActiveProject();
  useEffect(() => setProjectId(1), [setProjectId]);
  return null;
}

/** The open tabs' names, to see what the panel opened. */
function TabNames() {
  const { tabs, activeId } = useEditorTabs();
  return <p data-testid="tab-names">{tabs.map((tab) => `${tab.kind === 'source' ? tab.name : tab.id}${tab.id === activeId ? '*' : ''}`).join(',')}</p>;
}

function renderPanel(language: Language = 'en') {
  const user = userEvent.setup();
  render(
    <I18nextProvider i18n={createI18n(language)}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <ChooseProject />
          <SessionProvider>
            <CpuToolbar />
            <BottomPanel />
            <TabNames />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return user;
}

async function connect(user: ReturnType<typeof userEvent.setup>) {
  await user.click(screen.getByTestId('cpu-download'));
  await waitFor(() => expect(sockets).toHaveLength(1));
  act(() => {
    socket().open();
    socket().receive(hello());
    socket().receive(frame({ seq: 1, cpu: cpuState({ mode: 'RUN' }) }));
  });
}

let fetchMock: ReturnType<typeof mockServer>;

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
  fetchMock = mockServer({
    'POST /api/projects/1/sessions': () => json(SESSION, 201),
    'GET /api/projects/1/files': () => json([]),
    'GET /api/projects/1/files/Scale.scl': () => json(file('Scale.scl', 'FUNCTION "Scale" : REAL\n')),
    'GET /api/projects/1/files/OB1.awl': () => json(file('OB1.awl', 'ORGANIZATION_BLOCK OB 1\n')),
    'GET /api/sessions/s1/diagnostics': () => json([]),
  });
});

describe('the debug panel', () => {
  it('says the CPU is not holding', async () => {
    const user = renderPanel();
    await user.click(screen.getByTestId('panel-tab-debug'));
    const panel = screen.getByTestId('debug-panel');
    expect(panel.dataset.holding).toBe('false');
    expect(panel.textContent).toContain('The CPU is not holding');
  });

  it('shows the call stack, the locals and the registers of a hold, and opens the held file', async () => {
    const user = renderPanel();
    await connect(user);
    act(() => socket().receive(frame({ seq: 2, cpu: cpuState({ mode: 'HOLD' }), hold: HOLD })));
    const panel = screen.getByTestId('debug-panel');
    expect(screen.getByTestId('panel-tab-debug').getAttribute('aria-selected')).toBe('true');
    expect(panel.textContent).toContain('Held at a breakpoint: FC10 · NW 1 · L 17');
    expect(within(panel).getAllByRole('button').map((button) => button.textContent)).toEqual([
      'FC10 · NW 1 · L 17Scale.scl:17',
      'OB1 · NW 1 · L 14OB1.awl:14',
    ]);
    expect(within(screen.getByTestId('debug-local-Raw')).getByTestId('debug-local-value').textContent).toBe('13824');
    expect(screen.getByTestId('debug-local-High').textContent).toBe('HighREAL100.5');
    expect(screen.getByTestId('debug-local-On').textContent).toBe('OnBOOLTRUE');
    expect(screen.getByTestId('debug-register-ACCU1').textContent).toBe('ACCU116#FFFF_FFFF  (-1)');
    expect(screen.getByTestId('debug-register-AR1').textContent).toBe('AR1P#2.0');
    expect(screen.getByTestId('debug-register-STW').textContent).toBe('STW100000100');

    // The hold opened the held file; a click on the caller opens its file at the line.
    await waitFor(() => expect(screen.getByTestId('tab-names').textContent).toBe('start,Scale.scl*'));
    await user.click(screen.getByTestId('debug-frame-1'));
    await waitFor(() => expect(screen.getByTestId('tab-names').textContent).toBe('start,Scale.scl,OB1.awl*'));
    expect(requestsOf(fetchMock)).toContain('GET /api/projects/1/files/OB1.awl');

    act(() => socket().receive(frame({ seq: 3, cpu: cpuState({ mode: 'RUN' }), released: true })));
    expect(screen.getByTestId('debug-panel').dataset.holding).toBe('false');
  });

  it('speaks Arabic, with code left to right', async () => {
    const user = renderPanel('ar');
    await connect(user);
    act(() => socket().receive(frame({ seq: 2, cpu: cpuState({ mode: 'HOLD' }), hold: { ...HOLD, reason: 'step', locals: [] } })));
    const panel = screen.getByTestId('debug-panel');
    expect(panel.textContent).toContain('متوقفة بعد خطوة');
    expect(panel.textContent).toContain('لا توجد متغيرات محلية');
    expect(screen.getByTestId('debug-register-ACCU2').querySelector('dd')!.getAttribute('dir')).toBe('ltr');
  });
});
