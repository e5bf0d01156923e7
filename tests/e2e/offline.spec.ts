/**
 * A classroom may have no internet: the built front end and the API docs must load everything
 * from the Nasaq server itself.
 */
import fs from 'node:fs';
import path from 'node:path';
import { test, expect } from './fixtures';

const dist = path.resolve(__dirname, '../../frontend/dist');

/** Strings that look like URLs but are never fetched: XML namespaces, error texts, comments. Each is
 * an exact URL, never a pattern that could let a real one through. */
const NEVER_FETCHED = [
  /^http:\/\/www\.w3\.org\/(2000\/svg|1999\/xlink|1999\/xhtml|1998\/Math\/MathML|XML\/1998\/namespace|2000\/xmlns\/?)$/,
  /^https:\/\/react\.dev\/errors\/$/, // React's production error text
  /^https:\/\/react\.i18next\.com\/latest\/usetranslation-hook$/, // a react-i18next warning text
  // Monaco 0.57.0 (the lazily loaded editor chunk). Each is text inside a message, a comment or
  // a default setting that nothing in the standalone editor opens or fetches:
  /^https:\/\/code\.visualstudio\.com\/docs\/editor\/codebasics#_find-and-replace$/, // "too many cursors" notification text (logged, not shown as a link)
  /^https:\/\/code\.visualstudio\.com\/docs\/editor\/codebasics#_multicursor-modifier$/, // a setting's description; the standalone editor has no settings UI
  /^https:\/\/github\.com\/microsoft\/monaco-editor#faq$/, // console warning when a web worker cannot start
  /^https:\/\/github\.com\/microsoft\/vscode\/issues\/new$/, // VS Code's product defaults (reportIssueUrl): no UI in the standalone editor uses it
  /^https:\/\/github\.com\/microsoft\/vscode\/blob\/main\/LICENSE\.txt$/, // the same product defaults (licenseUrl, serverLicenseUrl)
  /^https:\/\/github\.com\/microsoft\/vscode\/issues\/103170$/, // a CSS comment inside a style sheet string
  /^https:\/\/github\.com\/markedjs\/marked\.$/, // marked's error text ("Please report this to ...")
  /^https:\/\/microsoft\.com$/, // Monaco's markdown renderer: stand-in target for an unfinished link while streaming chat text (fillInIncompleteTokens; hovers never set it)
  // elkjs 0.12.1 (the diagram layout, in its worker): Java code compiled to JavaScript, carrying
  // the Eclipse Modeling Framework's package and XML Schema type names. They are identifiers
  // (namespace URIs compared as strings), never opened:
  /^http:\/\/www\.w3\.org\/2001\/XMLSchema#(boolean|byte|decimal|double|float|hexBinary|int|integer|long|short|string)$/,
  /^http:\/\/www\.eclipse\.org\/elk\/ElkGraph$/,
  /^http:\/\/www\.eclipse\.org\/emf\/2002\/Ecore$/,
  /^http:\/\/www\.eclipse\.org\/emf\/2003\/XMLType$/,
  /^http:\/\/\/org\/eclipse\/emf\/ecore\/util\/ExtendedMetaData$/,
  // The bundler's runtime: the text of the error thrown when CommonJS code (elkjs) would
  // require a module that is not in the build.
  /^https:\/\/rolldown\.rs\/in-depth\/bundling-cjs#require-external-modules$/,
];

function filesUnder(folder: string): string[] {
  return fs.readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const full = path.join(folder, entry.name);
    return entry.isDirectory() ? filesUnder(full) : [full];
  });
}

test('the built front end names no outside URL it could load', () => {
  const textFiles = filesUnder(dist).filter((f) => /\.(html|js|css|svg|json|webmanifest)$/.test(f));
  expect(textFiles.length).toBeGreaterThan(2);
  const found = new Set<string>();
  for (const file of textFiles) {
    const text = fs.readFileSync(file, 'utf8');
    for (const match of text.matchAll(/https?:\/\/[^\s"'`)<>\\]+/g)) {
      if (!NEVER_FETCHED.some((allowed) => allowed.test(match[0]))) {
        found.add(`${path.relative(dist, file)}: ${match[0]}`);
      }
    }
    // Protocol-relative loads (//host/...) in markup or styles would go outside too.
    for (const match of text.matchAll(/(?:src|href)=["']\/\/[^"']+|url\(\s*["']?\/\/[^)]+/g)) {
      found.add(`${path.relative(dist, file)}: ${match[0]}`);
    }
  }
  expect([...found]).toEqual([]);
});

test('the fonts are bundled files of the build', () => {
  const fonts = filesUnder(path.join(dist, 'assets')).filter((f) => f.endsWith('.woff2'));
  const names = fonts.map((f) => path.basename(f));
  expect(names.some((n) => n.startsWith('vazirmatn-arabic'))).toBe(true);
  expect(names.some((n) => n.startsWith('noto-sans-vietnamese'))).toBe(true);
});

test('the API docs page renders from local files only', async ({ page, watch }) => {
  await page.goto('/api/docs');
  await expect(page.getByText('/api/projects', { exact: true }).first()).toBeVisible();
  expect(watch.foreignRequests).toEqual([]);
  expect(watch.consoleErrors).toEqual([]);
});
