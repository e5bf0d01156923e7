import type { FileInfo, TreeBlock } from '../api/types';

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
export function freeSourceName(files: readonly FileInfo[], suffix: 'awl' | 'scl'): string {
  let number = 1;
  while (nameTaken(files, `Source${number}.${suffix}`)) number += 1;
  return `Source${number}.${suffix}`;
}

/** `OB1_copy.awl`, `OB1_copy2.awl`, …: a free name for a copy of `name`. */
export function freeCopyName(files: readonly FileInfo[], name: string): string {
  const [stem, suffix] = split(name);
  let candidate = `${stem}_copy${suffix}`;
  for (let number = 2; nameTaken(files, candidate); number += 1) candidate = `${stem}_copy${number}${suffix}`;
  return candidate;
}

/** The first FC number the project's blocks leave free. */
function freeFc(blocks: readonly TreeBlock[]): number {
  const used = new Set(blocks.filter((block) => block.kind === 'FC').map((block) => block.number));
  let number = 1;
  while (used.has(number)) number += 1;
  return number;
}

/** What a new source holds: an empty function with the first free FC number, which compiles. */
export function newSourceText(language: 'stl' | 'scl', blocks: readonly TreeBlock[]): string {
  const number = freeFc(blocks);
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
