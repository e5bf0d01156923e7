import { useCallback } from 'react';
import { useTranslation } from 'react-i18next';
import type { DiagnosticEntry } from '../api/monitor';
import type { TreeBlock } from '../api/types';
import { useOpenProjectFile } from '../editor/useOpenProjectFile';
import { useProjectContents } from '../projects/projectContents';
import { formatSimTime } from '../cpu/cpuState';
import { useMonitor, useSession } from '../cpu/SessionContext';
import { useProblemText } from '../cpu/useProblemText';
import { ErrorIcon } from '../ui/icons';

const NO_BLOCKS: readonly TreeBlock[] = [];

/** `OB1 NW 2 line 7`: where in the program the CPU made the entry. */
export function cpuEntryPlace(entry: Pick<DiagnosticEntry, 'block' | 'network' | 'line'>): string {
  const parts: string[] = [];
  if (entry.block) parts.push(entry.block);
  if (entry.network != null) parts.push(`NW ${entry.network}`);
  if (entry.line != null) parts.push(`L ${entry.line}`);
  return parts.join(' ');
}

/**
 * The file and line an entry points at: the block's file (from the project's block list) at the
 * entry's line, or at the block's header when the CPU knows no line. Null for a block without a
 * source (a system block, an instance DB) or an entry without a block.
 */
export function cpuEntryTarget(
  entry: Pick<DiagnosticEntry, 'block' | 'line'>,
  blocks: readonly TreeBlock[],
): { file: string; line: number } | null {
  const name = entry.block?.replace(/\s+/g, '').toUpperCase();
  if (!name) return null;
  const block = blocks.find((item) => `${item.kind}${item.number}` === name && item.file);
  if (!block) return null;
  const line = entry.line ?? block.line;
  return { file: block.file, line: line ?? 1 };
}

/** Opens the faulting block of an entry at its line, in the session's project (for the
 * workbench, where the editor tabs are); false when the entry names no block with a source. */
export function useOpenCpuEntry(): (entry: DiagnosticEntry) => boolean {
  const { session } = useSession();
  const projectId = session?.projectId ?? null;
  const blocks = useProjectContents(projectId)?.blocks ?? NO_BLOCKS;
  const openFile = useOpenProjectFile();
  return useCallback(
    (entry) => {
      const target = projectId === null ? null : cpuEntryTarget(entry, blocks);
      if (projectId === null || !target) return false;
      openFile(projectId, target.file, { line: target.line }).catch(() => undefined);
      return true;
    },
    [projectId, blocks, openFile],
  );
}

/**
 * The CPU's diagnostic buffer, newest first as on a CPU's module information: its history comes
 * from GET .../diagnostics when the socket connects, new entries from the frames. Each entry is
 * said in the interface language from its catalogue key and params; its place is a link to the
 * faulting block and line, as a double-click on a buffer entry in STEP 7 opens the block there.
 */
export function CpuDiagnostics({ onOpen }: { onOpen?: (entry: DiagnosticEntry) => boolean }) {
  const { t } = useTranslation();
  const { session } = useSession();
  const entries = useMonitor((state) => state.diagnostics);
  const problemText = useProblemText();
  const projectId = session?.projectId ?? null;
  const blocks = useProjectContents(projectId)?.blocks ?? NO_BLOCKS;
  if (!session) return null;
  return (
    <section className="cpu-diagnostics" aria-label={t('diagnostics.cpuBuffer')} data-testid="cpu-diagnostics">
      <h3 className="cpu-diagnostics__title">
        {t('diagnostics.cpuBuffer')}
        <span className="count-badge">{entries.length}</span>
      </h3>
      {entries.length === 0 ? (
        <p className="panel-empty">{t('diagnostics.cpuBufferEmpty')}</p>
      ) : (
        <ol className="diagnostics__list" reversed>
          {[...entries].reverse().map((entry, index) => {
            const place = cpuEntryPlace(entry);
            return (
              <li key={`${entries.length - index}`} className="diagnostic diagnostic--error" data-testid="cpu-diagnostic">
                <ErrorIcon className="diagnostic__icon" />
                <code className="diagnostic__code">{entry.code}</code>
                <span className="diagnostic__message">{problemText(entry)}</span>
                {onOpen && place && cpuEntryTarget(entry, blocks) ? (
                  <button
                    type="button"
                    className="diagnostic__location diagnostic__jump"
                    dir="ltr"
                    data-testid="cpu-diagnostic-open"
                    title={t('diagnostics.goTo', { place })}
                    aria-label={t('diagnostics.goTo', { place })}
                    onClick={() => onOpen(entry)}
                  >
                    <code>
                      {place} · {formatSimTime(entry.time_ms)}
                    </code>
                  </button>
                ) : (
                  <code className="diagnostic__location" dir="ltr">
                    {place ? `${place} · ` : ''}
                    {formatSimTime(entry.time_ms)}
                  </code>
                )}
              </li>
            );
          })}
        </ol>
      )}
    </section>
  );
}
