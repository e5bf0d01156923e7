import type { FileInfo, TreeBlock } from '../api/types';
import { newGraphText } from '../editor/languages/graph';

/** Whether a project already has a file of this name (letter case does not count, as on the server). */
export function nameTaken(files: readonly FileInfo[], name: string, except?: string): boolean {
  const wanted = name.toLowerCase();
  return files.some((file) => file.name.toLowerCase() === wanted && file.name !== except);
}

function split(name: string): [string, string] {
  const dot = name.lastIndexOf('.');
  return dot > 0 ? [name.slice(0, dot), name.slice(dot)] : [name, ''];
}

/** `Source1.awl`, or the first number no file of the project uses yet. */
export function freeSourceName(files: readonly FileInfo[], suffix: 'awl' | 'scl' | 'lad' | 'fbd' | 'graph'): string {
  let number = 1;
  while (nameTaken(files, `Source${number}.${suffix}`)) number += 1;
  return `Source${number}.${suffix}`;
}

/** `Symbols.sdf`, else `Symbols2.sdf`, …: a free name for a new symbol table (STEP 7's SDF
 * export format, which keeps the comment column and reads back unchanged). */
export function freeSymbolTableName(files: readonly FileInfo[]): string {
  let candidate = 'Symbols.sdf';
  for (let number = 2; nameTaken(files, candidate); number += 1) candidate = `Symbols${number}.sdf`;
  return candidate;
}

/** `OB1_copy.awl`, `OB1_copy2.awl`, …: a free name for a copy of `name`. */
export function freeCopyName(files: readonly FileInfo[], name: string): string {
  const [stem, suffix] = split(name);
  let candidate = `${stem}_copy${suffix}`;
  for (let number = 2; nameTaken(files, candidate); number += 1) candidate = `${stem}_copy${number}${suffix}`;
  return candidate;
}

/** The first FC (or FB) number the project's blocks leave free. */
function freeFc(blocks: readonly TreeBlock[], kind: 'FC' | 'FB' = 'FC'): number {
  const used = new Set(blocks.filter((block) => block.kind === kind).map((block) => block.number));
  let number = 1;
  while (used.has(number)) number += 1;
  return number;
}

/** The languages a new source can be written in. */
export type NewSourceLanguage = 'stl' | 'scl' | 'lad' | 'fbd' | 'graph';

/**
 * What a new source holds: an empty function with the first free FC number, which compiles. A
 * LAD/FBD source shows the shape of a network in a comment (the text format has no empty rung).
 * An S7-Graph source is an FB with the first free FB number: a sequencer of two steps.
 */
export function newSourceText(language: NewSourceLanguage, blocks: readonly TreeBlock[]): string {
  // An S7-Graph source is an FB (a sequencer needs its instance DB): the first free FB number.
  if (language === 'graph') return newGraphText(freeFc(blocks, 'FB'));
  const number = freeFc(blocks);
  if (language === 'lad' || language === 'fbd') {
    return `FUNCTION FC ${number} : VOID
TITLE =
${language === 'fbd' ? 'LANGUAGE FBD\n' : ''}BEGIN
// NETWORK
// TITLE = Self-holding
// RUNG
//   PARALLEL
//     BRANCH Contact("Start") END_BRANCH
//     BRANCH Contact("Motor") END_BRANCH
//   END_PARALLEL
//   ContactNC("Stop")
//   Coil("Motor")
// END_RUNG
END_FUNCTION
`;
  }
  if (language === 'stl') {
    return `FUNCTION FC ${number} : VOID
TITLE =
VERSION : 0.1

BEGIN
NETWORK
TITLE =
      NOP   0;
END_FUNCTION
`;
  }
  return `FUNCTION FC ${number} : VOID
VERSION : '0.1'

VAR_TEMP
END_VAR

BEGIN
  ;
END_FUNCTION
`;
}
