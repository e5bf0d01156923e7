import { useId } from 'react';
import { useTranslation } from 'react-i18next';
import { CheckIcon, ErrorIcon } from '../ui/icons';
import type { QuizAnswer, QuizQuestion, QuizVerdict } from './api';
import { isRtl } from './markdown';
import { pick } from './progress';

/** What the learner has typed or chosen so far, by question id; predictions are committed apart. */
export interface QuizState {
  answers: Record<string, QuizAnswer>;
  /** Predict questions whose values the learner has committed (they cannot change them any more). */
  committed: Record<string, boolean>;
}

export const EMPTY_QUIZ: QuizState = { answers: {}, committed: {} };

/** A typed value as the server compares it: a number when it reads as one, else the text. */
export function typedValue(text: string): string | number {
  const trimmed = text.trim();
  return trimmed !== '' && /^[-+]?\d+(\.\d+)?$/.test(trimmed) ? Number(trimmed) : trimmed;
}

/**
 * The answers sent with "Check": every answered question; a prediction only once committed
 * (predict, then run: the truth comes from running the program, after the learner has said
 * what they expect).
 */
export function answersToSend(questions: readonly QuizQuestion[], state: QuizState): Record<string, QuizAnswer> {
  const out: Record<string, QuizAnswer> = {};
  for (const question of questions) {
    const answer = state.answers[question.id];
    if (answer === undefined) continue;
    if (question.kind === 'predict' && !state.committed[question.id]) continue;
    if (question.kind === 'number' && typeof answer === 'string') {
      const value = Number(answer.replace(',', '.'));
      if (answer.trim() === '' || Number.isNaN(value)) continue;
      out[question.id] = value;
    } else out[question.id] = answer;
  }
  return out;
}

interface QuizProps {
  questions: readonly QuizQuestion[];
  language: string;
  state: QuizState;
  onChange: (state: QuizState) => void;
  verdicts: readonly QuizVerdict[] | null;
}

function Verdict({ verdict, language }: { verdict: QuizVerdict; language: string }) {
  const { t } = useTranslation();
  return (
    <div className={verdict.correct ? 'quiz-verdict quiz-verdict--correct' : 'quiz-verdict quiz-verdict--wrong'} data-testid="quiz-verdict" data-correct={verdict.correct}>
      <p>
        {verdict.correct ? <CheckIcon className="quiz-verdict__icon" /> : <ErrorIcon className="quiz-verdict__icon" />}
        {verdict.correct ? t('lessonPane.quiz.correct') : t('lessonPane.quiz.wrong')}
        {verdict.expected_shown ? (
          <>
            {' '}
            {t('lessonPane.quiz.truth')}{' '}
            <code dir="ltr" data-testid="quiz-truth">
              {verdict.expected_shown}
            </code>
          </>
        ) : null}
      </p>
      {verdict.explain ? (
        <p className="quiz-verdict__explain" dir={isRtl(language) ? 'rtl' : 'ltr'} lang={language}>
          {pick(verdict.explain, language)}
        </p>
      ) : null}
    </div>
  );
}

function Question({ question, language, state, onChange, verdict }: { question: QuizQuestion; language: string; state: QuizState; onChange: (state: QuizState) => void; verdict: QuizVerdict | null }) {
  const { t } = useTranslation();
  const promptId = useId();
  const answer = state.answers[question.id];
  const committed = !!state.committed[question.id];
  const set = (value: QuizAnswer) => onChange({ ...state, answers: { ...state.answers, [question.id]: value } });
  const textDir = isRtl(language) ? 'rtl' : 'ltr';

  let body = null;
  if (question.kind === 'choice' || question.kind === 'multi') {
    const chosen = question.kind === 'multi' ? (Array.isArray(answer) ? answer : []) : [];
    body = (
      <div role={question.kind === 'choice' ? 'radiogroup' : 'group'} aria-labelledby={promptId} className="quiz-options">
        {(question.options ?? []).map((option) => (
          <label key={option.id} className="quiz-option" dir={textDir} lang={language}>
            <input
              type={question.kind === 'choice' ? 'radio' : 'checkbox'}
              name={`${promptId}-${question.id}`}
              value={option.id}
              data-testid={`quiz-${question.id}-${option.id}`}
              checked={question.kind === 'choice' ? answer === option.id : chosen.includes(option.id)}
              onChange={(event) => {
                if (question.kind === 'choice') set(option.id);
                else set(event.target.checked ? [...chosen, option.id] : chosen.filter((id) => id !== option.id));
              }}
            />
            <span>{pick(option.text, language)}</span>
          </label>
        ))}
      </div>
    );
  } else if (question.kind === 'number' || question.kind === 'text') {
    body = (
      <input
        className="quiz-input"
        dir="ltr"
        inputMode={question.kind === 'number' ? 'decimal' : 'text'}
        aria-labelledby={promptId}
        data-testid={`quiz-${question.id}-input`}
        value={typeof answer === 'string' || typeof answer === 'number' ? String(answer) : ''}
        onChange={(event) => set(event.target.value)}
      />
    );
  } else if (question.kind === 'predict') {
    const values = answer && typeof answer === 'object' && !Array.isArray(answer) ? answer : {};
    const filled = (question.ask ?? []).every((address) => String(values[address] ?? '').trim() !== '');
    body = (
      <div className="quiz-predict">
        {question.program ? (
          <pre className="quiz-predict__program" dir="ltr" data-testid={`quiz-${question.id}-program`}>
            <code>{question.program}</code>
          </pre>
        ) : null}
        {question.set && Object.keys(question.set).length > 0 ? (
          <p className="quiz-predict__given">
            {t('lessonPane.quiz.given', { count: question.scans ?? 1 })}{' '}
            <code dir="ltr">
              {Object.entries(question.set)
                .map(([address, value]) => `${address} = ${typeof value === 'boolean' ? (value ? 1 : 0) : value}`)
                .join(', ')}
            </code>
          </p>
        ) : null}
        <div className="quiz-predict__fields" dir="ltr">
          {(question.ask ?? []).map((address) => (
            <label key={address} className="quiz-predict__field">
              <code>{address}</code>
              <input
                className="quiz-input"
                dir="ltr"
                disabled={committed}
                data-testid={`quiz-${question.id}-${address}`}
                value={String(values[address] ?? '')}
                onChange={(event) => set({ ...values, [address]: event.target.value })}
              />
            </label>
          ))}
        </div>
        <button
          type="button"
          className="button button--small"
          disabled={committed || !filled}
          data-testid={`quiz-${question.id}-commit`}
          onClick={() => {
            const typed: Record<string, string | number> = {};
            for (const [address, value] of Object.entries(values)) typed[address] = typedValue(String(value));
            onChange({ answers: { ...state.answers, [question.id]: typed }, committed: { ...state.committed, [question.id]: true } });
          }}
        >
          {committed ? t('lessonPane.quiz.committed') : t('lessonPane.quiz.commit')}
        </button>
        {committed && !verdict ? <p className="quiz-predict__next">{t('lessonPane.quiz.runNext')}</p> : null}
      </div>
    );
  }

  return (
    <li className="quiz-question" data-testid={`quiz-${question.id}`}>
      <p id={promptId} className="quiz-question__prompt" dir={textDir} lang={language}>
        {pick(question.prompt, language)}
      </p>
      {body}
      {verdict ? <Verdict verdict={verdict} language={language} /> : null}
    </li>
  );
}

/** The lesson's quiz: choices, numbers, texts and "predict, then run"; the server checks the answers. */
export function Quiz({ questions, language, state, onChange, verdicts }: QuizProps) {
  const { t } = useTranslation();
  if (questions.length === 0) return null;
  return (
    <section className="lesson-quiz" aria-label={t('lessonPane.quiz.title')} data-testid="lesson-quiz">
      <h4 className="lesson-section-title">{t('lessonPane.quiz.title')}</h4>
      <ol className="quiz-questions">
        {questions.map((question) => (
          <Question
            key={question.id}
            question={question}
            language={language}
            state={state}
            onChange={onChange}
            verdict={verdicts?.find((verdict) => verdict.id === question.id) ?? null}
          />
        ))}
      </ol>
    </section>
  );
}
