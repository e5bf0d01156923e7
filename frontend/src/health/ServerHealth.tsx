import { createContext, useCallback, useContext, useEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import { asApiError, getHealth, type ApiError } from '../api/client';
import type { Health } from '../api/types';

export type ServerHealth =
  | { state: 'checking' }
  | { state: 'online'; health: Health }
  | { state: 'offline'; error: ApiError };

interface ServerHealthValue {
  health: ServerHealth;
  /** Asks the server again now. */
  recheck: () => void;
}

const ServerHealthContext = createContext<ServerHealthValue | null>(null);

/** How often the connection is checked again in the background. */
const RECHECK_MS = 30_000;

/** Asks `GET /api/health` at start and every 30 s, and shares the answer. */
export function ServerHealthProvider({ children }: { children: ReactNode }) {
  const [health, setHealth] = useState<ServerHealth>({ state: 'checking' });
  const latest = useRef(0);

  const recheck = useCallback(() => {
    const ticket = ++latest.current;
    getHealth().then(
      (answer) => {
        if (ticket === latest.current) setHealth({ state: 'online', health: answer });
      },
      (error: unknown) => {
        if (ticket === latest.current) setHealth({ state: 'offline', error: asApiError(error) });
      },
    );
  }, []);

  useEffect(() => {
    recheck();
    const timer = window.setInterval(recheck, RECHECK_MS);
    return () => {
      window.clearInterval(timer);
      latest.current += 1; // answers arriving after unmount are ignored
    };
  }, [recheck]);

  const value = useMemo(() => ({ health, recheck }), [health, recheck]);
  return <ServerHealthContext.Provider value={value}>{children}</ServerHealthContext.Provider>;
}

export function useServerHealth(): ServerHealthValue {
  const value = useContext(ServerHealthContext);
  if (!value) throw new Error('useServerHealth needs a <ServerHealthProvider> above it');
  return value;
}
