import ar from './locales/ar.json';
import en from './locales/en.json';
import fa from './locales/fa.json';
import vi from './locales/vi.json';
import ladAr from '../lad/locales/ar.json';
import ladEn from '../lad/locales/en.json';
import ladFa from '../lad/locales/fa.json';
import ladVi from '../lad/locales/vi.json';
import cpuEn from '../cpu/locales/en.json';
import cpuAr from '../cpu/locales/ar.json';
import cpuFa from '../cpu/locales/fa.json';
import cpuVi from '../cpu/locales/vi.json';
import watchTablesEn from '../watchtables/locales/en.json';
import watchTablesAr from '../watchtables/locales/ar.json';
import watchTablesFa from '../watchtables/locales/fa.json';
import watchTablesVi from '../watchtables/locales/vi.json';
import ioEn from '../io/locales/en.json';
import ioAr from '../io/locales/ar.json';
import ioFa from '../io/locales/fa.json';
import ioVi from '../io/locales/vi.json';
import xrefEn from '../xref/locales/en.json';
import xrefAr from '../xref/locales/ar.json';
import xrefFa from '../xref/locales/fa.json';
import xrefVi from '../xref/locales/vi.json';
import cpuPropsEn from '../cpuprops/locales/en.json';
import cpuPropsAr from '../cpuprops/locales/ar.json';
import cpuPropsFa from '../cpuprops/locales/fa.json';
import cpuPropsVi from '../cpuprops/locales/vi.json';
import panelsEn from '../panels/locales/en.json';
import panelsAr from '../panels/locales/ar.json';
import panelsFa from '../panels/locales/fa.json';
import panelsVi from '../panels/locales/vi.json';
import phrasesEn from './phrases/en.json';
import phrasesAr from './phrases/ar.json';
import phrasesFa from './phrases/fa.json';
import phrasesVi from './phrases/vi.json';
import examplesEn from '../examples/locales/en.json';
import examplesAr from '../examples/locales/ar.json';
import examplesFa from '../examples/locales/fa.json';
import examplesVi from '../examples/locales/vi.json';
import lessonPaneEn from '../lessons/locales/en.json';
import lessonPaneAr from '../lessons/locales/ar.json';
import lessonPaneFa from '../lessons/locales/fa.json';
import lessonPaneVi from '../lessons/locales/vi.json';
import plantsEn from '../plants/locales/en.json';
import plantsAr from '../plants/locales/ar.json';
import plantsFa from '../plants/locales/fa.json';
import plantsVi from '../plants/locales/vi.json';

import graphChecksEn from '../graph/locales/en.json';
import graphChecksAr from '../graph/locales/ar.json';
import graphChecksFa from '../graph/locales/fa.json';
import graphChecksVi from '../graph/locales/vi.json';
import graphSyntaxEn from '../graph/locales-syntax/en.json';
import graphSyntaxAr from '../graph/locales-syntax/ar.json';
import graphSyntaxFa from '../graph/locales-syntax/fa.json';
import graphSyntaxVi from '../graph/locales-syntax/vi.json';
import graphRunEn from '../graph/locales-run/en.json';
import graphRunAr from '../graph/locales-run/ar.json';
import graphRunFa from '../graph/locales-run/fa.json';
import graphRunVi from '../graph/locales-run/vi.json';
import graphChartEn from '../graph/locales-chart/en.json';
import graphChartAr from '../graph/locales-chart/ar.json';
import graphChartFa from '../graph/locales-chart/fa.json';
import graphChartVi from '../graph/locales-chart/vi.json';
import graphStepEn from '../graph/locales-step/en.json';
import graphStepAr from '../graph/locales-step/ar.json';
import graphStepFa from '../graph/locales-step/fa.json';
import graphStepVi from '../graph/locales-step/vi.json';
import graphControlEn from '../graph/locales-control/en.json';
import graphControlAr from '../graph/locales-control/ar.json';
import graphControlFa from '../graph/locales-control/fa.json';
import graphControlVi from '../graph/locales-control/vi.json';
import graphDocEn from '../graph/locales-doc/en.json';
import graphDocAr from '../graph/locales-doc/ar.json';
import graphDocFa from '../graph/locales-doc/fa.json';
import graphDocVi from '../graph/locales-doc/vi.json';

import problemsLimitsEn from '../problems/locales-limits/en.json';
import problemsLimitsAr from '../problems/locales-limits/ar.json';
import problemsLimitsFa from '../problems/locales-limits/fa.json';
import problemsLimitsVi from '../problems/locales-limits/vi.json';
import problemsProfileEn from '../problems/locales-profile/en.json';
import problemsProfileAr from '../problems/locales-profile/ar.json';
import problemsProfileFa from '../problems/locales-profile/fa.json';
import problemsProfileVi from '../problems/locales-profile/vi.json';
import problemsSyscommEn from '../problems/locales-syscomm/en.json';
import problemsSyscommAr from '../problems/locales-syscomm/ar.json';
import problemsSyscommFa from '../problems/locales-syscomm/fa.json';
import problemsSyscommVi from '../problems/locales-syscomm/vi.json';
import problemsTiafilesEn from '../problems/locales-tiafiles/en.json';
import problemsTiafilesAr from '../problems/locales-tiafiles/ar.json';
import problemsTiafilesFa from '../problems/locales-tiafiles/fa.json';
import problemsTiafilesVi from '../problems/locales-tiafiles/vi.json';
import problemsFormsEn from '../problems/locales-forms/en.json';
import problemsFormsAr from '../problems/locales-forms/ar.json';
import problemsFormsFa from '../problems/locales-forms/fa.json';
import problemsFormsVi from '../problems/locales-forms/vi.json';
import problemsFunctionsEn from '../problems/locales-functions/en.json';
import problemsFunctionsAr from '../problems/locales-functions/ar.json';
import problemsFunctionsFa from '../problems/locales-functions/fa.json';
import problemsFunctionsVi from '../problems/locales-functions/vi.json';
import problemsDefectsEn from '../problems/locales-defects/en.json';
import problemsDefectsAr from '../problems/locales-defects/ar.json';
import problemsDefectsFa from '../problems/locales-defects/fa.json';
import problemsDefectsVi from '../problems/locales-defects/vi.json';
import problemsStlexportEn from '../problems/locales-stlexport/en.json';
import problemsStlexportAr from '../problems/locales-stlexport/ar.json';
import problemsStlexportFa from '../problems/locales-stlexport/fa.json';
import problemsStlexportVi from '../problems/locales-stlexport/vi.json';
import problemsVariantEn from '../problems/locales-variant/en.json';
import problemsVariantAr from '../problems/locales-variant/ar.json';
import problemsVariantFa from '../problems/locales-variant/fa.json';
import problemsVariantVi from '../problems/locales-variant/vi.json';

/** The interface languages, in the order the language switch lists them. */
export const LANGUAGES = ['en', 'ar', 'fa', 'vi'] as const;
export type Language = (typeof LANGUAGES)[number];
export type Direction = 'ltr' | 'rtl';

export const DEFAULT_LANGUAGE: Language = 'en';

/** Where the user's choice is remembered. */
export const LANGUAGE_STORAGE_KEY = 'nasaq.lang';

/**
 * A feature's texts that live beside its code (`<feature>/locales/<lang>.json`): each file holds
 * its own top-level namespace and may add `problems.<key>` texts for the diagnostic codes it owns.
 */
const FEATURES = {
  en: [cpuEn, watchTablesEn, ioEn, xrefEn, cpuPropsEn, panelsEn, phrasesEn, examplesEn, lessonPaneEn, plantsEn, graphChecksEn, graphSyntaxEn, graphRunEn, graphChartEn, graphStepEn, graphControlEn, graphDocEn, problemsLimitsEn, problemsProfileEn, problemsTiafilesEn, problemsFormsEn, problemsFunctionsEn, problemsDefectsEn, problemsStlexportEn, problemsVariantEn, problemsSyscommEn],
  ar: [cpuAr, watchTablesAr, ioAr, xrefAr, cpuPropsAr, panelsAr, phrasesAr, examplesAr, lessonPaneAr, plantsAr, graphChecksAr, graphSyntaxAr, graphRunAr, graphChartAr, graphStepAr, graphControlAr, graphDocAr, problemsLimitsAr, problemsProfileAr, problemsTiafilesAr, problemsFormsAr, problemsFunctionsAr, problemsDefectsAr, problemsStlexportAr, problemsVariantAr, problemsSyscommAr],
  fa: [cpuFa, watchTablesFa, ioFa, xrefFa, cpuPropsFa, panelsFa, phrasesFa, examplesFa, lessonPaneFa, plantsFa, graphChecksFa, graphSyntaxFa, graphRunFa, graphChartFa, graphStepFa, graphControlFa, graphDocFa, problemsLimitsFa, problemsProfileFa, problemsTiafilesFa, problemsFormsFa, problemsFunctionsFa, problemsDefectsFa, problemsStlexportFa, problemsVariantFa, problemsSyscommFa],
  vi: [cpuVi, watchTablesVi, ioVi, xrefVi, cpuPropsVi, panelsVi, phrasesVi, examplesVi, lessonPaneVi, plantsVi, graphChecksVi, graphSyntaxVi, graphRunVi, graphChartVi, graphStepVi, graphControlVi, graphDocVi, problemsLimitsVi, problemsProfileVi, problemsTiafilesVi, problemsFormsVi, problemsFunctionsVi, problemsDefectsVi, problemsStlexportVi, problemsVariantVi, problemsSyscommVi],
} as const;

export type Catalogue = typeof en & { lad: typeof ladEn } & typeof cpuEn &
  typeof watchTablesEn &
  typeof ioEn &
  typeof xrefEn &
  typeof cpuPropsEn &
  typeof panelsEn &
  typeof phrasesEn &
  typeof examplesEn &
  typeof lessonPaneEn &
  typeof plantsEn;

type Tree = { [key: string]: unknown };

/** `base` with `extra` merged in; a key both define as text is a mistake, so it throws. */
function mergeTree(base: Tree, extra: Tree, path = ''): Tree {
  const out: Tree = { ...base };
  for (const [key, value] of Object.entries(extra)) {
    const where = path ? `${path}.${key}` : key;
    const existing = out[key];
    if (existing === undefined) out[key] = value;
    else if (typeof existing === 'object' && existing !== null && typeof value === 'object' && value !== null)
      out[key] = mergeTree(existing as Tree, value as Tree, where);
    else throw new Error(`the text ${where} is defined twice`);
  }
  return out;
}

function catalogue(main: typeof en, lad: typeof ladEn, features: readonly Tree[]): Catalogue {
  return features.reduce((tree, feature) => mergeTree(tree, feature), { ...main, lad } as Tree) as Catalogue;
}

/**
 * One catalogue per language; each one says its own name and writing direction. The diagram
 * editors' texts (`lad.*`) live beside them in `lad/locales/`, other features' in theirs.
 */
export const CATALOGUES: Record<Language, Catalogue> = {
  en: catalogue(en, ladEn, FEATURES.en),
  ar: catalogue(ar, ladAr, FEATURES.ar),
  fa: catalogue(fa, ladFa, FEATURES.fa),
  vi: catalogue(vi, ladVi, FEATURES.vi),
};

export function isLanguage(value: unknown): value is Language {
  return typeof value === 'string' && (LANGUAGES as readonly string[]).includes(value);
}

export function directionOf(language: Language): Direction {
  return CATALOGUES[language].language.dir === 'rtl' ? 'rtl' : 'ltr';
}

/** The language's name written in that language (for the switch). */
export function nativeNameOf(language: Language): string {
  return CATALOGUES[language].language.nativeName;
}

/** Maps a BCP 47 tag such as `fa-IR` or `vi` to a supported language, if any. */
export function matchLanguage(tag: string | null | undefined): Language | null {
  if (!tag) return null;
  const primary = tag.trim().toLowerCase().split(/[-_]/)[0];
  return isLanguage(primary) ? primary : null;
}

/**
 * The language to start with: the remembered choice, else the first supported
 * browser language, else English.
 */
export function detectInitialLanguage(stored: string | null, browserLanguages: readonly string[]): Language {
  const remembered = matchLanguage(stored);
  if (remembered) return remembered;
  for (const tag of browserLanguages) {
    const match = matchLanguage(tag);
    if (match) return match;
  }
  return DEFAULT_LANGUAGE;
}
