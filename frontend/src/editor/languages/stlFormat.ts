/**
 * "Format document" for STL sources: the column layout of the sources STEP 7 generates.
 *
 *   M001: A     I      0.0;                // comment
 *         CALL  "Scale" (
 *              Raw                      := "Level sensor",
 *
 * In the code of a block (between BEGIN and its END_…), a label ends at column 6, the mnemonic
 * starts at column 7 in a field of six, the operand follows, then `;`; an absolute address has
 * its byte number right-aligned (`I      0.0`, `MW    20`); a comment starts at column 37. The
 * parameters of a CALL are indented by 11 with their names in a field of 25. Declarations, data
 * blocks, NETWORK/TITLE lines and comment lines keep their layout; nothing but spaces changes.
 */

const LABEL_WIDTH = 6;
const MNEMONIC_WIDTH = 6;
const COMMENT_COLUMN = 36;
const PARAMETER_INDENT = 11;
const PARAMETER_WIDTH = 25;

/** Memory areas whose absolute addresses STEP 7 writes with the byte number right-aligned. */
const AREA = /^(?:([IQEAML]|DBX|DIX)\s*(\d+)(\.\d+)|([TCZ]|[IQEAMLV][BWD]|P[IQEA][BWD]|DB[BWD]|DI[BWD])\s*(\d+))$/i;
/** Jumps take a label (`M001`, `T1`), never an address. */
const JUMP = /^(J\w*|SP\w*|LOOP)$/i;

const CODE_BLOCK = /^\s*(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)\b/i;
const OTHER_BLOCK = /^\s*(DATA_BLOCK|TYPE)\b/i;
const BLOCK_END = /^\s*END_(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION|DATA_BLOCK|TYPE)\b/i;
const BEGIN = /^\s*BEGIN\b/i;
const KEEP = /^\s*(NETWORK|TITLE|\/\/|$)/i;
const PARAMETER = /^\s*([A-Za-z_#][\w.#]*)\s*:=\s*(.*)$/;
const LABEL = /^\s*([A-Za-z_]\w{0,3})\s*:(?!=)\s*/;

interface Statement {
  label: string | null;
  code: string;
  /** `;` was there. */
  terminated: boolean;
  /** After `;`: `// comment` or other text, trimmed. */
  rest: string;
}

/** Splits at the first `;` (or `//`) outside quotes. */
function splitStatement(line: string): { code: string; terminated: boolean; rest: string } {
  let quote: string | null = null;
  for (let i = 0; i < line.length; i += 1) {
    const char = line[i] ?? '';
    if (quote) {
      if (char === quote) quote = null;
      continue;
    }
    if (char === '"' || char === "'") quote = char;
    else if (char === ';') return { code: line.slice(0, i), terminated: true, rest: line.slice(i + 1).trim() };
    else if (char === '/' && line[i + 1] === '/') return { code: line.slice(0, i), terminated: false, rest: line.slice(i).trim() };
  }
  return { code: line, terminated: false, rest: '' };
}

function parse(line: string): Statement {
  let body = line;
  let label: string | null = null;
  const labelled = LABEL.exec(line);
  if (labelled) {
    label = labelled[1] ?? null;
    body = line.slice(labelled[0].length);
  }
  const { code, terminated, rest } = splitStatement(body);
  return { label, code: code.trim(), terminated, rest };
}

/** `I 0.0` → `I      0.0`, `MW20` → `MW    20`; other operands keep their text. */
function formatOperand(mnemonic: string, operand: string): string {
  const address = JUMP.test(mnemonic) ? null : AREA.exec(operand);
  if (!address) return operand;
  const area = address[1] ?? address[4] ?? '';
  const byte = address[2] ?? address[5] ?? '';
  const bit = address[3] ?? '';
  const pad = Math.max(1, 8 - area.length - byte.length);
  return `${area}${' '.repeat(pad)}${byte}${bit}`;
}

function withComment(code: string, rest: string): string {
  if (!rest) return code;
  const gap = rest.startsWith('//') && code.length < COMMENT_COLUMN ? COMMENT_COLUMN - code.length : 1;
  return `${code}${' '.repeat(gap)}${rest}`;
}

function formatStatement(line: string): string {
  const { label, code, terminated, rest } = parse(line);
  const labelField = label ? `${label}:`.padEnd(LABEL_WIDTH) : ' '.repeat(LABEL_WIDTH);
  const head = label && `${label}:`.length >= LABEL_WIDTH ? `${label}: ` : labelField;
  if (!code) {
    if (!label) return line.trimEnd();
    return withComment(`${label}:${terminated ? ' ;' : ''}`.trimEnd(), rest);
  }
  const space = code.search(/\s/);
  const mnemonic = space < 0 ? code : code.slice(0, space);
  const operand = space < 0 ? '' : code.slice(space).trim();
  const mnemonicField = mnemonic.length >= MNEMONIC_WIDTH ? `${mnemonic} ` : mnemonic.padEnd(MNEMONIC_WIDTH);
  const statement = `${head}${mnemonicField}${formatOperand(mnemonic, operand)}`;
  return withComment(terminated ? `${statement};` : statement.trimEnd(), rest);
}

function formatParameter(line: string): string {
  const parameter = PARAMETER.exec(line);
  if (!parameter) return line.trimEnd();
  const name = parameter[1] ?? '';
  const field = name.length >= PARAMETER_WIDTH ? `${name} ` : name.padEnd(PARAMETER_WIDTH);
  const { code, terminated, rest } = splitStatement(parameter[2] ?? '');
  const value = `${' '.repeat(PARAMETER_INDENT)}${field}:= ${code.trim()}${terminated ? ';' : ''}`;
  return withComment(value, rest);
}

/** The STL source laid out in STEP 7's columns (see above). Line ends are kept. */
export function formatStl(text: string): string {
  const eol = text.includes('\r\n') ? '\r\n' : '\n';
  const lines = text.split(/\r?\n/);
  let inBlock = false;
  let inCode = false;
  let inCall = false;
  const out = lines.map((line) => {
    if (BLOCK_END.test(line)) {
      inBlock = false;
      inCode = false;
      inCall = false;
      return line;
    }
    if (CODE_BLOCK.test(line) && !inBlock) {
      inBlock = true;
      return line;
    }
    if (OTHER_BLOCK.test(line) && !inBlock) {
      inBlock = false;
      return line;
    }
    if (inBlock && !inCode && BEGIN.test(line)) {
      inCode = true;
      return line;
    }
    if (!inCode || KEEP.test(line)) return line;
    if (inCall) {
      if (PARAMETER.test(line)) {
        if (splitStatement(line).code.trimEnd().endsWith(')')) inCall = false;
        return formatParameter(line);
      }
      inCall = false;
    }
    const formatted = formatStatement(line);
    const { code } = splitStatement(line);
    if (/^\s*(\w+:\s*)?CALL\b.*\($/i.test(code.trimEnd())) inCall = true;
    return formatted;
  });
  return out.join(eol);
}
