import type { MonitorState } from '../api/monitorClient';

/**
 * What the CPU panel shows: no session yet, the socket connecting, the CPU's own mode
 * (`pause`: in RUN with the clock stopped, e.g. after a single scan), or a session that ended.
 */
export type CpuMode = 'none' | 'connecting' | 'stop' | 'run' | 'pause' | 'hold' | 'closed';

export function cpuModeOf(hasSession: boolean, state: Pick<MonitorState, 'connection' | 'cpu'>): CpuMode {
  if (!hasSession) return 'none';
  if (state.connection === 'closed') return 'closed';
  const cpu = state.cpu;
  if (state.connection !== 'open' || cpu === null) return 'connecting';
  if (cpu.mode === 'HOLD') return 'hold';
  if (cpu.mode === 'STOP') return 'stop';
  return cpu.time_mode === 'pause' ? 'pause' : 'run';
}

/** Simulated time as seconds with milliseconds, e.g. `12.340 s`; minutes above one minute. */
export function formatSimTime(ms: number): string {
  const total = Math.max(0, ms) / 1000;
  if (total < 60) return `${total.toFixed(3)} s`;
  const minutes = Math.floor(total / 60);
  const seconds = total - minutes * 60;
  return `${minutes} min ${seconds.toFixed(1).padStart(4, '0')} s`;
}

/** A wall-clock duration of the program's work, e.g. `0.042 ms`. */
export function formatMs(ms: number): string {
  return `${ms < 10 ? ms.toFixed(3) : ms.toFixed(1)} ms`;
}
