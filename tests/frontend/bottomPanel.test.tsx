import { act, render, screen, within } from '@testing-library/react';
import { afterEach, describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../frontend/src/api/types';
import { DiagnosticsList, spanText } from '../../frontend/src/panels/DiagnosticsList';
import { createDiagnosticsStore, diagnosticsStore } from '../../frontend/src/panels/diagnosticsStore';
import { createI18n } from '../../frontend/src/i18n/setup';
import { I18nextProvider } from 'react-i18next';
import { healthyServer, renderApp } from './helpers';

const problem = (overrides: Partial<Diagnostic>): Diagnostic => ({
  code: 'STL101',
  severity: 'error',
  key: 'unknown_instruction',
  message: 'Unknown instruction',
  params: {},
  span: { file: 'OB1.awl', line: 3, column: 7 },
  ...overrides,
});

afterEach(() => diagnosticsStore.clear());

function tabNames() {
  return screen.getAllByRole('tab').map((tab) => tab.textContent);
}

function selectedTab() {
  return screen.getAllByRole('tab').find((tab) => tab.getAttribute('aria-selected') === 'true');
}

describe('bottom panel', () => {
  it('is a tab list with Diagnostics, Watch table, Trend, I/O, Plant, Call stack, Cross-references and Assignment list, Diagnostics first', () => {
    healthyServer();
    renderApp();
    expect(screen.getByRole('tablist', { name: 'Output panels' })).toBeTruthy();
    expect(tabNames()).toEqual([
      'Diagnostics0Problems: 0',
      'Watch table',
      'Trend',
      'I/O',
      'Plant',
      'Call stack',
      'Cross-references',
      'Assignment list',
    ]);
    const tab = selectedTab()!;
    expect(tab.textContent).toContain('Diagnostics');
    const panel = document.getElementById(tab.getAttribute('aria-controls')!)!;
    expect(panel.getAttribute('role')).toBe('tabpanel');
    expect(panel.getAttribute('aria-labelledby')).toBe(tab.id);
    expect(panel.hidden).toBe(false);
    expect(within(panel).getByTestId('diagnostics').textContent).toContain('No problems');
  });

  it('switches tabs with a click', async () => {
    healthyServer();
    const { user } = renderApp();
    await user.click(screen.getByRole('tab', { name: 'Watch table' }));
    const tab = selectedTab()!;
    expect(tab.textContent).toBe('Watch table');
    const panel = document.getElementById(tab.getAttribute('aria-controls')!)!;
    expect(panel.hidden).toBe(false);
    // Watch tables are files of a project: without one the tab says so.
    expect(panel.textContent).toContain('Open or create a project to keep watch tables in it.');
    expect(screen.getByTestId('diagnostics').closest('[role="tabpanel"]')!.hasAttribute('hidden')).toBe(true);
  });

  it('moves between tabs with the arrow keys, Home and End, with one tab stop', async () => {
    healthyServer();
    const { user } = renderApp();
    const [diagnostics, watch, trend, io, plant, debug, xref, assignments] = screen.getAllByRole('tab');
    expect([diagnostics, watch, trend, io, debug].map((tab) => tab!.tabIndex)).toEqual([0, -1, -1, -1, -1]);

    diagnostics!.focus();
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(watch);
    expect(watch!.getAttribute('aria-selected')).toBe('true');
    expect([diagnostics, watch, trend, io, debug].map((tab) => tab!.tabIndex)).toEqual([-1, 0, -1, -1, -1]);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(trend);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(io);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(plant);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(debug);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(xref);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(assignments);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(diagnostics);
    await user.keyboard('{ArrowLeft}');
    expect(document.activeElement).toBe(assignments);
    expect(assignments!.getAttribute('aria-selected')).toBe('true');
    await user.keyboard('{Home}');
    expect(document.activeElement).toBe(diagnostics);
    await user.keyboard('{End}');
    expect(document.activeElement).toBe(assignments);
  });

  it('mirrors the arrow keys in a right-to-left language', async () => {
    healthyServer();
    const { user } = renderApp('fa');
    const [diagnostics, watch] = screen.getAllByRole('tab');
    expect(diagnostics!.textContent).toContain('عیب\u200cیابی');
    diagnostics!.focus();
    await user.keyboard('{ArrowLeft}');
    expect(document.activeElement).toBe(watch);
    await user.keyboard('{ArrowRight}');
    expect(document.activeElement).toBe(diagnostics);
  });

  it('asks for a download in the trend and I/O views while no session runs', () => {
    healthyServer();
    renderApp();
    expect(screen.getByTestId('trend').textContent).toContain('Download a program (Ctrl+B) to record trends.');
    expect(screen.getByTestId('io-panel').textContent).toContain('Download a program (Ctrl+B)');
  });
});

describe('diagnostics list', () => {
  function renderList(store = createDiagnosticsStore()) {
    const i18n = createI18n('en');
    render(
      <I18nextProvider i18n={i18n}>
        <DiagnosticsList store={store} />
      </I18nextProvider>,
    );
    return { store, i18n };
  }

  it('renders the diagnostics of its store, errors first, with code, message and location', () => {
    const { store } = renderList();
    expect(screen.getByTestId('diagnostics').textContent).toBe('No problems');
    act(() =>
      store.set([
        problem({ code: 'SCL210', severity: 'warning', message: 'Implicit conversion', key: 'implicit_conversion', span: { file: 'FC1.scl', line: 12, column: 3 } }),
        problem({}),
      ]),
    );
    const rows = screen.getAllByTestId('diagnostic');
    expect(rows).toHaveLength(2);
    expect(rows[0]!.textContent).toContain('STL101');
    expect(rows[0]!.textContent).toContain('Unknown instruction');
    expect(rows[0]!.textContent).toContain('OB1.awl:3:7');
    expect(rows[0]!.textContent).toContain('Error');
    expect(rows[1]!.textContent).toContain('SCL210');
    expect(rows[1]!.textContent).toContain('FC1.scl:12:3');
    expect(screen.getByRole('list', { name: 'Problems (2)' })).toBeTruthy();

    act(() => store.clear());
    expect(screen.queryAllByTestId('diagnostic')).toHaveLength(0);
    expect(screen.getByTestId('diagnostics').textContent).toBe('No problems');
  });

  it('writes a span as file:line:column, with the network for diagrams', () => {
    expect(spanText({ file: 'OB1.awl', line: 3, column: 7 })).toBe('OB1.awl:3:7');
    expect(spanText({ file: 'FB2.lad', network: 4 })).toBe('FB2.lad:NW 4');
    expect(spanText({ line: 9 })).toBe('9');
    expect(spanText(null)).toBe('');
  });

  it('shows a problem without a place, and no empty location', () => {
    const { store } = renderList();
    act(() => store.set([problem({ code: 'API106', span: null, message: 'The database cannot be reached' })]));
    const row = screen.getByTestId('diagnostic');
    expect(row.textContent).toContain('API106');
    expect(row.querySelector('.diagnostic__location')).toBeNull();
  });

  it('translates a diagnostic when the catalogue knows its key', () => {
    const { store, i18n } = renderList();
    i18n.addResource('en', 'translation', 'problems.unknown_instruction', 'No instruction called {{name}}');
    act(() => store.set([problem({ key: 'unknown_instruction', params: { name: 'XYZ' } })]));
    expect(screen.getByTestId('diagnostic').textContent).toContain('No instruction called XYZ');
  });

  it('shows the application store in the bottom panel, with the count on the tab', async () => {
    healthyServer();
    renderApp();
    act(() => diagnosticsStore.set([problem({})]));
    expect(screen.getAllByTestId('diagnostic')).toHaveLength(1);
    expect(screen.getAllByRole('tab')[0]!.textContent).toContain('Problems: 1');
  });
});
