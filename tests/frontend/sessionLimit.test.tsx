/**
 * "Close one first" (MON610): the sessions on the server are listed with their project, CPU
 * mode and age; Close removes one and the list follows; the download can be tried again.
 */
import { render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { afterEach, describe, expect, it, vi } from 'vitest';
import type { SessionOut } from '../../frontend/src/api/sessions';
import { SessionLimit } from '../../frontend/src/cpu/SessionLimit';
import { createI18n } from '../../frontend/src/i18n/setup';
import { json, mockServer, requestsOf } from './helpers';
import { cpuState } from './monitorFakes';

function session(id: string, project: string | null, mode: 'RUN' | 'STOP', age: number, clients: number[] = []): SessionOut {
  return {
    id,
    blocks: ['OB1'],
    cpu: cpuState({ mode }),
    clients,
    websocket: `/api/sessions/${id}/ws`,
    project_id: project === null ? null : 1,
    project_name: project,
    profile: 'S7-300',
    started_at: '2026-01-01T10:00:00Z',
    age_seconds: age,
  };
}

afterEach(() => vi.unstubAllGlobals());

describe('the session list offered at the session limit', () => {
  it('lists every session with its project, mode and age, closes one and retries', async () => {
    let running = [session('a1', 'Mixer line', 'RUN', 300, [4]), session('b2', null, 'STOP', 7200)];
    const fetchMock = mockServer({
      'GET /api/sessions': () => json(running),
      'DELETE /api/sessions/a1': () => {
        running = running.filter((item) => item.id !== 'a1');
        return new Response(null, { status: 204 });
      },
    });
    const retry = vi.fn();
    render(
      <I18nextProvider i18n={createI18n('en')}>
        <SessionLimit onRetry={retry} />
      </I18nextProvider>,
    );
    const rows = await screen.findAllByTestId('session-row');
    expect(rows.map((row) => row.textContent)).toEqual([
      expect.stringMatching(/Mixer line.*S7-300 · RUN.*5 minutes ago.*1 open/),
      expect.stringMatching(/\(program without a project\).*STOP.*2 hours ago.*0 open/),
    ]);
    const user = userEvent.setup();
    await user.click(within(rows[0]!).getByRole('button', { name: 'Close the simulation of Mixer line' }));
    await waitFor(() => expect(screen.getAllByTestId('session-row')).toHaveLength(1));
    expect(requestsOf(fetchMock)).toContain('DELETE /api/sessions/a1');
    await user.click(screen.getByRole('button', { name: 'Download again' }));
    expect(retry).toHaveBeenCalledTimes(1);
  }, 15_000);
});
