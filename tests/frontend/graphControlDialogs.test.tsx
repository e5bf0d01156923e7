/**
 * The S7-Graph block settings dialog (applies on OK only, explains each choice, in every
 * language) and the generated view (the FB's interface and its STL from the server's compiler,
 * read-only; the errors listed with their lines when the source has some).
 */
import { act, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it, vi } from 'vitest';
import { GeneratedView, interfaceOf } from '../../frontend/src/graph/GeneratedView';
import type { Settings } from '../../frontend/src/graph/model';
import { SettingsDialog } from '../../frontend/src/graph/SettingsDialog';
import type { Language } from '../../frontend/src/i18n/languages';
import { createI18n } from '../../frontend/src/i18n/setup';
import { json, mockServer } from './helpers';

vi.mock('../../frontend/src/editor/CodeEditor', () => ({
  CodeEditor: ({ value, readOnly, ariaLabel, 'data-testid': testId }: { value: string; readOnly?: boolean; ariaLabel: string; 'data-testid'?: string }) => (
    <textarea data-testid={testId} aria-label={ariaLabel} readOnly={readOnly} value={value} onChange={() => undefined} />
  ),
}));

const SETTINGS: Settings = { parameters: 'STANDARD', skip_steps: false, acknowledge_required: true, interlock_blocks: false };

function renderSettings(language: Language = 'en') {
  const onApply = vi.fn();
  const onClose = vi.fn();
  const user = userEvent.setup();
  render(
    <I18nextProvider i18n={createI18n(language)}>
      <SettingsDialog open settings={SETTINGS} onApply={onApply} onClose={onClose} />
    </I18nextProvider>,
  );
  return { user, onApply, onClose };
}

describe('the block settings dialog', () => {
  it('applies the parameter set and the switches on OK', async () => {
    const { user, onApply, onClose } = renderSettings();
    screen.getByRole('dialog', { name: 'Block settings' });
    const select = screen.getByTestId('graph-settings-parameters') as HTMLSelectElement;
    expect(select.value).toBe('STANDARD');
    expect(screen.getByTestId('graph-settings-parameters-help').textContent).toContain('SW_AUTO');
    await user.selectOptions(select, 'MINIMUM');
    // Fewer parameters than now: the calls that pass them will not compile.
    expect(screen.getByTestId('graph-settings-smaller').textContent).toContain('fewer parameters');
    await user.selectOptions(select, 'MAXIMUM');
    expect(screen.queryByTestId('graph-settings-smaller')).toBeNull();
    // The explanation follows the choice.
    expect(screen.getByTestId('graph-settings-parameters-help').textContent).toContain('HALT_SQ');
    await user.click(screen.getByRole('checkbox', { name: 'Skip steps' }));
    await user.click(screen.getByRole('checkbox', { name: 'Acknowledge required' }));
    await user.click(screen.getByRole('checkbox', { name: 'Interlock blocks switching' }));
    expect(onApply).not.toHaveBeenCalled();
    await user.click(screen.getByTestId('graph-settings-ok'));
    expect(onApply).toHaveBeenCalledWith({ parameters: 'MAXIMUM', skip_steps: true, acknowledge_required: false, interlock_blocks: true });
    expect(onClose).toHaveBeenCalled();
  });

  it('changes nothing on Cancel, Escape, or OK without a change', async () => {
    const { user, onApply, onClose } = renderSettings();
    await user.click(screen.getByRole('checkbox', { name: 'Skip steps' }));
    await user.keyboard('{Escape}');
    expect(onClose).toHaveBeenCalledTimes(1);
    await user.click(screen.getByRole('button', { name: 'Cancel' }));
    expect(onClose).toHaveBeenCalledTimes(2);
    await user.click(screen.getByRole('checkbox', { name: 'Skip steps' }));
    await user.click(screen.getByTestId('graph-settings-ok'));
    expect(onApply).not.toHaveBeenCalled();
  });

  it('speaks Arabic', () => {
    renderSettings('ar');
    expect(screen.getByRole('dialog', { name: 'إعدادات الكتلة' })).toBeTruthy();
    expect(screen.getByRole('checkbox', { name: 'تخطي الخطوات' })).toBeTruthy();
  });

  it('is not there when closed', () => {
    render(
      <I18nextProvider i18n={createI18n('en')}>
        <SettingsDialog open={false} settings={SETTINGS} onApply={() => undefined} onClose={() => undefined} />
      </I18nextProvider>,
    );
    expect(screen.queryByRole('dialog')).toBeNull();
  });
});

const STL = `FUNCTION_BLOCK FB 1
TITLE = Fill
VERSION : 0.1
VAR_INPUT
  INIT_SQ : BOOL;
END_VAR
VAR
  Step1 : STRUCT
    X : BOOL;
  END_STRUCT;
END_VAR
BEGIN
NETWORK
TITLE = sequencer
      A     #INIT_SQ;
END_FUNCTION_BLOCK
`;

function renderGenerated(text: string, language: Language = 'en') {
  const user = userEvent.setup();
  const view = render(
    <I18nextProvider i18n={createI18n(language)}>
      <GeneratedView name="Seq.graph" text={text} active />
    </I18nextProvider>,
  );
  return { user, ...view };
}

describe('the generated view', () => {
  it('shows the interface, then the whole STL, read-only', async () => {
    const server = mockServer({ 'POST /api/convert': () => json({ text: STL, diagnostics: [], converted: 0, kept: 0, blocks: null }) });
    const { user } = renderGenerated('FUNCTION_BLOCK FB 1 ...');
    const editor = (await screen.findByTestId('graph-generated-editor')) as HTMLTextAreaElement;
    expect(JSON.parse(String(server.mock.calls[0]![1]!.body))).toEqual({ name: 'Seq.graph', text: 'FUNCTION_BLOCK FB 1 ...', to: 'stl' });
    expect(editor.readOnly).toBe(true);
    expect(editor.value).toContain('VAR_INPUT\n  INIT_SQ : BOOL;');
    expect(editor.value).toContain('Step1 : STRUCT');
    expect(editor.value).not.toContain('A     #INIT_SQ');
    expect(screen.getByTestId('graph-generated-interface').getAttribute('aria-pressed')).toBe('true');
    await user.click(screen.getByTestId('graph-generated-stl'));
    const stl = screen.getByTestId('graph-generated-editor') as HTMLTextAreaElement;
    expect(stl.value).toBe(STL);
    expect(stl.getAttribute('aria-label')).toBe('STL of Seq.graph (read-only)');
  });

  it('lists the errors with their lines when the source has some, in Persian', async () => {
    mockServer({
      'POST /api/convert': () =>
        json({
          text: '',
          diagnostics: [
            {
              code: 'GRA112',
              severity: 'error',
              key: 'graph_text_expected_sequencer_item',
              message: "STEP, INITIAL_STEP, TRANSITION or END_SEQUENCER expected, found 'STPE'.",
              params: { found: "'STPE'" },
              span: { file: 'Seq.graph', line: 9, column: 1, end_line: null, end_column: null, network: null, element: null },
            },
          ],
          converted: 0,
          kept: 0,
          blocks: null,
        }),
    });
    renderGenerated('broken', 'fa');
    const alert = await screen.findByTestId('graph-generated-errors');
    expect(alert.getAttribute('role')).toBe('alert');
    expect(alert.getAttribute('dir')).toBe('rtl');
    expect(alert.textContent).toContain('GRA112');
    expect(alert.textContent).toContain('خط 9');
    expect(screen.queryByTestId('graph-generated-editor')).toBeNull();
  });

  it('compiles again when the text changes, and offers a retry when the server fails', async () => {
    let calls = 0;
    mockServer({
      'POST /api/convert': () => {
        calls += 1;
        return calls === 1
          ? json({ error: { code: 'API500', key: 'internal_error', message: 'Something went wrong.', params: {}, location: null } }, 500)
          : json({ text: STL.replace('Fill', `Fill ${calls}`), diagnostics: [], converted: 0, kept: 0, blocks: null });
      },
    });
    const { user, rerender } = renderGenerated('one');
    await screen.findByText('The server could not compile the sequencer');
    await user.click(screen.getByRole('button', { name: 'Try again' }));
    await screen.findByTestId('graph-generated-editor');
    await user.click(screen.getByTestId('graph-generated-stl'));
    expect((screen.getByTestId('graph-generated-editor') as HTMLTextAreaElement).value).toContain('TITLE = Fill 2');
    act(() =>
      rerender(
        <I18nextProvider i18n={createI18n('en')}>
          <GeneratedView name="Seq.graph" text="two" active />
        </I18nextProvider>,
      ),
    );
    await waitFor(() => expect((screen.getByTestId('graph-generated-editor') as HTMLTextAreaElement).value).toContain('TITLE = Fill 3'));
  });

  it('takes every block’s declarations for the interface', () => {
    const two = `${STL}\nDATA_BLOCK DB 1\nFB 1\nBEGIN\nEND_DATA_BLOCK\n`;
    expect(interfaceOf(two).split('\n')).toEqual([...interfaceOf(STL).split('\n'), '', 'DATA_BLOCK DB 1', 'FB 1']);
    expect(interfaceOf(STL).startsWith('FUNCTION_BLOCK FB 1\nTITLE = Fill')).toBe(true);
  });
});
