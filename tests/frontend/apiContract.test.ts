/**
 * The front end's API types against the backend's OpenAPI document. Each record below must name
 * exactly the keys of its TypeScript interface (the compiler checks that), and the test checks them
 * against the schema's properties, so a field added or renamed on either side fails here.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { CLIENT_ERROR_CODES, asApiError } from '../../frontend/src/api/client';
import openapi from '../../frontend/src/api/openapi.json';
import type { ApiProblem, Diagnostic, Health, Project, ProjectCreate, Span } from '../../frontend/src/api/types';
import type { SessionOut } from '../../frontend/src/api/sessions';

type Fields<T> = Record<keyof Required<T>, true>;

const health: Fields<Health> = { status: true, version: true, database: true };
const project: Fields<Project> = { id: true, name: true, description: true, created_at: true, updated_at: true };
const projectCreate: Fields<ProjectCreate> = { name: true, description: true };
const span: Fields<Span> = {
  file: true,
  line: true,
  column: true,
  end_line: true,
  end_column: true,
  network: true,
  element: true,
};
const apiProblem: Fields<ApiProblem> = {
  code: true,
  severity: true,
  key: true,
  message: true,
  params: true,
  span: true,
  location: true,
};
const sessionOut: Fields<SessionOut> = {
  id: true,
  blocks: true,
  cpu: true,
  clients: true,
  websocket: true,
  project_id: true,
  project_name: true,
  profile: true,
  started_at: true,
  age_seconds: true,
};
const diagnostic: Fields<Diagnostic> = { code: true, severity: true, key: true, message: true, params: true, span: true };

const schemas = openapi.components.schemas as Record<string, { properties?: Record<string, unknown> }>;
const propertiesOf = (name: string): string[] => Object.keys(schemas[name]?.properties ?? {}).sort();
const keys = (record: object): string[] => Object.keys(record).sort();

describe('API types match the OpenAPI document', () => {
  it.each([
    ['Health', health],
    ['ProjectOut', project],
    ['ProjectCreate', projectCreate],
    ['Span', span],
    ['ApiProblem', apiProblem],
    ['SessionOut', sessionOut],
  ])('%s', (schema, record) => {
    expect(propertiesOf(schema).length).toBeGreaterThan(0);
    expect(keys(record)).toEqual(propertiesOf(schema));
  });

  it('Diagnostic is an API problem without the request location', () => {
    expect([...keys(diagnostic), 'location'].sort()).toEqual(propertiesOf('ApiProblem'));
  });

  it('the severities are the backend enum', () => {
    const severity = schemas.Severity as unknown as { enum: string[] };
    const ours: Record<Diagnostic['severity'], true> = { error: true, warning: true, info: true };
    expect(keys(ours)).toEqual([...severity.enum].sort());
  });
});

describe('client-side problem codes', () => {
  it('are rows of the one diagnostics catalogue, with the keys the client uses', () => {
    const csv = fs.readFileSync(path.resolve(__dirname, '../../backend/nasaq/diagnostics/client.csv'), 'utf8');
    const keyOf = new Map(csv.trim().split('\n').slice(1).map((row) => {
      const [code, , key] = row.split(',');
      return [code!, key!] as const;
    }));
    expect(keyOf.get(CLIENT_ERROR_CODES.unreachable)).toBe('server_unreachable');
    expect(keyOf.get(CLIENT_ERROR_CODES.badResponse)).toBe('unexpected_response');
    expect(keyOf.get(asApiError(new Error('x')).code)).toBe(asApiError(new Error('x')).key);
  });
});
