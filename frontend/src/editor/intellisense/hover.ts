/**
 * What the editor explains under the mouse, independent of Monaco (`register.ts` renders it):
 * an STL instruction (at a statement's start, in the file's mnemonic set) or an SCL standard
 * function, with syntax, meaning and the status bits it writes, in the interface language; a
 * symbol (address, type, comment); a block; a member of the block's interface or of a DB (type,
 * section, comment).
 */
import type { ProjectOutline } from '../../api/outline';
import { catalogueOf, functionHelp, instructionHelp } from './help';
import { detectMnemonicSet } from './mnemonicSet';
import { blockAt, blockNamed, resolveMember, symbolNamed } from './scope';

/** A part of the hover: code (always left to right) or text in the interface language. */
export type HoverPart = { kind: 'code'; text: string } | { kind: 'text'; text: string };

export interface HoverRequest {
  text: string;
  line: number;
  column: number;
  language: 'stl' | 'scl';
  outline: ProjectOutline | null;
  file: string | null;
  uiLanguage: string;
}

export interface HoverResult {
  /** The columns of the word explained: [from, to). */
  from: number;
  to: number;
  parts: HoverPart[];
}

const STATEMENT = /^(\s*(?:[A-Za-z_]\w{0,3}\s*:(?!=)\s*)?)([^\s;"]+)/;
const CHAIN = /(?:"[^"\n]*"|\b(?:DB|DI)[ \t]*\d+|#?[A-Za-z_]\w*)(?:\.[A-Za-z_]\w*)*/gi;

function commentStart(line: string): number {
  let quote: string | null = null;
  for (let i = 0; i < line.length; i += 1) {
    const char = line[i];
    if (quote) {
      if (char === quote) quote = null;
    } else if (char === '"' || char === "'") quote = char;
    else if (char === '/' && line[i + 1] === '/') return i;
  }
  return line.length;
}

function instructionHover(request: HoverRequest, lineText: string): HoverResult | null {
  const match = STATEMENT.exec(lineText);
  if (!match) return null;
  const from = (match[1] ?? '').length + 1;
  const word = match[2] ?? '';
  if (request.column < from || request.column > from + word.length) return null;
  // `Name : INT` (a declaration) and `Name := value` (a parameter, a DB value) are no instructions.
  if (/^\s*:/.test(lineText.slice(from - 1 + word.length))) return null;
  const set = detectMnemonicSet(request.text);
  const help = instructionHelp(word, set, request.uiLanguage);
  if (!help) return null;
  const labels = catalogueOf(request.uiLanguage).labels;
  const parts: HoverPart[] = [
    { kind: 'code', text: help.syntax },
    { kind: 'text', text: help.text },
    { kind: 'text', text: `${labels.status}: ${help.status.length ? help.status.join(', ') : labels.none}` },
  ];
  if (help.otherSpelling) parts.push({ kind: 'text', text: `${labels.spelledAs}: ${help.otherSpelling}` });
  return { from, to: from + word.length, parts };
}

interface Segment {
  text: string;
  from: number;
}

/** The dotted name around the column, split at its dots, and the index of the part hovered. */
function chainAt(lineText: string, column: number): { segments: Segment[]; index: number } | null {
  CHAIN.lastIndex = 0;
  for (let match = CHAIN.exec(lineText); match; match = CHAIN.exec(lineText)) {
    const start = match.index + 1;
    if (column < start || column > start + match[0].length) continue;
    const segments: Segment[] = [];
    let offset = start;
    const first = /^(?:"[^"\n]*"|(?:DB|DI)[ \t]*\d+|#?[A-Za-z_]\w*)/i.exec(match[0])?.[0] ?? match[0];
    segments.push({ text: first, from: offset });
    offset += first.length;
    for (const part of match[0].slice(first.length).split('.').slice(1)) {
      offset += 1;
      segments.push({ text: part, from: offset });
      offset += part.length;
    }
    const index = segments.findIndex((segment) => column >= segment.from && column <= segment.from + segment.text.length);
    return index < 0 ? null : { segments, index };
  }
  return null;
}

export function hoverAt(request: HoverRequest): HoverResult | null {
  const lineText = request.text.split('\n')[request.line - 1] ?? '';
  if (request.column - 1 >= commentStart(lineText)) return null;
  const labels = catalogueOf(request.uiLanguage).labels;
  if (request.language === 'stl') {
    const instruction = instructionHover(request, lineText);
    if (instruction) return instruction;
  }
  const chain = chainAt(lineText, request.column);
  if (!chain) return null;
  const { segments, index } = chain;
  const hovered = segments[index]!;
  const span = { from: hovered.from, to: hovered.from + hovered.text.length };
  const head = segments[0]!.text;
  const { outline } = request;

  if (index === 0 && head.startsWith('"')) {
    const name = head.slice(1, -1);
    const symbol = symbolNamed(outline, name);
    const block = blockNamed(outline, name);
    const parts: HoverPart[] = [];
    if (symbol) {
      parts.push({ kind: 'code', text: `"${symbol.name}"  ${symbol.address}  ${symbol.type}` });
      parts.push({ kind: 'text', text: `${labels.symbol} · ${labels.address}: ${symbol.address} · ${labels.type}: ${symbol.type}` });
      if (symbol.comment) parts.push({ kind: 'text', text: symbol.comment });
    } else if (block) {
      parts.push({ kind: 'code', text: `${block.kind} ${block.number} "${block.name}"` });
    }
    if (block?.return_type) parts.push({ kind: 'text', text: `${labels.returns}: ${block.return_type}` });
    if (block?.instance_of) parts.push({ kind: 'text', text: `${labels.instanceOf}: ${block.instance_of}` });
    return parts.length ? { ...span, parts } : null;
  }

  if (request.language === 'scl' && index === 0 && segments.length === 1) {
    const after = lineText.slice(span.to - 1);
    const help = functionHelp(head, request.uiLanguage);
    if (help && /^\s*\(/.test(after)) {
      return { ...span, parts: [{ kind: 'code', text: help.syntax }, { kind: 'text', text: help.text }] };
    }
  }

  const current = blockAt(outline, request.file, request.line);
  let base = null;
  let names = segments.slice(1, index + 1).map((segment) => segment.text);
  if (head.startsWith('"')) base = blockNamed(outline, head.slice(1, -1));
  else if (/^(?:DB|DI)/i.test(head) && /\d$/.test(head)) base = blockNamed(outline, head.replace(/^DI/i, 'DB'));
  else if (head.startsWith('#') || request.language === 'scl') {
    base = current;
    names = [head.replace(/^#/, ''), ...names];
  }
  if (!base || !names.length) return null;
  const member = resolveMember(outline, base, names.join('.'));
  if (!member) return null;
  const parts: HoverPart[] = [
    { kind: 'code', text: `${member.path} : ${member.type}` },
    { kind: 'text', text: `${labels.member} · ${labels.section}: ${member.section}` },
  ];
  if (member.comment) parts.push({ kind: 'text', text: member.comment });
  return { ...span, parts };
}
