import i18next, { type i18n as I18n } from 'i18next';
import { initReactI18next } from 'react-i18next';
import { readStored, writeStored } from '../ui/usePersistentState';
import {
  CATALOGUES,
  DEFAULT_LANGUAGE,
  LANGUAGES,
  LANGUAGE_STORAGE_KEY,
  detectInitialLanguage,
  type Language,
} from './languages';

function browserLanguages(): readonly string[] {
  if (typeof navigator === 'undefined') return [];
  if (navigator.languages && navigator.languages.length > 0) return navigator.languages;
  return navigator.language ? [navigator.language] : [];
}

/**
 * A ready-to-use i18next instance with all four catalogues bundled (no network
 * loading), started in the remembered or browser language.
 */
export function createI18n(language?: Language): I18n {
  const instance = i18next.createInstance();
  const lng = language ?? detectInitialLanguage(readStored(LANGUAGE_STORAGE_KEY), browserLanguages());
  void instance.use(initReactI18next).init({
    lng,
    fallbackLng: DEFAULT_LANGUAGE,
    supportedLngs: [...LANGUAGES],
    resources: Object.fromEntries(
      LANGUAGES.map((code) => [code, { translation: CATALOGUES[code] }]),
    ),
    initAsync: false,
    returnNull: false,
    interpolation: { escapeValue: false },
    react: { useSuspense: false },
  });
  return instance;
}

/** Switches the interface language and remembers the choice. */
export function chooseLanguage(instance: I18n, language: Language): Promise<unknown> {
  writeStored(LANGUAGE_STORAGE_KEY, language);
  return instance.changeLanguage(language);
}
