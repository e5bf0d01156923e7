/** How the CPU properties page changes the text of cpu.properties: one line per edit, nothing lost. */
import { describe, expect, it } from 'vitest';
import { languageOfFile } from '../../frontend/src/editor/fileLanguage';
import { DEFAULT_TEXT, lineOf, propertyText, setProperty } from '../../frontend/src/cpuprops/format';

describe('cpu.properties text', () => {
  it('replaces only the value of the line that sets the key, keeping its comment', () => {
    const text = '# mine\ncycle_time = 10   # fast\n\nnot a property\nstartup=warm\n';
    const next = setProperty(text, 'cycle_time', '20');
    expect(next).toBe('# mine\ncycle_time = 20   # fast\n\nnot a property\nstartup=warm\n');
    expect(setProperty(next, 'startup', 'cold')).toBe('# mine\ncycle_time = 20   # fast\n\nnot a property\nstartup=cold\n');
  });

  it('keeps the comment apart when a value is cleared and typed again', () => {
    let text = 'cycle_time = 10   # scan\n';
    text = setProperty(text, 'cycle_time', '');
    text = setProperty(text, 'cycle_time', '2');
    text = setProperty(text, 'cycle_time', '20');
    expect(text).toBe('cycle_time = 20   # scan\n');
  });

  it('appends a key the file does not have, finds keys in any letter case', () => {
    expect(setProperty('profile = S7-300', 'clock_memory', 'MB100')).toBe('profile = S7-300\nclock_memory = MB100\n');
    expect(lineOf('# c\nCLOCK_MEMORY: none\n', 'clock_memory')).toBe(1);
    expect(lineOf('# clock_memory = MB1\n', 'clock_memory')).toBe(-1);
  });

  it('writes the values as the file does, and the default text names every key once', () => {
    expect(propertyText('clock_memory', 100)).toBe('MB100');
    expect(propertyText('clock_memory', null)).toBe('none');
    expect(propertyText('cycle_time', 25)).toBe('25');
    for (const key of ['profile', 'cycle_monitoring_time', 'cycle_time', 'clock_memory', 'retentive_markers', 'retentive_timers', 'retentive_counters', 'startup'] as const) {
      expect(lineOf(DEFAULT_TEXT, key)).toBeGreaterThan(0);
    }
  });

  it('opens cpu.properties as the CPU properties page and no other .properties file', () => {
    expect(languageOfFile('cpu.properties')).toBe('cpu');
    expect(languageOfFile('CPU.Properties')).toBe('cpu');
    expect(languageOfFile('plc.properties')).toBeNull();
  });
});
