/**
 * What the editor offers at the caret (Ctrl+Space, or while typing): decided from the text before
 * the caret and the project outline, independent of Monaco (`register.ts` adapts the result).
 *
 * - after `"DbName".`, `DB10.`, `#instance.` (in SCL also `instance.`): the members one level down;
 * - after `#`: the members of the block the caret is in;
 * - after an opening `"`: symbols and named blocks, inserted with both quotes;
 * - STL, at a statement's start: the instructions of the file's mnemonic set
 *   (`mnemonicSet.ts`) and the block keywords; after CALL/UC/CC: the FCs and FBs; elsewhere:
 *   symbols, the block's members as `#name` and the DBs;
 * - SCL: keywords, IF/CASE/FOR/WHILE/REPEAT snippets, the standard functions with their
 *   parameters, the block's members as bare names, symbols, blocks and data types.
 */
import type { OutlineBlock, OutlineMember, ProjectOutline } from '../../api/outline';
import { SCL_KEYWORDS, SCL_STANDARD_FUNCTIONS, SCL_VAR_KEYWORDS, SCL_WORD_OPERATORS } from '../languages/scl';
import { PLC_TYPES, STL_BLOCK_KEYWORDS, STL_VAR_KEYWORDS } from '../languages/stl';
import { catalogueOf, functionHelp, instructionHelp } from './help';
import type { HelpCatalogue } from './help/en';
import { detectMnemonicSet, mnemonicsOf } from './mnemonicSet';
import { blockAt, blockNamed, membersBelow } from './scope';

export type SuggestionKind = 'instruction' | 'keyword' | 'snippet' | 'function' | 'symbol' | 'member' | 'block' | 'type';

export interface Suggestion {
  label: string;
  kind: SuggestionKind;
  insertText: string;
  /** `insertText` is a snippet with `${1:placeholders}`. */
  snippet?: boolean;
  detail?: string;
  documentation?: string;
  /** What Monaco matches the typed text against, when it is not the label. */
  filterText?: string;
  sortText: string;
}

export interface CompletionRequest {
  /** The whole text of the model. */
  text: string;
  /** 1-based line and column of the caret. */
  line: number;
  column: number;
  language: 'stl' | 'scl';
  outline: ProjectOutline | null;
  /** The model's file in the project, to find the block around the caret. */
  file: string | null;
  /** The interface language, for the help shown with instructions and functions. */
  uiLanguage: string;
}

export interface Completion {
  /** The columns the chosen suggestion replaces: [from, to). */
  from: number;
  to: number;
  suggestions: Suggestion[];
}

const MEMBER_ACCESS = /(?:"([^"\n]+)"|\b(DB|DI)[ \t]*(\d+)|(#?[A-Za-z_]\w*))((?:\.[A-Za-z_]\w*)*)\.([A-Za-z_]\w*)?$/i;
const STL_STATEMENT_START = /^\s*(?:[A-Za-z_]\w{0,3}\s*:(?!=)\s*)?([^\s;"#]*)$/;
const STL_CALL = /\b(?:CALL|UC|CC)\s+([A-Za-z_]\w*)?$/i;
const WORD = /[A-Za-z_]\w*$/;

/** Whether a `//` comment has started (outside quotes and strings). */
function inComment(before: string): boolean {
  let quote: string | null = null;
  for (let i = 0; i < before.length; i += 1) {
    const char = before[i];
    if (quote) {
      if (char === quote) quote = null;
    } else if (char === '"' || char === "'") quote = char;
    else if (char === '/' && before[i + 1] === '/') return true;
  }
  return false;
}

function quotesBefore(before: string): number {
  return (before.match(/"/g) ?? []).length;
}

function memberItem(member: OutlineMember, insert: string, order: string): Suggestion {
  return {
    label: insert,
    kind: 'member',
    insertText: insert,
    detail: `${member.type} · ${member.section}`,
    documentation: member.comment || undefined,
    sortText: `${order}${member.path}`,
    filterText: insert,
  };
}

function symbolItems(outline: ProjectOutline | null, quoted: boolean, order: string, catalogue: HelpCatalogue): Suggestion[] {
  const items: Suggestion[] = (outline?.symbols ?? []).map((symbol) => ({
    label: `"${symbol.name}"`,
    kind: 'symbol',
    insertText: `"${symbol.name}"`,
    detail: `${symbol.address} · ${symbol.type}`,
    documentation: symbol.comment || undefined,
    filterText: quoted ? `"${symbol.name}"` : symbol.name,
    sortText: `${order}${symbol.name}`,
  }));
  const named = new Set(items.map((item) => item.label.toLowerCase()));
  for (const block of outline?.blocks ?? []) {
    if (!block.name || named.has(`"${block.name.toLowerCase()}"`)) continue;
    items.push({
      label: `"${block.name}"`,
      kind: 'block',
      insertText: `"${block.name}"`,
      detail: `${block.kind} ${block.number} · ${catalogue.labels.block}`,
      filterText: quoted ? `"${block.name}"` : block.name,
      sortText: `${order}${block.name}`,
    });
  }
  return items;
}

function blockLabel(block: OutlineBlock): string {
  return block.name ? `"${block.name}"` : `${block.kind} ${block.number}`;
}

function callTargets(outline: ProjectOutline | null): Suggestion[] {
  return (outline?.blocks ?? [])
    .filter((block) => block.kind === 'FC' || block.kind === 'FB')
    .map((block) => ({
      label: blockLabel(block),
      kind: 'block',
      insertText: blockLabel(block),
      detail: `${block.kind} ${block.number}${block.return_type ? ` : ${block.return_type}` : ''}`,
      filterText: block.name || `${block.kind}${block.number}`,
      sortText: `0${block.name || block.kind + block.number}`,
    }));
}

function instructionItems(text: string, uiLanguage: string): Suggestion[] {
  const set = detectMnemonicSet(text);
  const catalogue = catalogueOf(uiLanguage);
  const items: Suggestion[] = mnemonicsOf(set).map((mnemonic) => {
    const help = instructionHelp(mnemonic, set, uiLanguage);
    return {
      label: mnemonic,
      kind: 'instruction',
      insertText: mnemonic,
      detail: `${catalogue.labels.instruction}${help ? ` · ${help.syntax}` : ''}`,
      documentation: help?.text,
      sortText: `0${mnemonic}`,
    };
  });
  for (const keyword of [...STL_BLOCK_KEYWORDS, ...STL_VAR_KEYWORDS]) {
    items.push({ label: keyword, kind: 'keyword', insertText: keyword, detail: catalogue.labels.keyword, sortText: `2${keyword}` });
  }
  return items;
}

const SNIPPETS: Array<{ label: string; key: 'ifSnippet' | 'ifElseSnippet' | 'caseSnippet' | 'forSnippet' | 'whileSnippet' | 'repeatSnippet'; body: string }> = [
  { label: 'IF', key: 'ifSnippet', body: 'IF ${1:condition} THEN\n\t$0\nEND_IF;' },
  { label: 'IF … ELSE', key: 'ifElseSnippet', body: 'IF ${1:condition} THEN\n\t${2}\nELSE\n\t$0\nEND_IF;' },
  { label: 'CASE', key: 'caseSnippet', body: 'CASE ${1:selector} OF\n\t${2:1}:\n\t\t${3}\nELSE\n\t$0\nEND_CASE;' },
  { label: 'FOR', key: 'forSnippet', body: 'FOR ${1:i} := ${2:1} TO ${3:10} DO\n\t$0\nEND_FOR;' },
  { label: 'WHILE', key: 'whileSnippet', body: 'WHILE ${1:condition} DO\n\t$0\nEND_WHILE;' },
  { label: 'REPEAT', key: 'repeatSnippet', body: 'REPEAT\n\t$0\nUNTIL ${1:condition}\nEND_REPEAT;' },
];

/** The call of a standard function with a placeholder for each parameter. */
export function functionSnippet(name: string, inputs: readonly string[]): string {
  if (!inputs.length) return `${name}(\${1})`;
  return `${name}(${inputs.map((input, i) => `${input} := \${${i + 1}}`).join(', ')})`;
}

function sclItems(request: CompletionRequest, block: OutlineBlock | null): Suggestion[] {
  const catalogue = catalogueOf(request.uiLanguage);
  const items: Suggestion[] = [];
  for (const member of block?.members.filter((m) => m.depth === 0) ?? []) {
    items.push(memberItem(member, member.name, '0'));
  }
  for (const snippet of SNIPPETS) {
    items.push({
      label: snippet.label,
      kind: 'snippet',
      insertText: snippet.body,
      snippet: true,
      detail: catalogue.labels[snippet.key],
      filterText: snippet.label.split(' ')[0],
      sortText: `1${snippet.label}`,
    });
  }
  for (const name of SCL_STANDARD_FUNCTIONS) {
    const help = functionHelp(name, request.uiLanguage);
    items.push({
      label: name,
      kind: 'function',
      insertText: functionSnippet(name, help?.inputs ?? []),
      snippet: true,
      detail: help ? help.syntax : catalogue.labels.standardFunction,
      documentation: help?.text,
      sortText: `3${name}`,
    });
  }
  for (const keyword of [...SCL_KEYWORDS, ...SCL_VAR_KEYWORDS, ...SCL_WORD_OPERATORS, 'TRUE', 'FALSE']) {
    items.push({ label: keyword, kind: 'keyword', insertText: keyword, detail: catalogue.labels.keyword, sortText: `4${keyword}` });
  }
  for (const type of PLC_TYPES) items.push({ label: type, kind: 'type', insertText: type, detail: catalogue.labels.type, sortText: `5${type}` });
  items.push(...symbolItems(request.outline, false, '2', catalogue));
  return items;
}

/**
 * Member access (`"Db".`, `DB10.`, `#inst.`), `#` and an open quote: the completions that read
 * the same in an STL line and in an operand typed on a LAD/FBD element.
 */
function accessCompletion(
  before: string,
  after: string,
  column: number,
  outline: ProjectOutline | null,
  block: OutlineBlock | null,
  language: 'stl' | 'scl',
  catalogue: HelpCatalogue,
): Completion | null {
  const access = MEMBER_ACCESS.exec(before);
  if (access && quotesBefore(before.slice(0, access.index)) % 2 === 0) {
    const [, quoted, area, number, word, rest = '', partial = ''] = access;
    let base: OutlineBlock | null = null;
    let path = rest.replace(/^\./, '');
    if (quoted !== undefined) base = blockNamed(outline, quoted);
    else if (area !== undefined) base = blockNamed(outline, `DB ${number}`);
    else if (word !== undefined && (word.startsWith('#') || language === 'scl') && block) {
      base = block;
      path = [word.replace(/^#/, ''), path].filter(Boolean).join('.');
    }
    const members = base ? membersBelow(outline, base, path) : [];
    if (base || quoted !== undefined || area !== undefined || word?.startsWith('#')) {
      return {
        from: column - partial.length,
        to: column,
        suggestions: members.map((member) => memberItem(member, member.name, '0')),
      };
    }
  }

  const hash = /#(\w*)$/.exec(before);
  if (hash) {
    return {
      from: column - hash[0].length,
      to: column,
      suggestions: (block?.members.filter((m) => m.depth === 0) ?? []).map((m) => memberItem(m, `#${m.name}`, '0')),
    };
  }

  if (quotesBefore(before) % 2 === 1) {
    const open = before.lastIndexOf('"');
    return {
      from: open + 1,
      to: column + (after.startsWith('"') ? 1 : 0),
      suggestions: symbolItems(outline, true, '0', catalogue),
    };
  }

  return null;
}

/** The suggestions at the caret; null where nothing should be offered (inside a comment). */
export function complete(request: CompletionRequest): Completion | null {
  const lineText = request.text.split('\n')[request.line - 1] ?? '';
  const before = lineText.slice(0, request.column - 1);
  const after = lineText.slice(request.column - 1);
  if (inComment(before)) return null;
  const catalogue = catalogueOf(request.uiLanguage);
  const { outline, column } = request;
  const block = blockAt(outline, request.file, request.line);

  const access = accessCompletion(before, after, column, outline, block, request.language, catalogue);
  if (access) return access;

  const partial = WORD.exec(before)?.[0] ?? '';
  if (request.language === 'scl') {
    return { from: column - partial.length, to: column, suggestions: sclItems(request, block) };
  }

  const call = STL_CALL.exec(before);
  if (call) return { from: column - partial.length, to: column, suggestions: callTargets(outline) };

  const start = STL_STATEMENT_START.exec(before);
  if (start) {
    const typed = start[1] ?? '';
    return { from: column - typed.length, to: column, suggestions: instructionItems(request.text, request.uiLanguage) };
  }

  const operands: Suggestion[] = [
    ...(block?.members.filter((m) => m.depth === 0) ?? []).map((m) => ({ ...memberItem(m, `#${m.name}`, '0'), filterText: m.name })),
    ...symbolItems(outline, false, '1', catalogue),
  ];
  return { from: column - partial.length, to: column, suggestions: operands };
}

/**
 * What an operand typed on a LAD/FBD element can be, for the text typed so far: members after
 * `#`, `"Db".` or `DB10.`, symbols after a quote, else the block's members and the symbols.
 */
export function completeOperand(typed: string, outline: ProjectOutline | null, block: OutlineBlock | null, uiLanguage: string): Completion {
  const catalogue = catalogueOf(uiLanguage);
  const column = typed.length + 1;
  const access = accessCompletion(typed, '', column, outline, block, 'stl', catalogue);
  if (access) return access;
  const partial = WORD.exec(typed)?.[0] ?? '';
  const suggestions: Suggestion[] = [
    ...(block?.members.filter((m) => m.depth === 0) ?? []).map((m) => ({ ...memberItem(m, `#${m.name}`, '0'), filterText: m.name })),
    ...symbolItems(outline, false, '1', catalogue),
  ];
  return { from: column - partial.length, to: column, suggestions };
}
