/**
 * What the CPU panel can show. Today only `unavailable` happens: the simulator is
 * not part of this release, so the front end never pretends a CPU is running.
 */
export type CpuMode = 'unavailable' | 'stop' | 'run' | 'hold';

export const CURRENT_CPU_MODE: CpuMode = 'unavailable';
