/**
 * A lesson's Markdown text made safe to show: `marked` turns it into HTML, DOMPurify removes
 * anything active (scripts, event handlers, frames, forms), and a last pass makes the HTML fit
 * the pane: figures are read from the lesson's figure route (any other image source is dropped,
 * so nothing is ever loaded from the network), code blocks, inline code (addresses) and
 * figures read left to right inside Arabic and Persian text, links open in a new tab.
 *
 * ```` ```lad-view ```` / ```` ```fbd-view ```` fences hold STL that the pane draws with the
 * LAD/FBD view: they come out as their own segments between the HTML ones.
 */
import DOMPurify from 'dompurify';
import { Marked, type Token, type Tokens } from 'marked';

export type LessonSegment =
  | { kind: 'html'; html: string }
  | { kind: 'diagram'; mode: 'LAD' | 'FBD'; stl: string };

const markdown = new Marked({ gfm: true, breaks: false, async: false });

/** The fences drawn as diagrams. */
const DIAGRAM_FENCES: Record<string, 'LAD' | 'FBD'> = { 'lad-view': 'LAD', 'fbd-view': 'FBD' };

/** A figure named in the text: `figures/name.svg` (a folder-less, dot-free-prefix file name). */
const FIGURE = /^(?:\.\/)?figures\/([A-Za-z0-9_][A-Za-z0-9_.-]*\.svg)$/;

let purifier: ReturnType<typeof DOMPurify> | null = null;

function purify(): ReturnType<typeof DOMPurify> {
  purifier ??= DOMPurify(window);
  return purifier;
}

/**
 * The sanitized HTML of a Markdown fragment; `figure(name)` gives the URL of a lesson figure.
 * Exported for the tests; the pane uses {@link lessonSegments}.
 */
export function safeHtml(html: string, figure: (name: string) => string): string {
  const fragment = purify().sanitize(html, {
    RETURN_DOM_FRAGMENT: true,
    FORBID_TAGS: ['style', 'form', 'input', 'button', 'textarea', 'select', 'iframe', 'object', 'embed', 'video', 'audio', 'source', 'link', 'meta', 'base'],
    FORBID_ATTR: ['style', 'srcset'],
  });
  for (const image of Array.from(fragment.querySelectorAll('img'))) {
    const match = FIGURE.exec(image.getAttribute('src') ?? '');
    if (!match?.[1]) {
      // Not one of the lesson's figures: never fetched; its caption stays as text.
      image.replaceWith(image.ownerDocument.createTextNode(image.getAttribute('alt') ?? ''));
      continue;
    }
    image.setAttribute('src', figure(match[1]));
    image.setAttribute('dir', 'ltr');
    image.setAttribute('loading', 'lazy');
    image.classList.add('lesson-text__figure');
  }
  for (const code of Array.from(fragment.querySelectorAll('pre, code, kbd, samp'))) code.setAttribute('dir', 'ltr');
  for (const link of Array.from(fragment.querySelectorAll('a'))) {
    const href = link.getAttribute('href') ?? '';
    if (/^https?:\/\//i.test(href)) {
      link.setAttribute('target', '_blank');
      link.setAttribute('rel', 'noopener noreferrer');
    } else if (!href.startsWith('#')) {
      // A path into the lesson folder (or anything else) leads nowhere in the pane: plain text.
      link.replaceWith(...Array.from(link.childNodes));
    }
  }
  const holder = document.createElement('div');
  holder.appendChild(fragment);
  return holder.innerHTML;
}

/**
 * The lesson text as HTML segments and diagram segments, in order. The text's first `# title`
 * is left out: the pane shows the title in its header.
 */
export function lessonSegments(text: string, figure: (name: string) => string): LessonSegment[] {
  const tokens = markdown.lexer(text);
  const segments: LessonSegment[] = [];
  let pending: Token[] = [];
  const flush = () => {
    if (pending.length === 0) return;
    const html = markdown.parser(pending);
    pending = [];
    if (html.trim() !== '') segments.push({ kind: 'html', html: safeHtml(html, figure) });
  };
  let first = true;
  for (const token of tokens) {
    if (first && token.type === 'heading' && (token as Tokens.Heading).depth === 1) {
      first = false;
      continue;
    }
    if (token.type !== 'space') first = false;
    const mode = token.type === 'code' ? DIAGRAM_FENCES[((token as Tokens.Code).lang ?? '').trim()] : undefined;
    if (mode) {
      flush();
      segments.push({ kind: 'diagram', mode, stl: (token as Tokens.Code).text });
    } else pending.push(token);
  }
  flush();
  return segments;
}

/** The language to show a lesson in: the interface language if the lesson has it, else English, else its own. */
export function textLanguage(languages: readonly string[], texts: Partial<Record<string, string>>, ui: string): string {
  const has = (language: string) => languages.includes(language) && typeof texts[language] === 'string';
  if (has(ui)) return ui;
  if (has('en')) return 'en';
  return languages.find(has) ?? Object.keys(texts)[0] ?? 'en';
}

/** Right-to-left languages of the lessons. */
export function isRtl(language: string): boolean {
  return language === 'ar' || language === 'fa';
}
