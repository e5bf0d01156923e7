/**
 * "Format document" for SCL sources: the indentation S7-SCL sources are written with, two spaces
 * a level, and nothing else.
 *
 *   FUNCTION_BLOCK "Motor"        block headers, their properties, VAR sections, BEGIN, END_*: 0
 *   VAR_INPUT
 *     Start : BOOL;               declarations: 1, a STRUCT's members one more
 *   END_VAR
 *   BEGIN
 *     IF Start THEN               statements: 1, one more inside IF/ELSIF/ELSE, FOR, WHILE,
 *       Run := TRUE;              REPEAT ... UNTIL, REGION and CASE (its labels one more, their
 *     END_IF;                     statements two more)
 *   END_FUNCTION_BLOCK
 *
 * Only the whitespace before a line changes (and the blanks after it go). A statement continued
 * on further lines keeps those lines' indentation relative to its first line (at least one
 * level). Comments and strings never change: a `(* ... *)` comment spanning lines keeps all its
 * lines as they are. Formatting a formatted text changes nothing.
 */

const UNIT = '  ';

type FrameKind = 'block' | 'var' | 'code' | 'struct' | 'if' | 'case' | 'for' | 'while' | 'repeat' | 'region';

interface Frame {
  kind: FrameKind;
  indent: number;
  /** CASE: a label has been seen, its statements are one level deeper. */
  labelled?: boolean;
}

const BLOCK_STARTS = new Set(['ORGANIZATION_BLOCK', 'FUNCTION_BLOCK', 'FUNCTION', 'DATA_BLOCK', 'TYPE', 'PROGRAM']);
const BLOCK_ENDS = new Set(['END_ORGANIZATION_BLOCK', 'END_FUNCTION_BLOCK', 'END_FUNCTION', 'END_DATA_BLOCK', 'END_TYPE', 'END_PROGRAM']);
const VAR_STARTS = new Set(['VAR', 'VAR_INPUT', 'VAR_OUTPUT', 'VAR_IN_OUT', 'VAR_TEMP', 'VAR_STAT', 'CONST', 'LABEL']);
const OPENERS: Record<string, FrameKind> = {
  BEGIN: 'code',
  STRUCT: 'struct',
  IF: 'if',
  CASE: 'case',
  FOR: 'for',
  WHILE: 'while',
  REPEAT: 'repeat',
  REGION: 'region',
};
const CLOSERS: Record<string, FrameKind> = {
  END_VAR: 'var',
  END_CONST: 'var',
  END_LABEL: 'var',
  END_STRUCT: 'struct',
  END_IF: 'if',
  END_CASE: 'case',
  END_FOR: 'for',
  END_WHILE: 'while',
  END_REPEAT: 'repeat',
  END_REGION: 'region',
};
/** Frames whose content is statements (where a line without `;` continues on the next). */
const STATEMENT_FRAMES = new Set<FrameKind>(['code', 'if', 'case', 'for', 'while', 'repeat', 'region']);
/** Last words after which a statement line is complete without `;`. */
const OPEN_ENDINGS = new Set(['THEN', 'DO', 'OF', 'ELSE', 'REPEAT', 'BEGIN']);

interface Scan {
  /** The line's code with strings and comments blanked out (for the keywords). */
  code: string;
  /** A `(* ... *)` comment is still open at the end of the line. */
  inComment: boolean;
}

/** Blanks out strings, `//` comments and `(* *)` comments (`inComment`: one is open at the start). */
function scan(line: string, inComment: boolean): Scan {
  let code = '';
  let open = inComment;
  let i = 0;
  while (i < line.length) {
    if (open) {
      const end = line.indexOf('*)', i);
      if (end < 0) return { code, inComment: true };
      code += ' ';
      i = end + 2;
      open = false;
      continue;
    }
    const char = line[i];
    if (char === '/' && line[i + 1] === '/') break;
    if (char === '(' && line[i + 1] === '*') {
      open = true;
      i += 2;
      continue;
    }
    if (char === "'" || char === '"') {
      let j = i + 1;
      while (j < line.length && line[j] !== char) j += line[j] === '$' ? 2 : 1;
      code += char === '"' ? '"x"' : "''";
      i = j + 1;
      continue;
    }
    code += char;
    i += 1;
  }
  return { code, inComment: open };
}

function contentIndent(frame: Frame | undefined): number {
  if (!frame) return 0;
  if (frame.kind === 'block') return frame.indent;
  if (frame.kind === 'case' && frame.labelled) return frame.indent + 2;
  return frame.indent + 1;
}

function popTo(stack: Frame[], kind: FrameKind): Frame | null {
  const at = stack.map((frame) => frame.kind).lastIndexOf(kind);
  if (at < 0) return null;
  const [frame] = stack.splice(at);
  return frame ?? null;
}

function leadingWidth(line: string): number {
  let width = 0;
  for (const char of line) {
    if (char === ' ') width += 1;
    else if (char === '\t') width += UNIT.length;
    else break;
  }
  return width;
}

export function formatScl(text: string): string {
  const eol = text.includes('\r\n') ? '\r\n' : '\n';
  const lines = text.split(/\r?\n/);
  const out: string[] = [];
  const stack: Frame[] = [];
  let inComment = false;
  /** A statement continues on this line: the new and the old indentation of its first line. */
  let continued: { indent: number; original: number } | null = null;

  for (const line of lines) {
    const started = inComment;
    const scanned = scan(line, inComment);
    inComment = scanned.inComment;
    if (started || inComment) {
      out.push(line); // a line of a comment spanning lines: untouched
      continue;
    }
    const trimmed = line.trim();
    if (!trimmed) {
      out.push('');
      continue;
    }
    const words: string[] = scanned.code.toUpperCase().match(/[A-Z_][A-Z0-9_]*/g) ?? [];
    const first = words[0] ?? '';
    const top = stack[stack.length - 1];
    let indent: number;
    let rest = words;

    if (continued) {
      indent = continued.indent; // the line is placed below, relative to the statement's first
    } else if (BLOCK_STARTS.has(first) || BLOCK_ENDS.has(first)) {
      stack.length = 0;
      indent = 0;
      rest = words.slice(1);
      if (BLOCK_STARTS.has(first)) stack.push({ kind: 'block', indent: 0 });
    } else if (first in CLOSERS) {
      const frame = popTo(stack, CLOSERS[first]!);
      indent = frame ? frame.indent : contentIndent(top);
      rest = words.slice(1);
    } else if ((first === 'ELSIF' || first === 'ELSE') && top && (top.kind === 'if' || top.kind === 'case')) {
      indent = top.indent;
      if (top.kind === 'case') top.labelled = false;
    } else if (first === 'UNTIL' && top?.kind === 'repeat') {
      indent = top.indent;
    } else if (top?.kind === 'case' && !(first in OPENERS) && /^[^;]*[^:]:(?!=)/.test(scanned.code.trim())) {
      indent = top.indent + 1; // a CASE label: 1:, 2, 3:, 4..6:
      top.labelled = true;
    } else {
      indent = contentIndent(top);
    }

    if (!continued) {
      for (const word of rest) {
        if (VAR_STARTS.has(word)) stack.push({ kind: 'var', indent });
        else if (word in OPENERS) stack.push({ kind: OPENERS[word]!, indent });
        else if (word in CLOSERS) popTo(stack, CLOSERS[word]!);
        else if (BLOCK_ENDS.has(word)) stack.length = 0;
      }
    }

    const width = continued
      ? continued.indent * UNIT.length + Math.max(UNIT.length, leadingWidth(line) - continued.original)
      : indent * UNIT.length;
    out.push(' '.repeat(width) + trimmed);

    const code = scanned.code.trim();
    const last = (code.match(/[A-Za-z_]\w*$/)?.[0] ?? '').toUpperCase();
    const inStatements = STATEMENT_FRAMES.has(stack[stack.length - 1]?.kind ?? 'block');
    const complete = !code || first === 'UNTIL' || code.endsWith(';') || code.endsWith(':') || OPEN_ENDINGS.has(last) || words.some((word) => word in OPENERS || word in CLOSERS);
    if (inStatements && !complete) continued ??= { indent, original: leadingWidth(line) };
    else continued = null;
  }
  return out.join(eol);
}
