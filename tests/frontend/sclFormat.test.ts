/** "Format document" for SCL: indentation only, comments and strings untouched, idempotent. */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { formatScl } from '../../frontend/src/editor/languages/sclFormat';

const EXAMPLES = path.resolve(__dirname, '../../examples/projects');

function exampleSclFiles(): Array<[string, string]> {
  const found: Array<[string, string]> = [];
  for (const project of fs.readdirSync(EXAMPLES)) {
    for (const name of fs.readdirSync(path.join(EXAMPLES, project))) {
      if (name.endsWith('.scl')) found.push([`${project}/${name}`, fs.readFileSync(path.join(EXAMPLES, project, name), 'utf8')]);
    }
  }
  return found;
}

const MESSY = `FUNCTION_BLOCK "Motor"
      VAR_INPUT
Start : BOOL;   // start   request
      END_VAR
   VAR
 State : STRUCT
 Speed : INT;
    END_STRUCT;
  END_VAR
      BEGIN
IF Start THEN
Run := TRUE;
      ELSIF Stop THEN
Run := FALSE;
        ELSE
  FOR i := 1 TO 10 DO
 Count := Count + 1;
END_FOR;
  END_IF;
CASE Mode OF
1:
Speed := 10;
 2, 3:
  Speed := 20;
ELSE
Speed := 0;
END_CASE;
 WHILE Speed > 0 DO
Speed := Speed - 1;
   END_WHILE;
REPEAT
 Speed := Speed + 1;
     UNTIL Speed > 5
   END_REPEAT;
Text := '  IF   kept  ';
            END_FUNCTION_BLOCK
`;

const FORMATTED = `FUNCTION_BLOCK "Motor"
VAR_INPUT
  Start : BOOL;   // start   request
END_VAR
VAR
  State : STRUCT
    Speed : INT;
  END_STRUCT;
END_VAR
BEGIN
  IF Start THEN
    Run := TRUE;
  ELSIF Stop THEN
    Run := FALSE;
  ELSE
    FOR i := 1 TO 10 DO
      Count := Count + 1;
    END_FOR;
  END_IF;
  CASE Mode OF
    1:
      Speed := 10;
    2, 3:
      Speed := 20;
  ELSE
    Speed := 0;
  END_CASE;
  WHILE Speed > 0 DO
    Speed := Speed - 1;
  END_WHILE;
  REPEAT
    Speed := Speed + 1;
  UNTIL Speed > 5
  END_REPEAT;
  Text := '  IF   kept  ';
END_FUNCTION_BLOCK
`;

describe('formatScl', () => {
  it('indents blocks, sections and statements', () => {
    expect(formatScl(MESSY)).toBe(FORMATTED);
  });

  it('is idempotent', () => {
    expect(formatScl(FORMATTED)).toBe(FORMATTED);
    expect(formatScl(formatScl(MESSY))).toBe(formatScl(MESSY));
  });

  it.each(exampleSclFiles())('leaves the example %s as it is, and formats it stably', (_name, text) => {
    expect(formatScl(text)).toBe(text);
    expect(formatScl(formatScl(text.replace(/^ +/gm, '')))).toBe(formatScl(text.replace(/^ +/gm, '')));
    expect(formatScl(text.replace(/^ +/gm, ''))).toBe(text);
  });

  it('never changes comments or strings', () => {
    const text = 'BEGIN\n(* a comment\n      spanning   lines IF\n  *)\n      x := \'END_IF;\'; // IF x THEN\nEND_FUNCTION';
    expect(formatScl(text)).toBe("BEGIN\n(* a comment\n      spanning   lines IF\n  *)\n  x := 'END_IF;'; // IF x THEN\nEND_FUNCTION");
  });

  it('keeps a continued statement indented relative to its first line', () => {
    const text = 'BEGIN\n      Pump := Level > 5.0\n             AND Enable;\n      x := 1;\nEND_FUNCTION';
    const formatted = 'BEGIN\n  Pump := Level > 5.0\n         AND Enable;\n  x := 1;\nEND_FUNCTION';
    expect(formatScl(text)).toBe(formatted);
    expect(formatScl(formatted)).toBe(formatted);
  });

  it('keeps Windows line ends and drops trailing blanks', () => {
    expect(formatScl('BEGIN  \r\nx := 1;\r\nEND_FUNCTION')).toBe('BEGIN\r\n  x := 1;\r\nEND_FUNCTION');
  });
});
