/**
 * The project files API's types (files, blocks, check, import) against the backend's OpenAPI
 * document: each record names exactly the keys of its TypeScript interface (the compiler checks
 * that), and the test checks them against the schema's properties.
 */
import { describe, expect, it } from 'vitest';
import openapi from '../../frontend/src/api/openapi.json';
import type {
  FileInfo,
  FileName,
  FileOut,
  FileSave,
  ImportOut,
  ProjectBuild,
  TreeBlock,
  UnsavedFile,
} from '../../frontend/src/api/types';

type Fields<T> = Record<keyof Required<T>, true>;

const fileInfo: Fields<FileInfo> = { name: true, language: true, size: true, version: true, created_at: true, updated_at: true };
const fileOut: Fields<FileOut> = { ...fileInfo, text: true };
const fileSave: Fields<FileSave> = { text: true, base_version: true };
const fileName: Fields<FileName> = { name: true };
const treeBlock: Fields<TreeBlock> = {
  kind: true,
  number: true,
  name: true,
  title: true,
  language: true,
  file: true,
  line: true,
  instance_of: true,
};
const projectBuild: Fields<ProjectBuild> = { blocks: true, diagnostics: true };
const unsavedFile: Fields<UnsavedFile> = { name: true, text: true };
const importOut: Fields<ImportOut> = { project: true, files: true, skipped: true };

type Schema = { properties?: Record<string, { enum?: string[] }> };
const schemas = openapi.components.schemas as Record<string, Schema>;
const propertiesOf = (name: string): string[] => Object.keys(schemas[name]?.properties ?? {}).sort();
const keys = (record: object): string[] => Object.keys(record).sort();
const paths = openapi.paths as Record<string, Record<string, unknown>>;

describe('project files API types match the OpenAPI document', () => {
  it.each([
    ['FileInfo', fileInfo],
    ['FileOut', fileOut],
    ['FileSave', fileSave],
    ['FileName', fileName],
    ['TreeBlock', treeBlock],
    ['ProjectBuild', projectBuild],
    ['UnsavedFile', unsavedFile],
    ['ImportOut', importOut],
  ])('%s', (schema, record) => {
    expect(propertiesOf(schema).length).toBeGreaterThan(0);
    expect(keys(record)).toEqual(propertiesOf(schema));
  });

  it('the enums are the backend’s', () => {
    const languages: Record<FileInfo['language'], true> = { stl: true, scl: true, lad: true, fbd: true, graph: true, symbols: true, watch: true, cpu: true, plant: true };
    expect(keys(languages)).toEqual([...(schemas.FileInfo!.properties!.language!.enum ?? [])].sort());
    const blockLanguages: Record<TreeBlock['language'], true> = { stl: true, scl: true, lad: true, fbd: true, graph: true };
    expect(keys(blockLanguages)).toEqual([...(schemas.TreeBlock!.properties!.language!.enum ?? [])].sort());
    const kinds: Record<TreeBlock['kind'], true> = { OB: true, FB: true, FC: true, DB: true, UDT: true };
    expect(keys(kinds)).toEqual([...(schemas.TreeBlock!.properties!.kind!.enum ?? [])].sort());
  });

  it('the client calls routes the server has, with their methods', () => {
    const routes: Array<[string, string]> = [
      ['/api/projects/{project_id}/files', 'get'],
      ['/api/projects/{project_id}/files/{name}', 'get'],
      ['/api/projects/{project_id}/files/{name}', 'put'],
      ['/api/projects/{project_id}/files/{name}', 'patch'],
      ['/api/projects/{project_id}/files/{name}', 'delete'],
      ['/api/projects/{project_id}/files/{name}/duplicate', 'post'],
      ['/api/projects/{project_id}/blocks', 'get'],
      ['/api/projects/{project_id}/check', 'post'],
      ['/api/projects/{project_id}/export.zip', 'get'],
      ['/api/projects/import', 'post'],
      ['/api/projects/{project_id}', 'delete'],
    ];
    for (const [path, method] of routes) expect(paths[path]?.[method], `${method} ${path}`).toBeDefined();
  });
});
