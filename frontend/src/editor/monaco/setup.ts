/**
 * Monaco as Nasaq uses it, loaded on demand by `load.ts`: the core editor API with the
 * contributions an IDE for STL and SCL needs, the STL, SCL and LAD/FBD text languages and the
 * light theme;
 * `environment.ts` sets up the editor's web worker. Everything is bundled by Vite: no CDN, no
 * loader, no request to any other host. The JSON/TypeScript/CSS/HTML language services and the
 * ~80 other languages of the full `monaco-editor` entry are left out on purpose.
 */
import './environment';
import './menu.css';
import * as monaco from 'monaco-editor/editor/editor.api';

// Editor features: modules of `monaco-editor`'s full entry (editor.main.js), minus those for
// language services, diff views, code lenses/actions, GPU rendering and touch keyboards.
// (codicon-modifiers.css comes with the suggest widget.)
import 'monaco-editor/editor/browser/coreCommands';
import 'monaco-editor/editor/browser/widget/codeEditor/codeEditorWidget';
import 'monaco-editor/features/codicon/register';
import 'monaco-editor/editor/common/standaloneStrings';
import 'monaco-editor/editor/contrib/bracketMatching/browser/bracketMatching';
import 'monaco-editor/editor/contrib/caretOperations/browser/caretOperations';
import 'monaco-editor/editor/contrib/caretOperations/browser/transpose';
import 'monaco-editor/editor/contrib/clipboard/browser/clipboard';
import 'monaco-editor/editor/contrib/comment/browser/comment';
import 'monaco-editor/editor/contrib/contextmenu/browser/contextmenu';
import 'monaco-editor/editor/contrib/cursorUndo/browser/cursorUndo';
import 'monaco-editor/features/find/register';
import 'monaco-editor/editor/contrib/folding/browser/folding';
import 'monaco-editor/editor/contrib/fontZoom/browser/fontZoom';
import 'monaco-editor/editor/contrib/format/browser/formatActions';
import 'monaco-editor/editor/contrib/gotoError/browser/gotoError';
import 'monaco-editor/editor/contrib/gotoError/browser/markerSelectionStatus';
import 'monaco-editor/editor/standalone/browser/quickAccess/standaloneGotoLineQuickAccess';
import 'monaco-editor/editor/standalone/browser/quickAccess/standaloneCommandsQuickAccess';
import 'monaco-editor/editor/standalone/browser/quickAccess/standaloneHelpQuickAccess';
import 'monaco-editor/editor/contrib/hover/browser/hoverContribution';
import 'monaco-editor/editor/contrib/indentation/browser/indentation';
import 'monaco-editor/editor/contrib/inPlaceReplace/browser/inPlaceReplace';
import 'monaco-editor/editor/contrib/lineSelection/browser/lineSelection';
import 'monaco-editor/editor/contrib/linesOperations/browser/linesOperations';
import 'monaco-editor/editor/contrib/multicursor/browser/multicursor';
import 'monaco-editor/editor/contrib/parameterHints/browser/parameterHints';
import 'monaco-editor/editor/contrib/readOnlyMessage/browser/contribution';
import 'monaco-editor/editor/contrib/smartSelect/browser/smartSelect';
import 'monaco-editor/editor/contrib/snippet/browser/snippetController2';
import 'monaco-editor/editor/contrib/suggest/browser/suggestController';
import 'monaco-editor/editor/contrib/toggleTabFocusMode/browser/toggleTabFocusMode';
import 'monaco-editor/editor/contrib/wordHighlighter/browser/wordHighlighter';
import 'monaco-editor/editor/contrib/wordOperations/browser/wordOperations';
import 'monaco-editor/editor/contrib/wordPartOperations/browser/wordPartOperations';

import { GRAPH_LANGUAGE_ID, graphConfiguration, graphFoldingRanges, graphLanguage } from '../languages/graph';
import { LAD_LANGUAGE_ID, ladConfiguration, ladFoldingRanges, ladLanguage } from '../languages/lad';
import { SCL_LANGUAGE_ID, sclConfiguration, sclFoldingRanges, sclLanguage } from '../languages/scl';
import { formatScl } from '../languages/sclFormat';
import { formatStl } from '../languages/stlFormat';
import { registerIntellisense } from '../intellisense/register';
import { STL_LANGUAGE_ID, stlConfiguration, stlFoldingRanges, stlLanguage, type LineRange } from '../languages/stl';
import { THEME_NAME } from './constants';
import { nasaqLightTheme } from './theme';

function register(
  id: string,
  extensions: string[],
  language: monaco.languages.IMonarchLanguage,
  configuration: monaco.languages.LanguageConfiguration,
  folding: (text: string) => LineRange[],
) {
  monaco.languages.register({ id, extensions });
  monaco.languages.setMonarchTokensProvider(id, language);
  monaco.languages.setLanguageConfiguration(id, configuration);
  monaco.languages.registerFoldingRangeProvider(id, {
    provideFoldingRanges: (model) => folding(model.getValue()),
  });
}

register(STL_LANGUAGE_ID, ['.awl', '.stl'], stlLanguage, stlConfiguration, stlFoldingRanges);
// "Format Document" (Shift+Alt+F, the context menu): STEP 7's column layout for STL.
monaco.languages.registerDocumentFormattingEditProvider(STL_LANGUAGE_ID, {
  provideDocumentFormattingEdits: (model) => {
    const text = model.getValue();
    const formatted = formatStl(text);
    return formatted === text ? [] : [{ range: model.getFullModelRange(), text: formatted }];
  },
});
register(SCL_LANGUAGE_ID, ['.scl', '.db', '.udt'], sclLanguage, sclConfiguration, sclFoldingRanges);
// "Format Document" for SCL: the indentation of blocks, sections and statements (sclFormat.ts).
monaco.languages.registerDocumentFormattingEditProvider(SCL_LANGUAGE_ID, {
  provideDocumentFormattingEdits: (model) => {
    const text = model.getValue();
    const formatted = formatScl(text);
    return formatted === text ? [] : [{ range: model.getFullModelRange(), text: formatted }];
  },
});
// LAD and FBD blocks as text, until the graphical editors draw them (the STL of networks
// kept as STL is embedded).
register(LAD_LANGUAGE_ID, ['.lad', '.fbd'], ladLanguage, ladConfiguration, ladFoldingRanges);
// S7-Graph FBs as text, until the chart editor draws them (conditions are LAD text).
register(GRAPH_LANGUAGE_ID, ['.graph'], graphLanguage, graphConfiguration, graphFoldingRanges);
// Completion and hover help for both languages, from the project outline (intellisense/).
registerIntellisense(monaco);
monaco.editor.defineTheme(THEME_NAME, nasaqLightTheme);

export { monaco };
