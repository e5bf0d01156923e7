/**
 * The DB editor over a fake server and a fake monitoring socket: the declaration view and the
 * offline values of the compiled DB, the online column once the project's simulation runs (its
 * members watched as `DB10.path`), modify, and the links to the declarations in the source.
 */
import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { useEffect } from 'react';
import { I18nextProvider } from 'react-i18next';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { DbMembers } from '../../frontend/src/api/symbols';
import { CpuToolbar } from '../../frontend/src/cpu/CpuToolbar';
import { SessionProvider } from '../../frontend/src/cpu/SessionContext';
import { DbEditorView } from '../../frontend/src/dbeditor/DbEditorView';
import { EditorTabsProvider, useEditorTabs, type DbTab } from '../../frontend/src/editor/EditorTabsContext';
import { createI18n } from '../../frontend/src/i18n/setup';
import { ActiveProjectProvider, useActiveProject } from '../../frontend/src/projects/ActiveProject';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { json, mockServer } from './helpers';
import { FakeSocket, cpuState, frame, hello } from './monitorFakes';

const member = (path: string, type: string, extra: Partial<DbMembers['members'][number]> = {}) => ({
  path,
  name: path.split('.').at(-1)!,
  type,
  section: 'STAT' as const,
  depth: path.split('.').length - 1,
  offset: '0.0',
  initial: null,
  actual: null,
  comment: '',
  elementary: true,
  file: 'LevelControl.scl',
  line: null,
  ...extra,
});

const DB10: DbMembers = {
  kind: 'DB',
  number: 10,
  name: 'LevelData',
  file: 'LevelData.awl',
  line: 1,
  instance_of: 10,
  members: [
    member('Level', 'REAL', { section: 'IN', actual: '0.0', line: 12, comment: 'measured level' }),
    member('Limits', 'STRUCT', { elementary: false }),
    member('Limits.Low', 'REAL', { initial: '2.000000e+01', actual: '20.0', offset: '4.0' }),
    member('Starts', 'INT', { actual: '0', offset: '8.0' }),
  ],
};

const LEVEL_DATA = 'DATA_BLOCK "LevelData"\n"LevelControl"\nBEGIN\nEND_DATA_BLOCK\n';
const SCL = 'FUNCTION_BLOCK "LevelControl"\n'.padEnd(400, '\n');
const info = (name: string) => ({
  name,
  language: name.endsWith('.scl') ? 'scl' : 'stl',
  size: 1,
  version: 1,
  created_at: '2025-01-01T00:00:00Z',
  updated_at: '2025-01-01T00:00:00Z',
});

let sockets: FakeSocket[] = [];
const socket = () => sockets[sockets.length - 1]!;

function server() {
  return mockServer({
    'GET /api/projects/1/blocks/DB10/members': () => json(DB10),
    'GET /api/projects/1/files': () => json([info('LevelData.awl'), info('LevelControl.scl')]),
    'GET /api/projects/1/blocks': () => json({ blocks: [], diagnostics: [] }),
    'GET /api/projects/1/files/LevelData.awl': () => json({ ...info('LevelData.awl'), text: LEVEL_DATA }),
    'GET /api/projects/1/files/LevelControl.scl': () => json({ ...info('LevelControl.scl'), text: SCL }),
    'POST /api/projects/1/sessions': () =>
      json({ id: 's1', blocks: ['DB10'], cpu: cpuState(), clients: [], websocket: '/api/sessions/s1/ws' }, 201),
    'GET /api/sessions/s1/diagnostics': () => json([]),
    'DELETE /api/sessions/s1': () => new Response(null, { status: 204 }),
  });
}

function OpenDb() {
  const { setProjectId } = useActiveProject();
  const { openDb, tabs, activeId } = useEditorTabs();
  useEffect(() => {
    setProjectId(1);
    openDb({ projectId: 1, block: 'DB10', name: 'DB10 LevelData' });
  }, [setProjectId, openDb]);
  const db = tabs.find((tab): tab is DbTab => tab.kind === 'db');
  const source = tabs.find((tab) => tab.kind === 'source' && tab.id === activeId);
  return (
    <>
      {db ? <DbEditorView tab={db} active /> : null}
      <output data-testid="active-source">{source && source.kind === 'source' ? `${source.name}:${source.reveal?.line ?? ''}` : ''}</output>
    </>
  );
}

function renderDb() {
  const user = userEvent.setup();
  render(
    <I18nextProvider i18n={createI18n('en')}>
      <EditorTabsProvider>
        <ActiveProjectProvider>
          <SessionProvider>
            <CpuToolbar />
            <OpenDb />
          </SessionProvider>
        </ActiveProjectProvider>
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return { user };
}

const row = (path: string) => screen.getAllByTestId('db-row').find((item) => item.dataset.path === path)!;

beforeEach(() => {
  projectContents.clear();
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

describe('the DB editor', () => {
  it('shows the members nested, their initial and offline actual values, and the declaration view', async () => {
    server();
    const { user } = renderDb();
    await waitFor(() => expect(screen.getAllByTestId('db-row')).toHaveLength(4));
    expect(screen.getByRole('heading').textContent).toContain('DB10 "LevelData"');
    expect(screen.getByText('instance DB of FB10')).toBeTruthy();
    expect(within(row('Limits.Low')).getByTestId('db-initial').textContent).toBe('2.000000e+01');
    expect(within(row('Limits.Low')).getByTestId('db-actual').textContent).toBe('20.0');
    expect(row('Limits.Low').querySelector('td')!.style.paddingInlineStart).toBe('1.75rem');
    expect(screen.getByTestId('db-online-state').textContent).toContain('Offline');
    expect(screen.queryAllByTestId('db-online')).toHaveLength(0);
    await user.click(screen.getByTestId('db-view-declaration'));
    expect(row('Level').textContent).toContain('measured level');
    expect(screen.queryAllByTestId('db-actual')).toHaveLength(0);
  });

  it('watches the elementary members once the simulation runs, and modifies one', async () => {
    server();
    const { user } = renderDb();
    await waitFor(() => expect(screen.getAllByTestId('db-row')).toHaveLength(4));
    await user.click(screen.getByTestId('cpu-download'));
    await waitFor(() => expect(sockets).toHaveLength(1));
    act(() => {
      socket().open();
      socket().receive(hello(3));
      socket().receive(frame({ seq: 1, cpu: cpuState({ mode: 'RUN' }) }));
    });
    await waitFor(() => expect(screen.getByTestId('db-online-state').textContent).toContain('Online'));
    await waitFor(() => {
      const watch = socket().sent.filter((message) => message.type === 'watch').at(-1);
      expect(watch?.entries).toEqual(['DB10.Level', 'DB10.Limits.Low', 'DB10.Starts']);
    });
    act(() => {
      socket().receive(
        frame({
          seq: 2,
          watch: {
            'DB10.Level': { value: 42.5, forced: false, error: null },
            'DB10.Starts': { value: 3, forced: false, error: null },
          },
        }),
      );
    });
    expect(within(row('Level')).getByTestId('db-online').textContent).toBe('42.5');
    expect(within(row('Starts')).getByTestId('db-online').textContent).toBe('3');
    expect(within(row('Limits')).queryByTestId('db-modify')).toBeNull();
    await user.type(within(row('Starts')).getByTestId('db-modify-value'), '7');
    await user.click(within(row('Starts')).getByTestId('db-modify'));
    await waitFor(() =>
      expect(socket().sent.filter((message) => message.type === 'modify').at(-1)).toMatchObject({
        target: 'DB10.Starts',
        value: 7,
      }),
    );
  });

  it('opens the source at a declaration and at the DB header (Edit source)', async () => {
    server();
    const { user } = renderDb();
    await waitFor(() => expect(screen.getAllByTestId('db-row')).toHaveLength(4));
    await user.click(within(row('Level')).getByTestId('db-member-link'));
    await waitFor(() => expect(screen.getByTestId('active-source').textContent).toBe('LevelControl.scl:12'));
    expect(within(row('Starts')).queryByTestId('db-member-link')).toBeNull(); // no line known
    await user.click(screen.getByTestId('db-edit-source'));
    await waitFor(() => expect(screen.getByTestId('active-source').textContent).toBe('LevelData.awl:1'));
  });
});
