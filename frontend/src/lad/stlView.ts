/**
 * The STL view of a LAD/FBD file goes back network by network, as STEP 7 converts a block's
 * networks: a network whose STL the user did not touch keeps its drawing (the same object, so its
 * lines in the file do not change either), only the networks typed or changed are lifted anew
 * (and stay STL networks with their reason where they have no LAD shape). Networks are matched by
 * their text, in order, so inserting or deleting a network in the STL keeps the others.
 */
import type { LadBlock, Network } from './model';
import { BLOCK_START } from './textEdit';

const NETWORK = /^\s*NETWORK(?!\w)/i;
const BLOCK_END = /^\s*END_(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION)(?!\w)/i;

interface StlBlock {
  header: string;
  networks: string[];
}

/** An STL source cut into blocks, each into its header and its networks' texts. */
export function splitStl(text: string): StlBlock[] {
  const blocks: StlBlock[] = [];
  let current: { header: string[]; networks: string[][] } | null = null;
  const finish = () => {
    if (current) blocks.push({ header: current.header.join('\n'), networks: current.networks.map((lines) => lines.join('\n').trimEnd()) });
    current = null;
  };
  for (const line of text.split('\n')) {
    if (BLOCK_START.test(line)) {
      finish();
      current = { header: [line], networks: [] };
    } else if (!current) {
      continue;
    } else if (BLOCK_END.test(line)) {
      finish();
    } else if (NETWORK.test(line)) {
      current.networks.push([line]);
    } else if (current.networks.length > 0) {
      current.networks[current.networks.length - 1]?.push(line);
    } else {
      current.header.push(line);
    }
  }
  finish();
  return blocks;
}

/** For each item of `after`, the index of the equal item of `before` it keeps (longest common subsequence), or -1. */
export function matchInOrder(before: readonly string[], after: readonly string[]): number[] {
  const rows = before.length;
  const cols = after.length;
  const lengths: number[][] = Array.from({ length: rows + 1 }, () => new Array<number>(cols + 1).fill(0));
  for (let i = rows - 1; i >= 0; i -= 1) {
    for (let j = cols - 1; j >= 0; j -= 1) {
      const row = lengths[i] as number[];
      row[j] = before[i] === after[j] ? (lengths[i + 1]?.[j + 1] ?? 0) + 1 : Math.max(lengths[i + 1]?.[j] ?? 0, row[j + 1] ?? 0);
    }
  }
  const matched = new Array<number>(cols).fill(-1);
  let i = 0;
  let j = 0;
  while (i < rows && j < cols) {
    if (before[i] === after[j]) {
      matched[j] = i;
      i += 1;
      j += 1;
    } else if ((lengths[i + 1]?.[j] ?? 0) >= (lengths[i]?.[j + 1] ?? 0)) i += 1;
    else j += 1;
  }
  return matched;
}

/**
 * The blocks after the STL view's edit: `lifted` is the whole edited STL lifted by the server;
 * where a block's header or a network's STL is as it was (`shownStl` is what the view showed for
 * `model`), the model's own header or network is kept. Null when the edit changed the blocks
 * themselves (added or removed one): then `lifted` is taken whole.
 */
export function mergeLifted(model: readonly LadBlock[], shownStl: string, editedStl: string, lifted: readonly LadBlock[]): LadBlock[] | null {
  const shown = splitStl(shownStl);
  const edited = splitStl(editedStl);
  if (shown.length !== model.length || edited.length !== lifted.length || edited.length !== model.length) return null;
  return lifted.map((block, b) => {
    const before = model[b] as LadBlock;
    const old = shown[b] as StlBlock;
    const now = edited[b] as StlBlock;
    if (old.networks.length !== before.networks.length || now.networks.length !== block.networks.length) return block;
    const kept = matchInOrder(old.networks, now.networks);
    const networks: Network[] = block.networks.map((network, k) => {
      const from = kept[k] ?? -1;
      return from >= 0 ? (before.networks[from] as Network) : network;
    });
    const header = old.header === now.header ? { language: before.language, kind: before.kind, name: before.name, return_type: before.return_type, title: before.title, declarations: before.declarations } : { language: before.language };
    return { ...block, ...header, networks };
  });
}
