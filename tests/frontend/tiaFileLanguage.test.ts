/** TIA Portal's exported DB (`.db`) and PLC data type (`.udt`) sources open as SCL, as the compiler reads them. */
import { describe, expect, it } from 'vitest';
import { languageOfFile } from '../../frontend/src/editor/fileLanguage';

describe('TIA Portal export files', () => {
  it('open as SCL sources, whatever the letter case', () => {
    expect(languageOfFile('Recipe data.db')).toBe('scl');
    expect(languageOfFile('MOTORDATA.UDT')).toBe('scl');
    expect(languageOfFile('Motor.scl')).toBe('scl');
    expect(languageOfFile('notes.dbx')).toBeNull();
  });
});
