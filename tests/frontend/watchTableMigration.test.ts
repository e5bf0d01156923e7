/** The watch table a browser kept in localStorage moves into a project file once, and is then forgotten. */
import { beforeEach, describe, expect, it, vi } from 'vitest';

const saved: Array<{ projectId: number; name: string; text: string }> = [];
vi.mock('../../frontend/src/api/client', async (importOriginal) => {
  const original = await importOriginal<typeof import('../../frontend/src/api/client')>();
  return {
    ...original,
    saveFile: vi.fn(async (projectId: number, name: string, body: { text: string }) => {
      saved.push({ projectId, name, text: body.text });
      const now = new Date().toISOString();
      return { name, language: 'watch', size: body.text.length, version: 1, created_at: now, updated_at: now };
    }),
  };
});

const { migrateLegacyTable, legacyStorageKey } = await import('../../frontend/src/watchtables/tableFiles');
const { parseWatchTable } = await import('../../frontend/src/watchtables/format');

const file = (name: string) => ({ name, language: 'watch' as const, size: 0, version: 1, created_at: '', updated_at: '' });

describe('the old localStorage watch table', () => {
  beforeEach(() => {
    saved.length = 0;
    window.localStorage.clear();
  });

  it('becomes a table file with its rows and formats, once', async () => {
    window.localStorage.setItem(
      legacyStorageKey(7),
      JSON.stringify([
        { entry: '"Motor"', format: null },
        { entry: 'MW10', format: 'hex' },
      ]),
    );
    const info = await migrateLegacyTable(7, [file('VAT_1.vat')]);
    expect(info?.name).toBe('VAT_2.vat');
    expect(saved).toHaveLength(1);
    const rows = parseWatchTable(saved[0]!.text).lines.flatMap((line) => (line.kind === 'row' ? [line.row] : []));
    expect(rows.map((row) => [row.operand, row.format])).toEqual([
      ['"Motor"', null],
      ['MW10', 'hex'],
    ]);
    expect(window.localStorage.getItem(legacyStorageKey(7))).toBeNull();
    expect(await migrateLegacyTable(7, [])).toBeNull();
    expect(saved).toHaveLength(1);
  });

  it('keeps the stored rows when the file cannot be saved', async () => {
    const client = await import('../../frontend/src/api/client');
    vi.mocked(client.saveFile).mockRejectedValueOnce(new Error('server away'));
    window.localStorage.setItem(legacyStorageKey(8), JSON.stringify([{ entry: 'QW4', format: null }]));
    await expect(migrateLegacyTable(8, [])).rejects.toThrow('server away');
    expect(window.localStorage.getItem(legacyStorageKey(8))).not.toBeNull();
  });
});
