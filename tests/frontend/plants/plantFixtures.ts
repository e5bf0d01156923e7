/** Plant frames and catalogue entries for the plant tests, shaped as the server sends them. */
import type { PlantFrame, PlantInfo } from '../../../frontend/src/plants/types';

export const TANK: PlantInfo = {
  kind: 'tank',
  title: 'Water tank with pump, valves and level sensors',
  signals: [
    { name: 'pump_pb', direction: 'control', kind: 'bool', normally_closed: false, description: '' },
    { name: 'stop_pb', direction: 'control', kind: 'bool', normally_closed: true, description: '' },
    { name: 'auto', direction: 'control', kind: 'bool', normally_closed: false, description: '' },
    { name: 'ls_low', direction: 'sensor', kind: 'bool', normally_closed: false, description: '' },
    { name: 'ls_high', direction: 'sensor', kind: 'bool', normally_closed: false, description: '' },
    { name: 'level', direction: 'sensor', kind: 'word', normally_closed: false, description: '' },
    { name: 'pump', direction: 'actuator', kind: 'bool', normally_closed: false, description: '' },
    { name: 'fill_valve', direction: 'actuator', kind: 'bool', normally_closed: false, description: '' },
    { name: 'drain_valve', direction: 'actuator', kind: 'bool', normally_closed: false, description: '' },
    { name: 'alarm', direction: 'actuator', kind: 'bool', normally_closed: false, description: '' },
  ],
  faults: [
    { code: 'overflow', injectable: false, description: 'water came in while the tank was full' },
    { code: 'ls_high_stuck', injectable: true, description: 'the full switch never reports full' },
    { code: 'level_wire_break', injectable: true, description: 'the level input reads 32767' },
  ],
  defaults: { initial: 10, pump_rate: 5 },
  default_wiring: { pump_pb: 'I0.0', stop_pb: 'I0.1', ls_low: 'I0.2', ls_high: 'I0.3', level: 'IW64', pump: 'Q4.0', alarm: 'Q4.1', drain_valve: 'Q4.2' },
};

export const BCD: PlantInfo = {
  kind: 'bcd_panel',
  title: 'BCD',
  signals: [
    { name: 'thumbwheel', direction: 'control', kind: 'word', normally_closed: false, description: '' },
    { name: 'display', direction: 'actuator', kind: 'word', normally_closed: false, description: '' },
  ],
  faults: [],
  defaults: {},
  default_wiring: { thumbwheel: 'IW0', display: 'QW4' },
};

export function tankFrame(level: number, extra: Partial<PlantFrame> = {}): PlantFrame {
  return {
    kind: 'tank',
    time_ms: 1000,
    state: { level, spilled: 0, filling: true, draining: false },
    signals: {
      pump_pb: 0,
      stop_pb: 1,
      auto: 0,
      ls_low: level >= 20 ? 1 : 0,
      ls_high: level >= 90 ? 1 : 0,
      level: Math.round((level / 100) * 27648),
      pump: 1,
      fill_valve: 0,
      drain_valve: 0,
      alarm: 0,
    },
    faults: [],
    wiring: { ...TANK.default_wiring },
    ...extra,
  };
}
