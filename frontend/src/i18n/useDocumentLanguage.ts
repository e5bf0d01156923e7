import { useLayoutEffect } from 'react';
import { useTranslation } from 'react-i18next';
import { DEFAULT_LANGUAGE, directionOf, isLanguage, type Direction, type Language } from './languages';

/** The current interface language and its writing direction. */
export function useUiLanguage(): { language: Language; dir: Direction } {
  const { i18n } = useTranslation();
  const language = isLanguage(i18n.language) ? i18n.language : DEFAULT_LANGUAGE;
  return { language, dir: directionOf(language) };
}

/**
 * Keeps `<html lang dir>` and the document title in step with the interface
 * language, so the whole page mirrors for Arabic and Persian.
 */
export function useDocumentLanguage(): void {
  const { t } = useTranslation();
  const { language, dir } = useUiLanguage();
  useLayoutEffect(() => {
    const root = document.documentElement;
    root.lang = language;
    root.dir = dir;
    document.title = t('app.documentTitle');
  }, [language, dir, t]);
}
