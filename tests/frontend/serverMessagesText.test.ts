import { describe, expect, it } from 'vitest';
import { translateParams } from '../../frontend/src/i18n/phraseParams';
import { createI18n } from '../../frontend/src/i18n/setup';
import type { Language } from '../../frontend/src/i18n/languages';

/** Server problems as the backend sends them (tests/backend/test_phrases.py checks that side):
 * the English text of each phrase parameter, with its key and params beside it. */
const PROBLEMS = [
  {
    key: 'mon_not_now',
    params: {
      action: 'A single step',
      action_key: 'act_step',
      action_params: {},
      reason: 'the CPU is in STOP',
      reason_key: 'cpu_in_stop',
      reason_params: {},
    },
    message: 'A single step is not possible now: the CPU is in STOP',
  },
  {
    key: 'mon_bad_value',
    params: {
      target: 'MW10',
      reason: '99999 does not fit type INT: -32768 to 32767',
      reason_key: 'value_not_fit',
      reason_params: {
        value: '99999',
        type: 'INT',
        allowed: '-32768 to 32767',
        allowed_key: 'range',
        allowed_params: { low: '-32768', high: '32767' },
      },
    },
    message: 'MW10: 99999 does not fit type INT: -32768 to 32767',
  },
  {
    key: 'mon_unknown_target',
    params: {
      target: 'DB9.DBW0',
      reason: 'DB9 is not in the downloaded program (its data blocks: DB1)',
      reason_key: 'db_missing_has',
      reason_params: { db: 9, known: 'DB1' },
    },
    message: '',
  },
  {
    key: 'mon_no_code_here',
    params: {
      where: 'OB1.awl line 3',
      where_key: 'where_line',
      where_params: { file: 'OB1.awl', line: 3 },
      hint: ' (the next line with code is 5)',
      hint_key: 'hint_next_line',
      hint_params: { line: 5 },
    },
    message: '',
  },
  {
    key: 'invalid_request',
    params: {
      field: 'name',
      reason: 'String should have at most 64 characters',
      reason_key: 'text_too_long',
      reason_params: { max_length: '64' },
    },
    message: 'name: String should have at most 64 characters',
  },
] as const;

// What may stay in Latin script: code (addresses, types, files, CPU modes) and the field's name.
const CODE = /^(?:[A-Z0-9_#.]+|OB1\.awl|name)$/;
const ENGLISH_WORDS = /\b(?:the|is|not|of|to|has|line|step|type|does|fit|program|data|blocks?|possible|now|at|most|characters?)\b/i;

function rendered(language: Language, problem: (typeof PROBLEMS)[number]): string {
  const i18n = createI18n(language);
  const params = translateParams(i18n.t, (key) => i18n.exists(key), problem.params);
  return i18n.t(`problems.${problem.key}`, params);
}

describe('server messages in the interface language', () => {
  it.each(['ar', 'fa'] as const)('%s: no Latin-script word but code and addresses', (language) => {
    for (const problem of PROBLEMS) {
      const text = rendered(language, problem);
      const latin = (text.match(/[A-Za-z][A-Za-z0-9_#.]*/g) ?? []).filter((word) => !CODE.test(word));
      expect(latin, text).toEqual([]);
      expect(text).toMatch(/[\u0600-\u06FF]/);
    }
  });

  it('vi: Vietnamese words, no English sentence', () => {
    for (const problem of PROBLEMS) {
      const text = rendered('vi', problem);
      expect(text, text).not.toMatch(ENGLISH_WORDS);
      expect(text).toMatch(/[ăâđêôơưạảấầẩẫậắằẳẵặẹẻẽếềểễệỉịọỏốồổỗộớờởỡợụủứừửữựỳỵỷỹàáèéìíòóùúý]/i);
    }
  });

  it('fa: nested phrases are translated inside their parent', () => {
    expect(rendered('fa', PROBLEMS[1])).toBe('MW10: 99999 در نوع INT نمی‌گنجد: از -32768 تا 32767');
    expect(rendered('fa', PROBLEMS[0])).toBe('اجرای یک گام اکنون ممکن نیست: CPU در حالت STOP است');
  });

  it('en: the same text as the server sends', () => {
    expect(rendered('en', PROBLEMS[0])).toBe(PROBLEMS[0].message);
    expect(rendered('en', PROBLEMS[1])).toBe(PROBLEMS[1].message);
  });

  it('a key the catalogue lacks keeps the English text', () => {
    const i18n = createI18n('fa');
    const params = translateParams(i18n.t, (key) => i18n.exists(key), { reason: 'new', reason_key: 'unknown_key' });
    expect(params.reason).toBe('new');
  });
});
