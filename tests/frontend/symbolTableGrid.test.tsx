/**
 * The symbol table editor over a fake `/symbols` API: editing a cell autosaves the rows with the
 * version, the server's problems show on their cells with codes, rows are added (also by typing
 * into the empty last row), deleted, sorted and filtered, a stale save offers the conflict choice,
 * and a 2,000-row table renders only the rows in view.
 */
import { act, fireEvent, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { afterEach, describe, expect, it, vi } from 'vitest';
import type { RowProblem, SymbolRow, SymbolTableOut } from '../../frontend/src/api/symbols';
import { EditorTabsProvider } from '../../frontend/src/editor/EditorTabsContext';
import { createI18n } from '../../frontend/src/i18n/setup';
import { createProjectContentsStore } from '../../frontend/src/projects/projectContents';
import { SymbolTableView } from '../../frontend/src/symbols/SymbolTableView';
import { apiError, json, mockServer } from './helpers';

const URL = '/api/projects/1/symbols/symbols.sdf';
const ROWS: SymbolRow[] = [
  { name: 'Start', address: 'I 0.0', type: 'BOOL', comment: 'start button' },
  { name: 'Motor', address: 'Q 4.0', type: 'BOOL', comment: 'contactor' },
  { name: 'Level', address: 'MD 10', type: 'REAL', comment: '' },
];

function table(rows: SymbolRow[], version: number, problems: RowProblem[] = []): SymbolTableOut {
  return { name: 'symbols.sdf', format: 'sdf', version, rows, problems };
}

function badAddress(row: number, address: string): RowProblem {
  return {
    row,
    field: 'address',
    problem: {
      code: 'API120',
      severity: 'error',
      key: 'symbol_address_invalid',
      message: `Row ${row + 1}: '${address}' is not an address: X is not an address area`,
      params: { row: row + 1, address, reason: 'X is not an address area' },
      span: null,
    },
  };
}

interface Saved {
  rows: SymbolRow[];
  base_version: number | null;
}

function symbolServer(initial: SymbolRow[] = ROWS, check: (rows: SymbolRow[]) => RowProblem[] = () => []) {
  let version = 1;
  let current = initial;
  const saves: Saved[] = [];
  const answers: Array<() => Response> = [];
  const fetchMock = mockServer({
    [`GET ${URL}`]: () => json(table(current, version, check(current))),
    [`PUT ${URL}`]: (init) => {
      const body = JSON.parse(String(init?.body)) as Saved;
      saves.push(body);
      const answer = answers.shift();
      if (answer) return answer();
      version += 1;
      current = body.rows;
      return json(table(current, version, check(current)));
    },
  });
  return { fetchMock, saves, answers, setRows: (rows: SymbolRow[]) => (current = rows) };
}

function renderTable() {
  const user = userEvent.setup();
  const store = createProjectContentsStore();
  store.reloadSoon = vi.fn();
  render(
    <I18nextProvider i18n={createI18n('en')}>
      <EditorTabsProvider>
        <SymbolTableView tabId="source-1" file={{ projectId: 1, path: 'symbols.sdf' }} active store={store} />
      </EditorTabsProvider>
    </I18nextProvider>,
  );
  return { user };
}

const names = () => screen.getAllByTestId('symbol-row').map((row) => row.getAttribute('data-name'));
const cell = (row: number, field: string) =>
  within(screen.getAllByTestId('symbol-row')[row]!).getByTestId(`symbol-cell-${field}`) as HTMLInputElement;

afterEach(() => {
  vi.useRealTimers();
});

describe('the symbol table editor', () => {
  it('edits a cell and autosaves the rows with the loaded version; problems show with their code', async () => {
    const server = symbolServer(ROWS, (rows) =>
      rows.flatMap((row, index) => (row.address.startsWith('X') ? [badAddress(index, row.address)] : [])),
    );
    const { user } = renderTable();
    await waitFor(() => expect(names()).toEqual(['Start', 'Motor', 'Level']));
    expect(screen.getByTestId('symbol-grid').getAttribute('dir')).toBe('ltr');
    await user.clear(cell(1, 'address'));
    await user.type(cell(1, 'address'), 'X 9');
    await waitFor(() => expect(server.saves).toHaveLength(1), { timeout: 3000 });
    expect(server.saves[0]!.base_version).toBe(1);
    expect(server.saves[0]!.rows[1]).toEqual({ name: 'Motor', address: 'X 9', type: 'BOOL', comment: 'contactor' });
    await waitFor(() => expect(cell(1, 'address').getAttribute('aria-invalid')).toBe('true'));
    expect(cell(1, 'name').getAttribute('aria-invalid')).toBeNull();
    expect(screen.getByTestId('symbol-problem-count').textContent).toBe('1 errors, 0 warnings');
    // The problems of the row with the focus are listed with their codes.
    expect(screen.getByTestId('symbol-row-problems').textContent).toContain('API120');
    expect(screen.getByTestId('symbol-row-problems').textContent).toContain('Address: Row 2: “X 9” is not an address');
    expect(screen.getByTestId('symbol-save-state').getAttribute('data-state')).toBe('saved');
    // Fixing it clears the problem at the next save.
    await user.clear(cell(1, 'address'));
    await user.type(cell(1, 'address'), 'Q 4.0');
    await waitFor(() => expect(server.saves).toHaveLength(2), { timeout: 3000 });
    expect(server.saves[1]!.base_version).toBe(2);
    await waitFor(() => expect(cell(1, 'address').getAttribute('aria-invalid')).toBeNull());
  });

  it('adds a row by typing into the empty last row, and with the Add button', async () => {
    const server = symbolServer();
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    const fresh = within(screen.getByTestId('symbol-row-new')).getByTestId('symbol-cell-name');
    await user.click(fresh);
    await user.keyboard('Pump');
    expect(names()).toEqual(['Start', 'Motor', 'Level', 'Pump']);
    expect(document.activeElement).toBe(cell(3, 'name'));
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(cell(3, 'address'));
    await user.keyboard('Q 4.1');
    await waitFor(() => expect(server.saves.at(-1)?.rows).toHaveLength(4), { timeout: 3000 });
    await waitFor(() => expect(server.saves.at(-1)?.rows[3]).toEqual({ name: 'Pump', address: 'Q 4.1', type: '', comment: '' }), {
      timeout: 3000,
    });
    await user.click(screen.getByTestId('symbol-add'));
    expect(screen.getAllByTestId('symbol-row')).toHaveLength(5);
  });

  it('deletes the selected rows and the focused row with Ctrl+Delete', async () => {
    const server = symbolServer();
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    const remove = screen.getByTestId('symbol-delete') as HTMLButtonElement;
    expect(remove.disabled).toBe(true);
    await user.click(screen.getByRole('checkbox', { name: 'Select row 2' }));
    expect(remove.textContent).toBe('Delete selected (1)');
    await user.click(remove);
    expect(names()).toEqual(['Start', 'Level']);
    await user.click(cell(0, 'comment'));
    await user.keyboard('{Control>}{Delete}{/Control}');
    expect(names()).toEqual(['Level']);
    await waitFor(() => expect(server.saves.at(-1)?.rows.map((row) => row.name)).toEqual(['Level']), { timeout: 3000 });
  });

  it('sorts by a column (ascending, then descending) and filters without changing the table', async () => {
    const server = symbolServer();
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    await user.click(screen.getByTestId('symbol-sort-name'));
    expect(names()).toEqual(['Level', 'Motor', 'Start']);
    expect(screen.getByTestId('symbol-sort-name').parentElement!.getAttribute('aria-sort')).toBe('ascending');
    await user.click(screen.getByTestId('symbol-sort-name'));
    expect(names()).toEqual(['Start', 'Motor', 'Level']);
    await user.click(screen.getByTestId('symbol-sort-address'));
    expect(names()).toEqual(['Start', 'Level', 'Motor']); // I, M, Q
    await waitFor(() => expect(server.saves.at(-1)?.rows.map((row) => row.name)).toEqual(['Start', 'Level', 'Motor']), {
      timeout: 3000,
    });
    await user.type(screen.getByTestId('symbol-filter'), 'bool');
    expect(names()).toEqual(['Start', 'Motor']);
    expect(screen.getByTestId('symbol-count').textContent).toBe('2 of 3 rows');
  });

  it('moves between cells with the keyboard and undoes a cell with Escape', async () => {
    symbolServer();
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    await user.click(cell(0, 'name'));
    await user.keyboard('{ArrowDown}');
    expect(document.activeElement).toBe(cell(1, 'name'));
    await user.keyboard('{Enter}');
    expect(document.activeElement).toBe(cell(2, 'name'));
    await user.keyboard('{ArrowUp}{End}{ArrowRight}');
    expect(document.activeElement).toBe(cell(1, 'address'));
    await user.keyboard('XYZ');
    expect(cell(1, 'address').value).toBe('Q 4.0XYZ');
    await user.keyboard('{Escape}');
    expect(cell(1, 'address').value).toBe('Q 4.0');
    await user.keyboard('{Control>}{End}{/Control}');
    expect(document.activeElement).toBe(within(screen.getByTestId('symbol-row-new')).getByTestId('symbol-cell-address'));
  });

  it('offers reload and overwrite when the file changed elsewhere (409 API111)', async () => {
    const server = symbolServer();
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    server.answers.push(() =>
      apiError(409, 'API111', 'file_changed', 'changed', { name: 'symbols.sdf', current_version: 7 }),
    );
    await user.type(cell(0, 'comment'), '!');
    const banner = await screen.findByTestId('symbols-conflict', {}, { timeout: 3000 });
    expect(banner.textContent).toContain('API111');
    await user.click(within(banner).getByTestId('symbols-conflict-overwrite'));
    await waitFor(() => expect(server.saves).toHaveLength(2));
    expect(server.saves[1]!.base_version).toBe(7);
    await waitFor(() => expect(screen.queryByTestId('symbols-conflict')).toBeNull());
    // A second conflict, resolved by taking the server's table.
    server.answers.push(() => apiError(409, 'API111', 'file_changed', 'changed', { name: 'symbols.sdf', current_version: 9 }));
    server.setRows([{ name: 'Other', address: 'M 0.0', type: 'BOOL', comment: '' }]);
    await user.type(cell(0, 'comment'), '?');
    await user.click(await screen.findByTestId('symbols-conflict-reload', {}, { timeout: 3000 }));
    await waitFor(() => expect(names()).toEqual(['Other']));
  });

  it('imports a chosen STEP 7 file (merge) as the raw upload, and links the export formats', async () => {
    const server = symbolServer();
    const imported: Array<{ url: string; body: unknown }> = [];
    const base = server.fetchMock.getMockImplementation()!;
    server.fetchMock.mockImplementation(async (input, init) => {
      const url = String(input);
      if (url.startsWith(`${URL}/import?`)) {
        imported.push({ url, body: init?.body });
        return json(table([...ROWS, { name: 'Stop', address: 'I 0.1', type: 'BOOL', comment: '' }], 5));
      }
      return base(input, init);
    });
    const { user } = renderTable();
    await waitFor(() => expect(names()).toHaveLength(3));
    await user.selectOptions(screen.getByTestId('symbol-import-mode'), 'merge');
    const upload = new File(['126,Stop                    I 0.1       BOOL\r\n'], 'plant.asc');
    await user.upload(screen.getByTestId('symbol-import-file') as HTMLInputElement, upload);
    await waitFor(() => expect(names()).toEqual(['Start', 'Motor', 'Level', 'Stop']));
    expect(imported[0]!.url).toBe(`${URL}/import?name=plant.asc&mode=merge&base_version=1`);
    expect(imported[0]!.body).toBe(upload);
    expect(screen.getByRole('status').textContent).toBe('Imported 4 rows from plant.asc.');
    // The next save starts from the import's version.
    await user.type(cell(3, 'comment'), 'x');
    await waitFor(() => expect(server.saves.at(-1)?.base_version).toBe(5), { timeout: 3000 });
    expect(screen.getByTestId('symbol-export-asc').getAttribute('href')).toBe(`${URL}/export?format=asc`);
    expect(screen.getByTestId('symbol-export-csv').hasAttribute('download')).toBe(true);
  });

  it('keeps a 2,000-row table responsive: only the rows in view are rendered', async () => {
    const many = Array.from({ length: 2000 }, (_, index) => ({
      name: `Symbol ${index}`,
      address: `M ${index}.0`,
      type: 'BOOL',
      comment: '',
    }));
    symbolServer(many);
    renderTable();
    await waitFor(() => expect(screen.getByTestId('symbol-count').textContent).toBe('2000 rows'));
    const shown = screen.getAllByTestId('symbol-row');
    expect(shown.length).toBeLessThan(100);
    const grid = screen.getByTestId('symbol-grid');
    act(() => {
      grid.scrollTop = 28 * 1500;
      fireEvent.scroll(grid);
    });
    expect(names()).toContain('Symbol 1500');
    expect(names()).not.toContain('Symbol 0');
  });

  it('shows why the table cannot be read', async () => {
    mockServer({ [`GET ${URL}`]: () => apiError(404, 'API107', 'file_not_found', 'gone', { project: 1, name: 'symbols.sdf' }) });
    renderTable();
    expect((await screen.findByRole('alert')).textContent).toContain('API107');
  });
});
