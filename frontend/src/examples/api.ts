/** The example projects in the interface language (backend `nasaq.api.examples`). */
import { request } from '../api/client';
import type { Project } from '../api/types';
import type { Language } from '../i18n/languages';

export interface ExampleProject {
  name: string;
  title: string;
  description: string;
  /** The project's name in this language. */
  project: string;
  /** The project made from this language's variant, when there is one. */
  project_id: number | null;
  /** The file to open first. */
  main: string | null;
}

export function listExamples(language: Language, signal?: AbortSignal): Promise<ExampleProject[]> {
  return request<ExampleProject[]>(`/api/examples?lang=${language}`, { signal });
}

/** The example as a project with this language's comments (made on the first call). */
export function openExample(name: string, language: Language): Promise<Project> {
  return request<Project>(`/api/examples/${encodeURIComponent(name)}/open?lang=${language}`, { method: 'POST' });
}
