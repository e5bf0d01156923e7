// Reads the English texts of the installed monaco-editor ESM build: each `localize(<n>, "...")`
// and `localize2(<n>, "...")` call, as a map from message number to English text.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { runInNewContext } from 'node:vm';

const CALL = /localize2?\((\d+),\s*("(?:[^"\\]|\\.)*"|'(?:[^'\\]|\\.)*')/g;

/** The text of a JavaScript string literal (the regex admits nothing else). */
function unquote(literal) {
  return runInNewContext(literal);
}

function* scripts(folder) {
  for (const name of readdirSync(folder)) {
    const path = join(folder, name);
    if (statSync(path).isDirectory()) yield* scripts(path);
    else if (name.endsWith('.js')) yield path;
  }
}

/** Message number → English text, for every numbered message of Monaco's ESM build. */
export function scanMonacoMessages() {
  const require = createRequire(import.meta.url);
  const root = dirname(require.resolve('monaco-editor/nls')); // …/esm/vs
  const messages = new Map();
  for (const path of scripts(root)) {
    for (const match of readFileSync(path, 'utf8').matchAll(CALL)) messages.set(Number(match[1]), unquote(match[2]));
  }
  return messages;
}

/** For each English text, the sorted message numbers that carry it (texts Monaco lacks: none). */
export function messageIdsOf(messages, english) {
  const wanted = new Set(english);
  const ids = Object.fromEntries(english.map((text) => [text, []]));
  for (const [id, text] of [...messages].sort((a, b) => a[0] - b[0])) if (wanted.has(text)) ids[text].push(id);
  return ids;
}
