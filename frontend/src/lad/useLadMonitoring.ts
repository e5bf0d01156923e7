/**
 * Program status in a LAD/FBD editor: while monitoring is on, the block on screen is opened on
 * the session with the networks on screen only (the server instruments just those), and the
 * elements' states of each sampled scan come back per network. Also where the CPU holds.
 */
import { useEffect, useMemo, useRef } from 'react';
import type { ElementStatus } from '../api/monitor';
import { problemOf, useMonitor, useSession } from '../cpu/SessionContext';
import type { Problem } from '../api/monitorClient';
import type { ElementState } from './status';

/** How long the scroll position must rest before other networks are opened. */
export const OPEN_DELAY_MS = 120;

/** `OB 1`, `FC10`, `"Motor"` as the session names blocks (`OB1`), or the symbol as written. */
export function sessionBlockName(name: string): string {
  const absolute = /^\s*(OB|FB|FC)\s*(\d+)\s*$/i.exec(name);
  return absolute ? `${absolute[1]?.toUpperCase()}${Number(absolute[2])}` : name.trim();
}

export interface LadMonitoring {
  online: boolean;
  /** The element states of network `n` (1-based), by element id; empty: not processed. */
  statesOf: (network: number) => ReadonlyMap<string, ElementState> | undefined;
  /** The network the CPU holds in, if it holds in this block of this file. */
  heldNetwork: number | null;
}

const EMPTY: ReadonlyMap<string, ElementState> = new Map();

interface Options {
  enabled: boolean;
  projectId: number;
  file: string;
  /** The block on screen (as the file names it) and its networks on screen (1-based). */
  block: string | null;
  networks: readonly number[];
  /** The session's name of this block, when it differs (a symbolic name: `FB5`). */
  resolvedName?: string | null;
  onProblem: (problem: Problem | null) => void;
}

export function useLadMonitoring({ enabled, projectId, file, block, networks, resolvedName, onProblem }: Options): LadMonitoring {
  const { session, client } = useSession();
  const online = enabled && client !== null && session?.projectId === projectId && block !== null;
  const problemRef = useRef(onProblem);
  problemRef.current = onProblem;
  const name = block ? sessionBlockName(block) : null;
  const networkKey = networks.join(',');

  useEffect(() => {
    if (!online || !client || !name) return;
    let live = true;
    const timer = setTimeout(() => {
      const wanted = networkKey === '' ? [] : networkKey.split(',').map(Number);
      client
        .openBlock(name, wanted)
        .then(() => live && problemRef.current(null))
        .catch((error: unknown) => live && problemRef.current(problemOf(error)));
    }, OPEN_DELAY_MS);
    return () => {
      live = false;
      clearTimeout(timer);
    };
  }, [online, client, name, networkKey]);

  useEffect(() => {
    if (!online || !client) return;
    return () => {
      client.openBlock(null).catch(() => undefined);
      problemRef.current(null);
    };
  }, [online, client]);

  const status = useMonitor((state) => state.block);
  const hold = useMonitor((state) => state.hold);
  const byNetwork = useMemo(() => {
    const grouped = new Map<number, Map<string, ElementState>>();
    if (!online || !status || !status.elements) return grouped;
    for (const element of status.elements as readonly ElementStatus[]) {
      let states = grouped.get(element.network);
      if (!states) grouped.set(element.network, (states = new Map()));
      states.set(element.id, { value: element.value ?? null, out: element.out ?? null, pins: element.pins ?? {} });
    }
    return grouped;
  }, [online, status]);

  const here = (candidate: string | null | undefined) =>
    !!candidate && (candidate === name || candidate === resolvedName);
  const heldNetwork =
    hold && here(hold.location.block) && (!hold.location.file || hold.location.file === file) ? hold.location.network ?? null : null;

  const sampled = online && status !== null && (here(status.block) || status.language === 'lad' || status.language === 'fbd');
  return {
    online,
    statesOf: (network) => (sampled ? (byNetwork.get(network) ?? EMPTY) : undefined),
    heldNetwork,
  };
}
