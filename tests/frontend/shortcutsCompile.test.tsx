/**
 * Compile (Ctrl+F7 and the toolbar's button): unsaved editor text is saved first, the whole
 * project is checked again (`/blocks`), the Diagnostics panel comes forward and the result is
 * announced in the status bar's live region.
 */
import { act, screen, waitFor, within } from '@testing-library/react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import { countProblems } from '../../frontend/src/app/compile';
import type { Diagnostic } from '../../frontend/src/api/types';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { fake } from './fakeMonaco';
import { apiError, makeProject, renderApp } from './helpers';
import { block, projectServer, type FakeProject } from './projectServer';

vi.mock('../../frontend/src/editor/monaco/load', () => import('./fakeMonaco'));

const OB1 = 'ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n      A     I 0.0;\nEND_ORGANIZATION_BLOCK\n';

function problem(severity: Diagnostic['severity'], line: number): Diagnostic {
  return {
    code: severity === 'error' ? 'STL201' : 'STL301',
    severity,
    key: 'stl_unknown_instruction',
    message: 'Unknown instruction XYZ.',
    params: { mnemonic: 'XYZ', hint: '' },
    span: { file: 'OB1.awl', line, column: 7, end_line: null, end_column: null },
  };
}

/** The saved OB1 has one error per XYZ line and one warning per WARN line. */
function project(): FakeProject {
  const p: FakeProject = {
    project: makeProject(1, 'Motor'),
    files: new Map([['OB1.awl', { text: OB1, version: 1 }]]),
    blocks: [block('OB', 1, 'Main', 'OB1.awl', 1)],
    diagnostics: () => {
      const lines = p.files.get('OB1.awl')!.text.split('\n');
      return lines.flatMap((line, index) => [
        ...(line.includes('XYZ') ? [problem('error', index + 1)] : []),
        ...(line.includes('WARN') ? [problem('warning', index + 1)] : []),
      ]);
    },
  };
  return p;
}

const tree = () => screen.getByTestId('block-tree');

async function openProject() {
  const server = projectServer([project()]);
  const view = renderApp();
  const node = await within(tree()).findByRole('treeitem', { name: 'Motor' });
  await view.user.click(node.firstElementChild as HTMLElement);
  await within(tree()).findByTestId('file-node-1-OB1.awl');
  return { server, ...view };
}

const blocksRequests = (requests: string[]) => requests.filter((r) => r === 'GET /api/projects/1/blocks').length;

beforeEach(() => {
  projectContents.clear();
  fake.reset();
});

describe('compile', () => {
  it('counts errors and warnings', () => {
    expect(countProblems([problem('error', 1), problem('warning', 2), problem('warning', 3), { ...problem('info', 4) }])).toEqual({
      errors: 1,
      warnings: 2,
    });
  });

  it('is disabled until a project is selected', async () => {
    projectServer([project()]);
    renderApp();
    const button = screen.getByTestId('cpu-compile') as HTMLButtonElement;
    expect(button.disabled).toBe(true);
    expect(button.getAttribute('aria-keyshortcuts')).toMatch(/F7/);
    expect(button.title).toContain('Select a project in the project tree first.');
  });

  it('saves the open editor first, checks the project and shows the Diagnostics panel (Ctrl+F7)', async () => {
    const { user, server } = await openProject();
    await user.dblClick(within(screen.getByTestId('file-node-1-OB1.awl')).getByText('OB1.awl'));
    await waitFor(() => expect(fake.editors).toHaveLength(1));
    const model = fake.editors[0]!.getModel();
    await user.click(screen.getByTestId('panel-tab-watch'));
    expect(screen.getByTestId('panel-tab-diagnostics').getAttribute('aria-selected')).toBe('false');
    const before = blocksRequests(server.requests());

    act(() => model.type('      XYZ   1; // WARN\n'));
    await user.keyboard('{Control>}{F7}{/Control}');

    const status = screen.getByTestId('compile-status');
    await waitFor(() => expect(status.textContent).toBe('Compiled — errors: 1, warnings: 1'));
    expect(status.getAttribute('role')).toBe('status');
    expect(status.dataset.state).toBe('errors');
    // Saved before the check: the server compiled the new text.
    const requests = server.requests();
    expect(blocksRequests(requests)).toBe(before + 1);
    expect(requests.indexOf('PUT /api/projects/1/files/OB1.awl')).toBeLessThan(requests.lastIndexOf('GET /api/projects/1/blocks'));
    expect(server.saves.at(-1)!.text).toContain('XYZ');
    expect(screen.getByTestId('panel-tab-diagnostics').getAttribute('aria-selected')).toBe('true');
    const list = screen.getByTestId('diagnostics');
    expect(within(list).getAllByTestId('diagnostic').map((row) => row.querySelector('code')!.textContent)).toEqual(['STL201', 'STL301']);
  });

  it('compiles from the toolbar button; a clean project says so', async () => {
    const { user, server } = await openProject();
    await user.click(screen.getByTestId('cpu-compile'));
    await waitFor(() => expect(screen.getByTestId('compile-status').textContent).toBe('Compiled — errors: 0, warnings: 0'));
    expect(screen.getByTestId('compile-status').dataset.state).toBe('ok');
    expect(blocksRequests(server.requests())).toBe(2);
  });

  it('reports a check the server could not do, with its code', async () => {
    const { user, server } = await openProject();
    const answer = server.fetch.getMockImplementation()!;
    server.fetch.mockImplementation(async (input, init) =>
      String(input) === '/api/projects/1/blocks'
        ? apiError(500, 'API500', 'internal_error', 'Something broke on the server.')
        : answer(input, init),
    );
    await user.click(screen.getByTestId('cpu-compile'));
    await waitFor(() => expect(screen.getByTestId('compile-status').textContent).toContain('API500'));
    expect(screen.getByTestId('cpu-problem').textContent).toContain('API500');
  });
});
