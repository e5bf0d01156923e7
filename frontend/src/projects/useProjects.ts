import { useCallback, useEffect, useRef, useState } from 'react';
import { asApiError, listProjects, type ApiError } from '../api/client';
import type { Project } from '../api/types';

export type ProjectsState =
  | { status: 'loading' }
  | { status: 'ready'; projects: Project[] }
  | { status: 'error'; error: ApiError };

function byName(a: Project, b: Project): number {
  return a.name.localeCompare(b.name, undefined, { sensitivity: 'base', numeric: true });
}

const PROJECT_MADE = 'nasaq:project-made';

/** Tells every project list on the page about a project made outside it. */
export function announceProject(project: Project): void {
  window.dispatchEvent(new CustomEvent<Project>(PROJECT_MADE, { detail: project }));
}

/** The server's project list: loads on mount, reloads on demand, takes in newly created projects. */
export function useProjects() {
  const [state, setState] = useState<ProjectsState>({ status: 'loading' });
  const request = useRef<AbortController | null>(null);

  const reload = useCallback(() => {
    request.current?.abort();
    const controller = new AbortController();
    request.current = controller;
    setState({ status: 'loading' });
    listProjects(controller.signal).then(
      (projects) => {
        if (!controller.signal.aborted) setState({ status: 'ready', projects: [...projects].sort(byName) });
      },
      (error: unknown) => {
        if (!controller.signal.aborted) setState({ status: 'error', error: asApiError(error) });
      },
    );
  }, []);

  useEffect(() => {
    reload();
    return () => request.current?.abort();
  }, [reload]);

  const add = useCallback((project: Project) => {
    setState((current) => {
      const known = current.status === 'ready' ? current.projects.filter((p) => p.id !== project.id) : [];
      return { status: 'ready', projects: [...known, project].sort(byName) };
    });
  }, []);

  // A project made elsewhere in the page (the Start page's examples) joins the list.
  useEffect(() => {
    const taken = (event: Event) => add((event as CustomEvent<Project>).detail);
    window.addEventListener(PROJECT_MADE, taken);
    return () => window.removeEventListener(PROJECT_MADE, taken);
  }, [add]);

  const remove = useCallback((id: number) => {
    setState((current) =>
      current.status === 'ready' ? { status: 'ready', projects: current.projects.filter((p) => p.id !== id) } : current,
    );
  }, []);

  return { state, reload, add, remove };
}
