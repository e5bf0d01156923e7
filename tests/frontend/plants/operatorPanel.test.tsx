/**
 * The operator panel and the "Attach a plant" dialog: push buttons are momentary (pointer and
 * keyboard), an NC stop button sends 0 while pressed, switches stay, faults are injected from a
 * menu and the plant is reset; the dialog prefills the usual wiring, refuses a wrong address at
 * once and saves `<kind>.plant` in the project.
 */
import { fireEvent, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it, vi } from 'vitest';
import { createI18n } from '../../../frontend/src/i18n/setup';
import { AttachPlantDialog } from '../../../frontend/src/plants/AttachPlantDialog';
import { OperatorPanel } from '../../../frontend/src/plants/OperatorPanel';
import { readPlantFile } from '../../../frontend/src/plants/plantFile';
import type { PlantCommand } from '../../../frontend/src/plants/types';
import { json, mockServer } from '../helpers';
import { BCD, TANK, tankFrame } from './plantFixtures';

function panel(send: (command: PlantCommand) => void, disabled = false, info = TANK, plant = tankFrame(30)) {
  return render(
    <I18nextProvider i18n={createI18n('en')}>
      <OperatorPanel plant={plant} info={info} disabled={disabled} send={send} />
    </I18nextProvider>,
  );
}

describe('the operator panel', () => {
  it('holds a push button while the pointer holds it', () => {
    const send = vi.fn();
    panel(send);
    const button = screen.getByRole('button', { name: /Pump on/ });
    expect(button.getAttribute('data-testid')).toBe('plant-control-pump_pb');
    fireEvent.pointerDown(button, { button: 0, pointerId: 1 });
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_operate', control: 'pump_pb', value: 1 });
    expect(button.getAttribute('aria-pressed')).toBe('true');
    fireEvent.pointerUp(button, { button: 0, pointerId: 1 });
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_operate', control: 'pump_pb', value: 0 });
    expect(send).toHaveBeenCalledTimes(2);
  });

  it('opens an NC stop button while pressed, by the Space key too', () => {
    const send = vi.fn();
    panel(send);
    const stop = screen.getByTestId('plant-control-stop_pb');
    fireEvent.keyDown(stop, { key: ' ' });
    fireEvent.keyDown(stop, { key: ' ', repeat: true });
    expect(send).toHaveBeenCalledTimes(1);
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_operate', control: 'stop_pb', value: 0 });
    fireEvent.keyUp(stop, { key: ' ' });
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_operate', control: 'stop_pb', value: 1 });
  });

  it('turns a selector switch, which stays', async () => {
    const send = vi.fn();
    panel(send);
    await userEvent.click(screen.getByRole('switch', { name: /Automatic/ }));
    expect(send).toHaveBeenCalledWith({ type: 'plant_operate', control: 'auto', value: 1 });
    expect(send).toHaveBeenCalledTimes(1);
  });

  it('injects only the injectable faults and resets the plant', async () => {
    const send = vi.fn();
    panel(send, false, TANK, tankFrame(30, { faults: ['level_wire_break'] }));
    await userEvent.click(screen.getByRole('button', { name: 'Inject a fault' }));
    expect(screen.queryByTestId('plant-inject-overflow')).toBeNull();
    const stuck = screen.getByRole('checkbox', { name: /high-level switch is stuck/ }) as HTMLInputElement;
    expect(stuck.checked).toBe(false);
    expect((screen.getByTestId('plant-inject-level_wire_break') as HTMLInputElement).checked).toBe(true);
    await userEvent.click(stuck);
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_fault', fault: 'ls_high_stuck', on: true });
    await userEvent.click(screen.getByTestId('plant-inject-level_wire_break'));
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_fault', fault: 'level_wire_break', on: false });
    await userEvent.click(screen.getByRole('button', { name: 'Reset plant' }));
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_reset' });
  });

  it('sets BCD thumbwheels digit by digit', () => {
    const send = vi.fn();
    panel(send, false, BCD, { kind: 'bcd_panel', time_ms: 0, state: {}, signals: { thumbwheel: 0x0120, display: 0 }, faults: [], wiring: {} });
    fireEvent.change(screen.getByLabelText('Thumbwheels: digit 4'), { target: { value: '7' } });
    expect(send).toHaveBeenLastCalledWith({ type: 'plant_operate', control: 'thumbwheel', value: 0x0127 });
  });

  it('does nothing while no session runs the plant', () => {
    const send = vi.fn();
    panel(send, true);
    expect((screen.getByTestId('plant-control-pump_pb') as HTMLButtonElement).disabled).toBe(true);
    expect((screen.getByTestId('plant-reset') as HTMLButtonElement).disabled).toBe(true);
  });
});

describe('the attach dialog', () => {
  function dialog(onSaved = vi.fn()) {
    render(
      <I18nextProvider i18n={createI18n('en')}>
        <AttachPlantDialog projectId={7} files={[]} plants={[TANK, BCD]} editing={null} onClose={vi.fn()} onSaved={onSaved} />
      </I18nextProvider>,
    );
    return onSaved;
  }

  it('prefills the usual wiring and saves the plant file in the project', async () => {
    const saves: string[] = [];
    mockServer({
      'PUT /api/projects/7/files/tank.plant': (init) => {
        saves.push((JSON.parse(String(init?.body)) as { text: string }).text);
        return json({ name: 'tank.plant', language: 'plant', size: 1, version: 1, created_at: '', updated_at: '' });
      },
    });
    const onSaved = dialog();
    expect((screen.getByLabelText('Address of Low level') as HTMLInputElement).value).toBe('I0.2');
    expect((screen.getByLabelText('Address of Fill valve') as HTMLInputElement).value).toBe('');
    await userEvent.type(screen.getByLabelText('Address of Fill valve'), 'q4.3');
    await userEvent.click(screen.getByRole('button', { name: 'Attach' }));
    await waitFor(() => expect(onSaved).toHaveBeenCalledWith('tank.plant'));
    const saved = readPlantFile(saves[0] ?? '');
    expect(saved.kind).toBe('tank');
    expect(saved.wiring).toEqual({ ...TANK.default_wiring, fill_valve: 'Q4.3' });
    expect(saved.params).toEqual({});
  });

  it('refuses a wire to the wrong side at once', async () => {
    mockServer({});
    dialog();
    const low = screen.getByLabelText('Address of Low level');
    await userEvent.clear(low);
    await userEvent.type(low, 'Q4.0');
    expect(low.getAttribute('aria-invalid')).toBe('true');
    expect(screen.getByTestId('attach-wire-error-ls_low').textContent).toContain('Inputs only');
    expect((screen.getByRole('button', { name: 'Attach' }) as HTMLButtonElement).disabled).toBe(true);
  });

  it('prefills another kind when the kind changes', async () => {
    mockServer({});
    dialog();
    await userEvent.selectOptions(screen.getByTestId('attach-plant-kind'), 'bcd_panel');
    expect((screen.getByLabelText('Address of Thumbwheels') as HTMLInputElement).value).toBe('IW0');
    expect(screen.getByText('bcd_panel.plant')).toBeTruthy();
  });
});
