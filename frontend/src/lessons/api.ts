/**
 * The lessons API (`/api/lessons`, issue 17 brief section 5) as the lesson pane sees it. Quiz
 * answers and the reference solution never come with a lesson: the server checks the answers,
 * and the solution is fetched only once the learner has passed or given up.
 */
import { request } from '../api/client';
import type { PlantConfig } from '../plants/types';

/** Texts in the lesson's languages (`{fa: "...", en: "..."}`). */
export type Texts = Partial<Record<string, string>>;

export type ProgressStatus = 'not_started' | 'tried' | 'passed';

/** The learner's progress in one lesson, kept on the server for the lesson's project. */
export interface Progress {
  status: ProgressStatus;
  attempts: number;
  time_s: number;
  hints_revealed: number;
  gave_up: boolean;
  passed_at: string | null;
}

export type WorksIn = 'LAD' | 'FBD' | 'STL' | 'SCL' | 'none';
export type LessonForm = 'program' | 'find-the-bug' | 'find-the-fault' | 'quiz' | 'predict' | 'conversion';

/** A lesson as the course outline lists it. */
export interface LessonSummary {
  id: string;
  order: number;
  title: Texts;
  summary: Texts;
  languages: string[];
  works_in: WorksIn;
  form: LessonForm;
  plant: string | null;
  prerequisites: string[];
  progress: Progress | null;
}

export interface CourseUnit {
  id: string;
  order: number;
  language: string;
  title: Texts;
  summary: Texts;
  lessons: LessonSummary[];
}

/** A lesson folder the server could not read: listed, never breaking the list. */
export interface CourseProblem {
  file: string;
  line: number | null;
  code: string;
  message: string;
  /** The catalogue's message key and parameters (`problems.<key>` in the locale files). */
  key?: string;
  params?: Record<string, unknown>;
}

export interface Course {
  units: CourseUnit[];
  problems: CourseProblem[];
}

export type QuestionKind = 'choice' | 'multi' | 'number' | 'text' | 'predict';

/** A quiz question as served: without its answer. */
export interface QuizQuestion {
  id: string;
  kind: QuestionKind;
  prompt: Texts;
  options?: Array<{ id: string; text: Texts }>;
  /** predict: the addresses the learner predicts, and the inputs set before the scans. */
  ask?: string[];
  set?: Record<string, number | boolean>;
  scans?: number;
  /** A predict question's program, shown for the learner to read. */
  program?: string | null;
}

export interface LessonCheckInfo {
  kind: 'scenario' | 'convert' | 'quiz';
  name: string;
}

export interface Lesson {
  id: string;
  unit: string;
  order: number;
  title: Texts;
  summary: Texts;
  languages: string[];
  works_in: WorksIn;
  open: string | null;
  form: LessonForm;
  time_limit_min: number | null;
  text: Texts;
  figures: string[];
  hints_total: number;
  /** The hints revealed so far in the lesson's project. */
  hints: Texts[];
  quiz: QuizQuestion[];
  plant: PlantConfig | null;
  checks: LessonCheckInfo[];
  prerequisites: string[];
  progress: Progress | null;
}

export interface LessonOpened {
  project_id: number;
  project_name: string;
  open: string | null;
  progress: Progress | null;
}

/** Where in the learner's program a failing expectation points: the instruction that wrote it last. */
export interface Where {
  file: string;
  line: number | null;
  network: number | null;
  element: string | null;
}

export interface CheckFailure {
  address: string;
  expected: unknown;
  actual: unknown;
  at_ms: number | null;
  where: Where | null;
}

export interface CheckStep {
  step: number;
  note: string | null;
  passed: boolean;
  failures: CheckFailure[];
}

export interface CheckDiagnostic {
  code: string;
  severity: 'error' | 'warning' | 'info';
  message: string;
  file: string | null;
  line: number | null;
  column: number | null;
  /** The catalogue's message key and parameters, to show the message in the interface language. */
  key?: string;
  params?: Record<string, unknown>;
  /** In a LAD/FBD file: the network and element the diagnostic is on. */
  network?: number | null;
  element?: string | null;
}

export interface CheckOutcome {
  kind: 'scenario' | 'convert' | 'quiz';
  name: string;
  passed: boolean;
  error: string | null;
  diagnostics: CheckDiagnostic[];
  /** Why the CPU stopped (STOP or a runaway program); key/params when the server translates it. */
  stop: { code: string; reason: string; key?: string; params?: Record<string, unknown> } | null;
  steps: CheckStep[];
}

export interface QuizVerdict {
  id: string;
  correct: boolean;
  expected_shown: string | null;
  explain: Texts | null;
}

export type CheckStatus = 'passed' | 'failed' | 'compile_error' | 'error';

export interface CheckResult {
  status: CheckStatus;
  checks: CheckOutcome[];
  quiz: QuizVerdict[];
  progress: Progress | null;
}

export type QuizAnswer = string | number | string[] | Record<string, string | number>;

export interface HintsRevealed {
  index: number;
  total: number;
  hints: Texts[];
}

export interface Solution {
  files: Array<{ name: string; text: string }>;
}

const base = (id: string) => `/api/lessons/${encodeURIComponent(id)}`;

export function getCourse(lang: string, signal?: AbortSignal): Promise<Course> {
  return request<Course>(`/api/lessons?lang=${encodeURIComponent(lang)}`, { signal: signal ?? null });
}

export function getLesson(id: string, signal?: AbortSignal): Promise<Lesson> {
  return request<Lesson>(base(id), { signal: signal ?? null });
}

/** Where a figure of the lesson text is served (`figures/name.svg` in the lesson folder). */
export function figureUrl(id: string, name: string): string {
  return `${base(id)}/figures/${encodeURIComponent(name)}`;
}

/** The learner's project of the lesson (made from start/ the first time; `reset`: back to start/). */
export function openLesson(id: string, reset = false): Promise<LessonOpened> {
  return request<LessonOpened>(`${base(id)}/open`, { method: 'POST', body: JSON.stringify({ reset }) });
}

/** Runs the lesson's checks; `lang` (the interface language) is the language of the steps' notes. */
export function checkLesson(
  id: string,
  projectId: number,
  answers: Record<string, QuizAnswer>,
  lang: string,
): Promise<CheckResult> {
  return request<CheckResult>(`${base(id)}/check`, {
    method: 'POST',
    body: JSON.stringify({ project_id: projectId, answers, lang }),
  });
}

export function revealHint(id: string, projectId: number): Promise<HintsRevealed> {
  return request<HintsRevealed>(`${base(id)}/hint`, { method: 'POST', body: JSON.stringify({ project_id: projectId }) });
}

/** Gives up: the solution may be shown from now on. Answers the progress. */
export function giveUp(id: string, projectId: number): Promise<Progress> {
  return request<Progress>(`${base(id)}/give-up`, { method: 'POST', body: JSON.stringify({ project_id: projectId }) });
}

/** The reference solution: refused (403) unless the learner passed or gave up. */
export function getSolution(id: string, projectId: number): Promise<Solution> {
  return request<Solution>(`${base(id)}/solution?project_id=${projectId}`);
}
