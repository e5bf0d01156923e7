// Writes src/editor/monaco/locales/messageIds.json: for each English Monaco text that Nasaq
// translates (the keys of locales/fa.json), the numbers under which this Monaco build looks it
// up (`localize(<n>, "<English>")`). Run it after upgrading monaco-editor:
//   node frontend/scripts/monaco-nls-ids.mjs
// (tests/frontend/monacoLocales.test.ts fails while the file is out of date).
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { messageIdsOf, scanMonacoMessages } from './monacoNls.mjs';

const locales = fileURLToPath(new URL('../src/editor/monaco/locales/', import.meta.url));
const english = Object.keys(JSON.parse(readFileSync(`${locales}fa.json`, 'utf8')));
const ids = messageIdsOf(scanMonacoMessages(), english);
const lines = Object.entries(ids).map(([text, numbers]) => `  ${JSON.stringify(text)}: ${JSON.stringify(numbers)}`);
writeFileSync(`${locales}messageIds.json`, `{\n${lines.join(',\n')}\n}\n`);
