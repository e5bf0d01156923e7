import { useCallback } from 'react';
import { useTranslation } from 'react-i18next';
import type { Problem } from '../api/monitorClient';
import { translateParams } from '../i18n/phraseParams';

/**
 * A problem (socket error, API error, client failure) as text in the interface language: the
 * catalogue's `problems.<key>` with its params when it has one, else the server's English message.
 */
export function useProblemText(): (problem: Pick<Problem, 'key' | 'message' | 'params'>) => string {
  const { t, i18n } = useTranslation();
  return useCallback(
    (problem) => {
      const key = `problems.${problem.key}`;
      return i18n.exists(key) ? t(key, translateParams(t, (k) => i18n.exists(k), problem.params)) : problem.message;
    },
    [t, i18n],
  );
}
