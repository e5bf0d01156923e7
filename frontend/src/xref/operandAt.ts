/**
 * The operand under the caret of an STL or SCL line, as cross-references and rename take it:
 * a quoted symbol (`"Motor"`), a DB member (`"Tank".Level`, `DB1.Level`; the DB alone when the
 * caret is on its name), an absolute address (`Q 4.0`, `MW 10`, `DB1.DBW 2`, `T 1`) or a block
 * (`FB 10`). Comments and `#locals` name nothing here: they are not project-wide operands.
 */

const OPERAND = new RegExp(
  [
    String.raw`"[^"\n]*"(?:\s*\.\s*[A-Za-z_]\w*)*`, // "Symbol", "DB".member.sub
    String.raw`\bDB\s*\d+\s*\.\s*DB[XBWD]\s*\d+(?:\.\d+)?\b`, // DB1.DBX 0.1
    String.raw`\bDB\s*\d+\s*\.\s*[A-Za-z_]\w*`, // DB1.member
    String.raw`\b(?:PI|PQ|PE|PA)[BWD]\s*\d+\b`, // PIW 256
    String.raw`\b[IQMEAL][BWD]\s*\d+\b`, // MW 10
    String.raw`\b[IQMEAL]\s*\d+\.\d\b`, // I 0.0
    String.raw`\b(?:OB|FB|FC|DB|DI|SFC|SFB|UDT)\s*\d+\b`, // FB 10
    String.raw`\b[TCZ]\s*\d+\b`, // T 1
  ].join('|'),
  'g',
);

function commentStart(line: string): number {
  let quote: string | null = null;
  for (let i = 0; i < line.length; i += 1) {
    const char = line[i];
    if (quote) {
      if (char === quote) quote = null;
    } else if (char === '"' || char === "'") quote = char ?? null;
    else if (char === '/' && line[i + 1] === '/') return i;
  }
  return line.length;
}

/** The operand at 1-based `column` of `line`, normalised for the API; null when none. */
export function operandAt(line: string, column: number): string | null {
  const index = column - 1;
  const end = commentStart(line);
  if (index > end) return null;
  const code = line.slice(0, end);
  OPERAND.lastIndex = 0;
  for (let match = OPERAND.exec(code); match; match = OPERAND.exec(code)) {
    const start = match.index;
    const text = match[0];
    if (start > index || index > start + text.length) continue;
    if (start > 0 && code[start - 1] === '#') return null;
    if (text.startsWith('"')) {
      const close = text.indexOf('"', 1);
      // On the DB's quoted name: the DB itself; on a member: the member path.
      if (index <= start + close) return text.slice(0, close + 1);
      return text.replace(/\s+/g, '');
    }
    return text.replace(/\s+/g, ' ').replace(/ ?\. ?/g, '.');
  }
  return null;
}
