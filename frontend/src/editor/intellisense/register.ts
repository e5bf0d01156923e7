/**
 * Completion and hover for STL and SCL in Monaco, registered once (from `monaco/setup.ts`) for
 * every model of the two languages. A model says which project file it shows through
 * `modelRegistry.ts`; the project's outline comes from `outlineStore.ts`; the interface language
 * is the document's (`<html lang>`, set by the app), so the help follows the language switch.
 */
import type * as Monaco from 'monaco-editor/editor/editor.api';
import { complete, type SuggestionKind } from './completion';
import { hoverAt, type HoverPart } from './hover';
import { sourceOf } from './modelRegistry';
import { outlines, type OutlineStore } from './outlineStore';
import './intellisense.css';

type MonacoApi = typeof Monaco;
type Model = Monaco.editor.ITextModel;

const RTL_LANGUAGES = new Set(['ar', 'fa']);

export function uiLanguage(): string {
  return typeof document === 'undefined' ? 'en' : document.documentElement.lang || 'en';
}

function escapeHtml(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

function escapeMarkdown(text: string): string {
  return text.replace(/[\\`*_{}[\]()#+\-.!<>|~]/g, (char) => `\\${char}`);
}

/** A hover part as Monaco markdown: code in a code block, RTL text in a right-aligned div. */
export function markdownOf(part: HoverPart, language: string, codeLanguage: string): Monaco.IMarkdownString {
  if (part.kind === 'code') return { value: `\`\`\`${codeLanguage}\n${part.text}\n\`\`\`` };
  if (RTL_LANGUAGES.has(language)) return { value: `<div align="right">${escapeHtml(part.text)}</div>`, supportHtml: true };
  return { value: escapeMarkdown(part.text) };
}

function kindOf(monaco: MonacoApi, kind: SuggestionKind): Monaco.languages.CompletionItemKind {
  const kinds = monaco.languages.CompletionItemKind;
  switch (kind) {
    case 'instruction':
      return kinds.Operator;
    case 'keyword':
      return kinds.Keyword;
    case 'snippet':
      return kinds.Snippet;
    case 'function':
      return kinds.Function;
    case 'symbol':
      return kinds.Constant;
    case 'member':
      return kinds.Field;
    case 'block':
      return kinds.Module;
    default:
      return kinds.TypeParameter;
  }
}

async function context(model: Model, store: OutlineStore) {
  const source = sourceOf(model);
  const outline = source ? await store.ready(source.projectId) : null;
  const language = model.getLanguageId() === 'scl' ? ('scl' as const) : ('stl' as const);
  return { outline, file: source?.path ?? null, language, uiLanguage: uiLanguage() };
}

/** Registers the providers for `stl` and `scl`; the disposable removes them again. */
export function registerIntellisense(monaco: MonacoApi, store: OutlineStore = outlines): Monaco.IDisposable {
  const disposables: Monaco.IDisposable[] = [];
  for (const languageId of ['stl', 'scl']) {
    disposables.push(
      monaco.languages.registerCompletionItemProvider(languageId, {
        triggerCharacters: ['.', '#', '"'],
        provideCompletionItems: async (model, position) => {
          const found = complete({ text: model.getValue(), line: position.lineNumber, column: position.column, ...(await context(model, store)) });
          if (!found) return { suggestions: [] };
          const range = { startLineNumber: position.lineNumber, endLineNumber: position.lineNumber, startColumn: found.from, endColumn: found.to };
          return {
            suggestions: found.suggestions.map((item) => ({
              label: item.label,
              kind: kindOf(monaco, item.kind),
              insertText: item.insertText,
              insertTextRules: item.snippet ? monaco.languages.CompletionItemInsertTextRule.InsertAsSnippet : undefined,
              detail: item.detail,
              documentation: item.documentation,
              filterText: item.filterText,
              sortText: item.sortText,
              range,
            })),
          };
        },
      }),
      monaco.languages.registerHoverProvider(languageId, {
        provideHover: async (model, position) => {
          const request = await context(model, store);
          const found = hoverAt({ text: model.getValue(), line: position.lineNumber, column: position.column, ...request });
          if (!found) return null;
          return {
            range: { startLineNumber: position.lineNumber, endLineNumber: position.lineNumber, startColumn: found.from, endColumn: found.to },
            contents: found.parts.map((part) => markdownOf(part, request.uiLanguage, languageId)),
          };
        },
      }),
    );
  }
  return { dispose: () => disposables.forEach((disposable) => disposable.dispose()) };
}
