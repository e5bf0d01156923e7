/** The typed calls of `api/symbols.ts`: URLs, bodies, the raw import upload and error mapping. */
import { describe, expect, it } from 'vitest';
import { ApiError } from '../../frontend/src/api/client';
import {
  getDbMembers,
  getSymbols,
  importSymbols,
  saveSymbols,
  symbolsExportUrl,
} from '../../frontend/src/api/symbols';
import { apiError, json, mockServer, serverDown } from './helpers';

const OUT = { name: 'my symbols.sdf', format: 'sdf', version: 3, rows: [], problems: [] };

describe('symbol table calls', () => {
  it('reads and saves the rows of an escaped file name, with the base version', async () => {
    const fetchMock = mockServer({
      'GET /api/projects/2/symbols/my%20symbols.sdf': () => json(OUT),
      'PUT /api/projects/2/symbols/my%20symbols.sdf': () => json({ ...OUT, version: 4 }),
    });
    expect((await getSymbols(2, 'my symbols.sdf')).version).toBe(3);
    const rows = [{ name: 'A', address: 'I 0.0', type: 'BOOL', comment: '' }];
    expect((await saveSymbols(2, 'my symbols.sdf', rows, 3)).version).toBe(4);
    const [, init] = fetchMock.mock.calls[1]!;
    expect(JSON.parse(String(init?.body))).toEqual({ rows, base_version: 3 });
    expect(new Headers(init?.headers).get('Content-Type')).toBe('application/json');
  });

  it('uploads an import as the raw file, its name, mode and version in the query', async () => {
    const url = '/api/projects/2/symbols/s.sdf/import?name=plant+old.asc&mode=merge&base_version=5';
    const fetchMock = mockServer({ [`POST ${url}`]: () => json(OUT) });
    const upload = new Blob(['126,Start                   I 0.0\r\n']);
    await importSymbols(2, 's.sdf', upload, 'plant old.asc', 'merge', 5);
    const [, init] = fetchMock.mock.calls[0]!;
    expect(init?.body).toBe(upload);
    expect(new Headers(init?.headers).get('Content-Type')).toBe('application/octet-stream');
  });

  it('names the export download by format', () => {
    expect(symbolsExportUrl(2, 'my symbols.sdf', 'asc')).toBe('/api/projects/2/symbols/my%20symbols.sdf/export?format=asc');
  });

  it('reads a DB by number or symbol', async () => {
    mockServer({ 'GET /api/projects/2/blocks/%22Tank%22/members': () => json({ kind: 'DB', number: 1, members: [] }) });
    expect((await getDbMembers(2, '"Tank"')).number).toBe(1);
  });

  it('turns refusals into ApiErrors with the catalogue code, and a dead server into NET000', async () => {
    mockServer({
      'GET /api/projects/2/symbols/x.sdf': () => apiError(422, 'API127', 'not_a_symbol_table', 'no', { name: 'x.sdf' }),
    });
    const refused = await getSymbols(2, 'x.sdf').catch((error: unknown) => error);
    expect(refused).toBeInstanceOf(ApiError);
    expect((refused as ApiError).code).toBe('API127');
    expect((refused as ApiError).status).toBe(422);
    serverDown();
    const down = await getSymbols(2, 'x.sdf').catch((error: unknown) => error);
    expect((down as ApiError).code).toBe('NET000');
  });
});
