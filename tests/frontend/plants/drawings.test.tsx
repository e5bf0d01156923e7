/**
 * The plant drawings: each kind draws from a frame alone, shows its signals' addresses, animates
 * what the state says (the tank's water, a lamp lit by its signal) and names its faults in the
 * page's language; a kind without a drawing of its own still shows every signal.
 */
import { render, screen, within } from '@testing-library/react';
import { I18nextProvider } from 'react-i18next';
import { describe, expect, it } from 'vitest';
import { createI18n } from '../../../frontend/src/i18n/setup';
import type { Language } from '../../../frontend/src/i18n/languages';
import { PlantDrawing, stillFrame } from '../../../frontend/src/plants/PlantDrawing';
import { DRAWINGS } from '../../../frontend/src/plants/drawings';
import type { PlantFrame } from '../../../frontend/src/plants/types';
import { TANK, tankFrame } from './plantFixtures';

function draw(plant: PlantFrame, language: Language = 'en', info = TANK) {
  return render(
    <I18nextProvider i18n={createI18n(language)}>
      <PlantDrawing plant={plant} info={plant.kind === info.kind ? info : undefined} />
    </I18nextProvider>,
  );
}

const waterHeight = () => Number(screen.getByTestId('plant-water').getAttribute('height'));

describe('the tank drawing', () => {
  it('fills the vessel by the level and lights the level switch lamps', () => {
    const { rerender } = draw(tankFrame(10));
    const low = waterHeight();
    expect(screen.getByTestId('plant-lamp-ls_low').getAttribute('data-on')).toBe('0');
    expect(screen.getByTestId('plant-level-text').textContent).toContain('10 %');
    rerender(
      <I18nextProvider i18n={createI18n('en')}>
        <PlantDrawing plant={tankFrame(55)} info={TANK} />
      </I18nextProvider>,
    );
    expect(waterHeight()).toBeGreaterThan(low * 4);
    expect(screen.getByTestId('plant-lamp-ls_low').getAttribute('data-on')).toBe('1');
    expect(screen.getByTestId('plant-lamp-ls_high').getAttribute('data-on')).toBe('0');
    expect(screen.getByTestId('plant-level-text').textContent).toContain('55 %');
    expect(screen.getByTestId('plant-pump').getAttribute('data-running')).toBe('1');
  });

  it('shows each signal at its wired address and a dash where none is wired', () => {
    draw(tankFrame(30));
    expect(screen.getByTestId('plant-address-ls_low').textContent).toContain('I0.2');
    expect(screen.getByTestId('plant-address-pump').textContent).toContain('Q4.0');
    expect(screen.getByTestId('plant-address-fill_valve').textContent).toContain('—');
  });

  it('names a fault in the page language and frames the drawing in red', () => {
    draw(tankFrame(100, { faults: ['overflow'] }), 'fa');
    const fault = screen.getByTestId('plant-fault-overflow');
    expect(fault.textContent).toContain('سرریز');
    expect(screen.getByTestId('plant-drawing-tank').classList.contains('plant-svg--fault')).toBe(true);
    // The drawing stays left to right in a right-to-left page.
    expect(fault.closest('figure')?.getAttribute('dir')).toBe('ltr');
  });

  it('draws a broken level wire as such', () => {
    draw(tankFrame(40, { faults: ['level_wire_break'], signals: { ...tankFrame(40).signals, level: 32767 } }));
    expect(screen.getByTestId('plant-gauge-level').classList.contains('plant-gauge--fault')).toBe(true);
    expect(screen.getByTestId('plant-fault-level_wire_break').textContent).toContain('wire broken');
  });
});

describe('every plant kind', () => {
  const kinds = Object.keys(DRAWINGS);

  it('has a drawing for each kind the course uses', () => {
    for (const kind of ['tank', 'motor', 'bottle_conveyor', 'traffic_light', 'car_park', 'drill', 'mixer', 'panel', 'bcd_panel', 'door', 'shuttle', 'cylinder', 'packaging_line', 'hopper', 'sorter', 'yoghurt_filler', 'roller_coaster', 'cutter', 'servo_piston', 'shrink_wrap', 'cylinders']) {
      expect(kinds).toContain(kind);
    }
  });

  it.each(kinds)('%s draws from a frame at rest and with its outputs on, in a translated name', (kind) => {
    const frame: PlantFrame = { kind, time_ms: 0, state: {}, signals: {}, faults: [], wiring: {} };
    const { unmount } = draw(frame, 'vi');
    const svg = screen.getByTestId(`plant-drawing-${kind}`);
    expect(svg.getAttribute('aria-label')).not.toBe(kind);
    unmount();
    draw({ ...frame, time_ms: 12_345, signals: { start: 1, conveyor: 1, motor: 1, pump: 1 }, state: { position: 50, level: 50 } }, 'ar');
    expect(screen.getByTestId(`plant-drawing-${kind}`).isConnected).toBe(true);
  });

  it('turns the motor rotor with the plant time and stops it without power', () => {
    const motor = (time: number, contactor: number): PlantFrame => ({
      kind: 'motor',
      time_ms: time,
      state: { speed: contactor ? 100 : 0, tripped: false },
      signals: { contactor, overload: 1, running: contactor },
      faults: [],
      wiring: { contactor: 'Q4.0' },
    });
    const { unmount } = draw(motor(100, 1));
    const rotor = () => screen.getByTestId('plant-motor').querySelector('.plant-motor__rotor')!.getAttribute('transform');
    const first = rotor();
    unmount();
    draw(motor(300, 1));
    expect(rotor()).not.toBe(first);
    expect(screen.getByTestId('plant-motor-speed').textContent).toContain('100');
  });

  it('shows the BCD display, and E for a nibble above 9', () => {
    draw({ kind: 'bcd_panel', time_ms: 0, state: {}, signals: { thumbwheel: 0x1234, display: 0x09a7 }, faults: [], wiring: { display: 'QW4' } });
    expect(screen.getByTestId('plant-digit-1').getAttribute('data-digit')).toBe('9');
    expect(screen.getByTestId('plant-digit-2').getAttribute('data-digit')).toBe('E');
    expect(screen.getByTestId('plant-bcd-error').isConnected).toBe(true);
  });
});

describe('a kind without its own drawing', () => {
  it('shows every signal of the catalogue as a lamp or bar with its address', () => {
    const info = { ...TANK, kind: 'new_machine' };
    const frame: PlantFrame = { kind: 'new_machine', time_ms: 0, state: {}, signals: { pump: 1, ls_low: 0, level: 1000 }, faults: ['jammed_belt'], wiring: { pump: 'Q4.0' } };
    draw(frame, 'en', info);
    const svg = screen.getByTestId('plant-drawing-new_machine');
    for (const signal of info.signals) {
      expect(within(svg).getByTestId(signal.kind === 'word' ? `plant-gauge-${signal.name}` : `plant-lamp-${signal.name}`).isConnected).toBe(true);
    }
    expect(screen.getByTestId('plant-lamp-pump').getAttribute('data-on')).toBe('1');
    expect(screen.getByTestId('plant-address-pump').textContent).toContain('Q4.0');
    expect(screen.getByTestId('plant-fault-jammed_belt').textContent).toContain('jammed_belt');
  });

  it('draws a still plant from its file before any session runs', () => {
    draw(stillFrame('tank', { ls_low: 'I0.2' }, TANK));
    expect(screen.getByTestId('plant-address-ls_low').textContent).toContain('I0.2');
    expect(screen.getByTestId('plant-level-text').textContent).toContain('0 %');
  });
});
