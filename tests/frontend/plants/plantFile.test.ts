import { describe, expect, it } from 'vitest';
import { PlantFileError, isPlantFile, plantFileName, readPlantFile, writePlantFile } from '../../../frontend/src/plants/plantFile';
import { normalAddress, wireProblem } from '../../../frontend/src/plants/wiring';
import { bcdWheels, bcdWord, controlStyle, pressedValue, restValue } from '../../../frontend/src/plants/controls';
import { TANK } from './plantFixtures';

describe('the plant file', () => {
  it('writes the configuration as block YAML and reads it back unchanged', () => {
    const config = { kind: 'tank', wiring: { pump: 'Q4.0', level: 'IW64' }, params: { pump_rate: 7.5 }, faults: ['ls_high_stuck'] };
    const text = writePlantFile(config);
    expect(text).toBe('kind: tank\nwiring:\n  pump: Q4.0\n  level: IW64\nparams:\n  pump_rate: 7.5\nfaults:\n  - ls_high_stuck\n');
    expect(readPlantFile(text)).toEqual(config);
  });

  it('leaves empty parts and unconnected signals out', () => {
    expect(writePlantFile({ kind: 'motor', wiring: { start: 'I0.0', stop: ' ' }, params: {}, faults: [] })).toBe('kind: motor\nwiring:\n  start: I0.0\n');
  });

  it('reads the flow style a lesson writes, with comments', () => {
    const text = '# from the lesson\nkind: tank\nwiring: {pump_pb: I0.0, stop_pb: "I0.1", pump: Q4.0}\nparams: {pump_rate: 5}\nfaults: [ls_high_stuck]\n';
    expect(readPlantFile(text)).toEqual({
      kind: 'tank',
      wiring: { pump_pb: 'I0.0', stop_pb: 'I0.1', pump: 'Q4.0' },
      params: { pump_rate: 5 },
      faults: ['ls_high_stuck'],
    });
  });

  it('reads what the lessons write (PyYAML block style)', () => {
    const text = "kind: tank\nwiring:\n  pump_pb: I0.0\n  level: IW64\nparams:\n  pump_rate: 5.0\nfaults:\n- ls_high_stuck\n";
    expect(readPlantFile(text)).toEqual({ kind: 'tank', wiring: { pump_pb: 'I0.0', level: 'IW64' }, params: { pump_rate: 5 }, faults: ['ls_high_stuck'] });
    expect(readPlantFile('kind: tank\nwiring: {}\nparams: {}\nfaults: []\n')).toEqual({ kind: 'tank', wiring: {}, params: {}, faults: [] });
  });

  it('refuses what it does not know with the line', () => {
    expect(() => readPlantFile('kind: tank\nwiring:\n  pump Q4.0\n')).toThrow(PlantFileError);
    let caught: unknown = null;
    try {
      readPlantFile('kind: tank\nparams:\n  pump_rate: fast\n');
    } catch (error) {
      caught = error;
    }
    expect(caught).toBeInstanceOf(PlantFileError);
    expect((caught as PlantFileError).line).toBe(3);
    expect(() => readPlantFile('wiring: {}\n')).toThrow(/no kind/);
    expect(() => readPlantFile('kind: tank\ncolour: red\n')).toThrow(/line 2/);
  });

  it('names plant files by their suffix', () => {
    expect(plantFileName('tank')).toBe('tank.plant');
    expect(isPlantFile('Tank.PLANT')).toBe(true);
    expect(isPlantFile('.plant')).toBe(false);
    expect(isPlantFile('OB1.awl')).toBe(false);
  });
});

describe('the wiring rules', () => {
  const signal = (name: string) => TANK.signals.find((s) => s.name === name)!;

  it('accepts inputs for sensors and controls, outputs and markers for actuators', () => {
    expect(wireProblem(signal('ls_low'), 'I0.2')).toBeNull();
    expect(wireProblem(signal('ls_low'), 'e 0.2')).toBeNull();
    expect(wireProblem(signal('level'), 'PIW256')).toBeNull();
    expect(wireProblem(signal('level'), 'IW64')).toBeNull();
    expect(wireProblem(signal('pump'), 'Q4.0')).toBeNull();
    expect(wireProblem(signal('pump'), 'M10.1')).toBeNull();
    expect(wireProblem(signal('pump'), '')).toBeNull();
  });

  it('says what is wrong with a wire', () => {
    expect(wireProblem(signal('ls_low'), 'Q4.0')).toBe('input');
    expect(wireProblem(signal('pump'), 'I0.0')).toBe('output');
    expect(wireProblem(signal('pump'), 'QW4')).toBe('bit');
    expect(wireProblem(signal('level'), 'I0.8')).toBe('word');
    expect(wireProblem(signal('ls_low'), 'I0.8')).toBe('bit');
    expect(normalAddress(' piw 256 ')).toBe('PIW256');
  });
});

describe('the operator controls', () => {
  it('presses an NC stop button to 0 and lets it rest at 1', () => {
    const stop = TANK.signals[1]!;
    expect([restValue(stop), pressedValue(stop)]).toEqual([1, 0]);
    const start = TANK.signals[0]!;
    expect([restValue(start), pressedValue(start)]).toEqual([0, 1]);
  });

  it('shows selector switches, push buttons and thumbwheels', () => {
    expect(controlStyle('tank', TANK.signals[2]!)).toBe('switch');
    expect(controlStyle('tank', TANK.signals[0]!)).toBe('button');
    expect(controlStyle('bcd_panel', { name: 'thumbwheel', direction: 'control', kind: 'word', normally_closed: false, description: '' })).toBe('thumbwheel');
  });

  it('sets a BCD word digit by digit', () => {
    expect(bcdWord([1, 2, 3, 4])).toBe(0x1234);
    expect(bcdWheels(0x0907)).toEqual([0, 9, 0, 7]);
    expect(bcdWheels(0x00a1)).toEqual([0, 0, 0, 1]);
  });
});
