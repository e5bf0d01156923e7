/**
 * Copy, cut and paste of networks, within a block, between blocks and between files: the
 * networks themselves are kept in the page (exact, with STL networks and ids), and their text is
 * put on the system clipboard too, so they can be pasted into the text view or another program.
 * Text copied elsewhere (networks in the `.lad` format) is pasted through the server's reader.
 */
import { readLad } from '../api/client';
import type { LadBlock, Network } from './model';
import { printLad } from './print';

let copied: { networks: readonly Network[]; text: string } | null = null;

const BEGIN = /^\s*BEGIN(?!\w)/i;
const BLOCK_END = /^\s*END_(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)(?!\w)/i;

/** The networks as the text format writes them (without their block). */
export function networksText(block: LadBlock, networks: readonly Network[]): string {
  const lines = printLad([{ ...block, networks: [...networks] }]).split('\n');
  const begin = lines.findIndex((line) => BEGIN.test(line));
  const end = lines.findIndex((line) => BLOCK_END.test(line));
  return `${lines.slice(begin + 1, end).join('\n')}\n`;
}

export function copyNetworks(block: LadBlock, networks: readonly Network[]): void {
  const text = networksText(block, networks);
  copied = { networks, text };
  navigator.clipboard?.writeText(text).catch(() => undefined);
}

/**
 * What to paste: the networks copied in this page when the system clipboard still holds their
 * text (or cannot be read), else the networks read from the clipboard's text; null when it holds
 * no networks.
 */
export async function pasteNetworks(): Promise<readonly Network[] | null> {
  let text: string | null = null;
  try {
    text = (await navigator.clipboard?.readText()) ?? null;
  } catch {
    text = null;
  }
  if (copied && (text === null || text === copied.text)) return copied.networks;
  if (!text || !/^\s*NETWORK(?!\w)/im.test(text)) return copied?.networks ?? null;
  try {
    const read = await readLad('clipboard.lad', `ORGANIZATION_BLOCK OB 1\nBEGIN\n${text}\nEND_ORGANIZATION_BLOCK\n`);
    if (read.diagnostics.some((d) => d.severity === 'error')) return null;
    return read.blocks[0]?.networks ?? null;
  } catch {
    return null;
  }
}

/** Forgets what was copied (tests). */
export function clearClipboard(): void {
  copied = null;
}
