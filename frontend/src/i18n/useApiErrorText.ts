import { useCallback } from 'react';
import { useTranslation } from 'react-i18next';
import type { ApiError } from '../api/client';
import { translateParams } from './phraseParams';

/**
 * Turns an API error into text for the interface language: the catalogue's
 * `problems.<key>` when it has one, else the server's own (English) message.
 */
export function useApiErrorText(): (error: ApiError) => string {
  const { t, i18n } = useTranslation();
  return useCallback(
    (error: ApiError) => {
      const key = `problems.${error.key}`;
      return i18n.exists(key) ? t(key, translateParams(t, (k) => i18n.exists(k), error.params)) : error.message;
    },
    [t, i18n],
  );
}
