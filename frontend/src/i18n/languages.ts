import ar from './locales/ar.json';
import en from './locales/en.json';
import fa from './locales/fa.json';
import vi from './locales/vi.json';
import ladAr from '../lad/locales/ar.json';
import ladEn from '../lad/locales/en.json';
import ladFa from '../lad/locales/fa.json';
import ladVi from '../lad/locales/vi.json';

/** The interface languages, in the order the language switch lists them. */
export const LANGUAGES = ['en', 'ar', 'fa', 'vi'] as const;
export type Language = (typeof LANGUAGES)[number];
export type Direction = 'ltr' | 'rtl';

export const DEFAULT_LANGUAGE: Language = 'en';

/** Where the user's choice is remembered. */
export const LANGUAGE_STORAGE_KEY = 'nasaq.lang';

export type Catalogue = typeof en & { lad: typeof ladEn };

/**
 * One catalogue per language; each one says its own name and writing direction. The diagram
 * editors' texts (`lad.*`) live beside them in `lad/locales/`.
 */
export const CATALOGUES: Record<Language, Catalogue> = {
  en: { ...en, lad: ladEn },
  ar: { ...ar, lad: ladAr },
  fa: { ...fa, lad: ladFa },
  vi: { ...vi, lad: ladVi },
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
