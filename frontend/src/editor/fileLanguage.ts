import type { SourceLanguage } from './CodeEditor';

/** What a project file holds, by its suffix, as the compiler decides (`workbench/names.py`). */
export function languageOfFile(name: string): SourceLanguage | null {
  const dot = name.lastIndexOf('.');
  const suffix = dot >= 0 ? name.slice(dot).toLowerCase() : '';
  if (suffix === '.awl' || suffix === '.stl') return 'stl';
  // TIA Portal exports a DB as `.db` and a PLC data type as `.udt`, both in SCL syntax.
  if (suffix === '.scl' || suffix === '.db' || suffix === '.udt') return 'scl';
  if (suffix === '.lad') return 'lad';
  if (suffix === '.fbd') return 'fbd';
  if (suffix === '.graph') return 'graph';
  if (['.sdf', '.asc', '.seq', '.csv'].includes(suffix)) return 'symbols';
  if (name.toLowerCase() === 'cpu.properties') return 'cpu'; // the CPU properties page
  if (suffix === '.plant') return 'plant'; // the project's virtual plant (YAML)
  return null;
}

/** The suffix a new source of the language gets. */
export const SOURCE_SUFFIX = { stl: 'awl', scl: 'scl', lad: 'lad', graph: 'graph' } as const;
