/**
 * What the text around the caret refers to, from the project outline: the block the caret is in
 * (the last block header of this file above it), the block or DB a name means, the members a
 * dotted path reaches.
 */
import type { OutlineBlock, OutlineMember, OutlineSymbol, ProjectOutline } from '../../api/outline';

/** The block of `file` whose header is the nearest above `line`. */
export function blockAt(outline: ProjectOutline | null, file: string | null, line: number): OutlineBlock | null {
  let found: OutlineBlock | null = null;
  for (const block of outline?.blocks ?? []) {
    if (block.file !== file || block.line === null || block.line > line) continue;
    if (!found || (found.line ?? 0) < block.line) found = block;
  }
  return found;
}

/** `FB 10`, `DB1` ... as kind and number. */
function absolute(text: string): { kind: string; number: number } | null {
  const match = /^(OB|FB|FC|DB|DI|UDT)\s*(\d+)$/i.exec(text.trim());
  if (!match) return null;
  const kind = match[1]!.toUpperCase();
  return { kind: kind === 'DI' ? 'DB' : kind, number: Number(match[2]) };
}

export function symbolNamed(outline: ProjectOutline | null, name: string): OutlineSymbol | null {
  const key = name.toLowerCase();
  return outline?.symbols.find((symbol) => symbol.name.toLowerCase() === key) ?? null;
}

/** The block a name means: `"Name"` (its symbol or its own name), or `DB 10`, `FC1`. */
export function blockNamed(outline: ProjectOutline | null, name: string): OutlineBlock | null {
  if (!outline) return null;
  const numbered = absolute(name) ?? absolute(symbolNamed(outline, name)?.address ?? '');
  if (numbered) return outline.blocks.find((b) => b.kind === numbered.kind && b.number === numbered.number) ?? null;
  const key = name.toLowerCase();
  return outline.blocks.find((block) => block.name.toLowerCase() === key) ?? null;
}

/** The block a member's type names (an FB for a multi-instance, a UDT), if the project has it. */
export function blockOfType(outline: ProjectOutline | null, type: string): OutlineBlock | null {
  const quoted = /^"([^"]*)"$/.exec(type.trim());
  return blockNamed(outline, quoted ? quoted[1]! : type);
}

export function memberNamed(block: OutlineBlock | null, path: string): OutlineMember | null {
  const key = path.toLowerCase();
  return block?.members.find((member) => member.path.toLowerCase() === key) ?? null;
}

function hasNested(block: OutlineBlock, member: OutlineMember): boolean {
  const prefix = `${member.path.toLowerCase()}.`;
  return block.members.some((other) => other.path.toLowerCase().startsWith(prefix));
}

/**
 * Follows a dotted path from `block`: through STRUCT members within it, and into the FB or UDT a
 * member's type names. The block reached, the path within it ('' for its top) and the last member.
 */
function walk(
  outline: ProjectOutline | null,
  block: OutlineBlock,
  path: string,
): { block: OutlineBlock; prefix: string; member: OutlineMember | null } | null {
  let current = block;
  let prefix = '';
  let member: OutlineMember | null = null;
  for (const part of path ? path.split('.') : []) {
    member = memberNamed(current, prefix ? `${prefix}.${part}` : part);
    if (!member) return null;
    if (hasNested(current, member)) {
      prefix = member.path;
      continue;
    }
    const typed = blockOfType(outline, member.type);
    if (!typed) return { block: current, prefix: member.path, member };
    current = typed;
    prefix = '';
  }
  return { block: current, prefix, member };
}

/**
 * The members one step below `path` (`''`: the top level) of `block`: a STRUCT's members, or
 * the members of the FB or UDT a member's type names. Array elements and an FB's TEMP are left out.
 */
export function membersBelow(outline: ProjectOutline | null, block: OutlineBlock, path: string): OutlineMember[] {
  const reached = walk(outline, block, path);
  if (!reached) return [];
  const viaType = reached.block !== block;
  if (!reached.prefix) {
    return reached.block.members.filter((m) => m.depth === 0 && !(viaType && m.section === 'TEMP'));
  }
  const parent = memberNamed(reached.block, reached.prefix);
  const prefix = `${reached.prefix.toLowerCase()}.`;
  return reached.block.members.filter(
    (m) => m.depth === (parent?.depth ?? 0) + 1 && m.path.toLowerCase().startsWith(prefix) && !m.name.includes('['),
  );
}

/** The member a dotted path from `block` reaches, following FB and UDT types. */
export function resolveMember(outline: ProjectOutline | null, block: OutlineBlock, path: string): OutlineMember | null {
  const dot = path.lastIndexOf('.');
  if (dot < 0) return memberNamed(block, path);
  const head = walk(outline, block, path.slice(0, dot));
  if (!head) return null;
  const last = path.slice(dot + 1);
  return memberNamed(head.block, head.prefix ? `${head.prefix}.${last}` : last);
}
