/**
 * Renaming a project from the tree (F2 or the row menu): the server's refusal is shown in the
 * interface language; after the rename the tree shows the new name and open tabs keep saving.
 */
import { screen, waitFor, within } from '@testing-library/react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import { renameProject } from '../../frontend/src/api/client';
import { projectContents } from '../../frontend/src/projects/projectContents';
import { apiError, json, makeProject, renderApp } from './helpers';
import { projectServer, type FakeServer } from './projectServer';

const tree = () => screen.getByTestId('block-tree');

/** The fake server, with `PATCH /api/projects/{id}` as the real one answers it. */
function serverWithRename(): FakeServer & { patches: Array<{ id: number; name: string }> } {
  const server = projectServer([
    { project: makeProject(1, 'Motor'), files: new Map([['OB1.awl', { text: 'ORGANIZATION_BLOCK OB 1\n', version: 1 }]]), blocks: [], diagnostics: () => [] },
    { project: makeProject(2, 'Tank'), files: new Map(), blocks: [], diagnostics: () => [] },
  ]);
  const patches: Array<{ id: number; name: string }> = [];
  const answer = server.fetch.getMockImplementation()!;
  server.fetch.mockImplementation(async (input, init) => {
    const match = /^\/api\/projects\/(\d+)$/.exec(String(input));
    if (!match || init?.method !== 'PATCH') return answer(input, init);
    const id = Number(match[1]);
    const name = String((JSON.parse(String(init.body)) as { name: string }).name);
    patches.push({ id, name });
    const taken = server.projects.find((p) => p.project.id !== id && p.project.name.toLowerCase() === name.toLowerCase());
    if (taken) {
      return apiError(409, 'API105', 'project_name_taken', `A project named '${name}' already exists.`, { name }, ['body', 'name']);
    }
    const entry = server.projects.find((p) => p.project.id === id)!;
    entry.project = { ...entry.project, name };
    return json(entry.project);
  });
  return Object.assign(server, { patches });
}

beforeEach(() => projectContents.clear());

describe('project rename', () => {
  it('renames with F2; a taken name is refused with the server code, translated', async () => {
    const server = serverWithRename();
    const { user } = renderApp('fa');
    const row = await within(tree()).findByRole('treeitem', { name: 'Motor' });
    row.focus();
    await user.keyboard('{F2}');
    const dialog = await screen.findByTestId('project-rename-dialog');
    expect(within(dialog).getByRole('heading').textContent).toBe('تغییر نام پروژه Motor');
    const input = within(dialog).getByTestId('project-rename-input') as HTMLInputElement;
    expect(input.value).toBe('Motor');
    expect(document.activeElement).toBe(input);

    await user.clear(input);
    await user.type(input, 'tank{Enter}');
    const error = await within(dialog).findByTestId('project-rename-error');
    expect(error.textContent).toContain('API105');
    expect(error.textContent).toContain('پروژه');
    expect(input.getAttribute('aria-invalid')).toBe('true');

    await user.clear(input);
    await user.type(input, 'Conveyor{Enter}');
    await waitFor(() => expect(screen.queryByTestId('project-rename-dialog')).toBeNull());
    expect(server.patches).toEqual([
      { id: 1, name: 'tank' },
      { id: 1, name: 'Conveyor' },
    ]);
    // The list stays sorted by name.
    const names = within(tree())
      .getAllByRole('treeitem')
      .filter((item) => item.getAttribute('aria-level') === '1')
      .map((item) => item.textContent);
    expect(names).toEqual(['Conveyor', 'Tank']);
  });

  it('is in the project row menu; an empty name is refused before asking the server', async () => {
    const server = serverWithRename();
    const { user } = renderApp();
    const row = await within(tree()).findByRole('treeitem', { name: 'Tank' });
    row.focus();
    await user.keyboard('{Shift>}{F10}{/Shift}');
    await user.click(await screen.findByRole('menuitem', { name: 'Rename project…' }));
    const dialog = await screen.findByRole('dialog', { name: 'Rename project Tank' });
    const input = within(dialog).getByLabelText('Project name');
    await user.clear(input);
    await user.click(within(dialog).getByTestId('project-rename-submit'));
    expect(within(dialog).getByTestId('project-rename-error').textContent).toBe('Enter a name for the project.');
    // The same name closes without a request.
    await user.type(input, 'Tank{Enter}');
    await waitFor(() => expect(screen.queryByRole('dialog')).toBeNull());
    expect(server.patches).toEqual([]);
  });

  it('keeps the open project selected and its files listed after the rename', async () => {
    const server = serverWithRename();
    const { user } = renderApp();
    const row = await within(tree()).findByRole('treeitem', { name: 'Motor' });
    await user.click(row.firstElementChild as HTMLElement);
    await within(tree()).findByTestId('file-node-1-OB1.awl');
    row.focus();
    await user.keyboard('{F2}');
    const input = within(await screen.findByTestId('project-rename-dialog')).getByTestId('project-rename-input');
    await user.clear(input);
    await user.type(input, 'Motor line 2{Enter}');
    await waitFor(() => expect(screen.queryByTestId('project-rename-dialog')).toBeNull());
    const renamed = within(tree()).getByRole('treeitem', { name: 'Motor line 2' });
    expect(renamed.getAttribute('aria-expanded')).toBe('true');
    expect(within(tree()).getByTestId('file-node-1-OB1.awl')).toBeTruthy();
    expect((screen.getByTestId('cpu-download') as HTMLButtonElement).disabled).toBe(false);
    expect(server.requests()).toContain('PATCH /api/projects/1');
  });
});

describe('renameProject', () => {
  it('turns a server without an answer into NET000 and an odd answer into NET001', async () => {
    vi.stubGlobal('fetch', vi.fn(async () => Promise.reject(new TypeError('Failed to fetch'))));
    await expect(renameProject(1, 'A')).rejects.toMatchObject({ code: 'NET000', status: 0 });
    vi.stubGlobal('fetch', vi.fn(async () => new Response('<html>', { status: 500 })));
    await expect(renameProject(1, 'A')).rejects.toMatchObject({ code: 'NET001', status: 500 });
  });
});
