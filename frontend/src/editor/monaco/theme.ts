import type { editor } from 'monaco-editor/editor/editor.api';

/**
 * A light theme in the colours of the app (styles/tokens.css). Every token colour has a
 * contrast of at least 4.5:1 on the white editor and on the highlighted line, and the token
 * kinds a learner must tell apart (instructions, addresses, comments, constants) differ in hue.
 */
export const nasaqLightTheme: editor.IStandaloneThemeData = {
  base: 'vs',
  inherit: true,
  rules: [
    { token: '', foreground: '1b2733' },
    { token: 'keyword', foreground: '6f2da8', fontStyle: 'bold' },
    { token: 'keyword.instruction', foreground: '0550ae', fontStyle: '' },
    { token: 'keyword.operator', foreground: '0550ae', fontStyle: 'bold' },
    { token: 'type', foreground: '00707a' },
    { token: 'predefined', foreground: '005960', fontStyle: 'bold' },
    { token: 'address', foreground: 'a0410d' },
    { token: 'variable.local', foreground: '7d5200' },
    { token: 'variable.symbol', foreground: '1e7239' },
    { token: 'variable.predefined', foreground: '7d5200', fontStyle: 'bold' },
    { token: 'variable.symbol.invalid', foreground: 'b0241b' },
    { token: 'identifier', foreground: '1b2733' },
    { token: 'number', foreground: 'a0106b' },
    { token: 'constant', foreground: 'a0106b', fontStyle: 'bold' },
    { token: 'string', foreground: 'a31515' },
    { token: 'string.invalid', foreground: 'b0241b', fontStyle: 'underline' },
    { token: 'comment', foreground: '5b6b77', fontStyle: 'italic' },
    { token: 'comment.title', foreground: '44525e', fontStyle: 'italic' },
    { token: 'label', foreground: '87358c', fontStyle: 'bold' },
    { token: 'annotation', foreground: '5b6b77' },
    { token: 'operator', foreground: '1b2733' },
    { token: 'delimiter', foreground: '4b5966' },
  ],
  colors: {
    'editor.background': '#ffffff',
    'editor.foreground': '#1b2733',
    'editor.lineHighlightBackground': '#f0f5f8',
    'editor.lineHighlightBorder': '#f0f5f8',
    'editor.selectionBackground': '#bfe1e4',
    'editor.inactiveSelectionBackground': '#d3eaec',
    'editorCursor.foreground': '#00707a',
    'editorLineNumber.foreground': '#5b6b77',
    'editorLineNumber.activeForeground': '#1b2733',
    'editorIndentGuide.background1': '#e1e7ec',
    'editorError.foreground': '#b0241b',
    'editorWarning.foreground': '#8a5300',
    'editorInfo.foreground': '#1d5fa8',
    'focusBorder': '#1565c0',
    // The context menu (see menu.css for the menu outside the editor's element).
    'menu.background': '#ffffff',
    'menu.foreground': '#1b2733',
    'menu.selectionBackground': '#d3eaec',
    'menu.selectionForeground': '#1b2733',
    'menu.separatorBackground': '#c3cdd5',
    'menu.border': '#9aa8b4',
  },
};
