/**
 * Shapes of the Nasaq HTTP API, as the front end sees them.
 *
 * Kept in one file and held to the backend's OpenAPI document (`openapi.json` beside this file,
 * regenerated with `.venv/bin/nasaq openapi > frontend/src/api/openapi.json`): the tests fail when
 * the two disagree on the fields of a shape.
 */

/** `GET /api/health` */
export interface Health {
  status: 'ok';
  version: string;
  database: 'ok';
}

/** A PLC project stored on the server (`GET /api/projects`, `POST /api/projects`). */
export interface Project {
  id: number;
  name: string;
  description: string;
  /** ISO 8601 timestamp */
  created_at: string;
  /** ISO 8601 timestamp */
  updated_at: string;
}

/** Body of `POST /api/projects`. */
export interface ProjectCreate {
  name: string;
  description: string;
}

/** A path into the request that caused an error, e.g. `["body", "name"]`. */
export type ErrorLocation = Array<string | number>;

/** What every failed API call answers: `{"error": ApiProblem}`. */
export interface ApiProblem {
  /** Stable catalogue code, e.g. `API409` or `API105`. */
  code: string;
  message: string;
  /** Message key the UI translates (`problems.<key>` in the catalogues). */
  key: string;
  params?: Record<string, unknown>;
  location?: ErrorLocation | null;
  severity?: Severity;
  span?: Span | null;
}

export interface ApiErrorBody {
  error: ApiProblem;
}

export type Severity = 'error' | 'warning' | 'info';

/**
 * Where a problem sits (backend `nasaq.diagnostics.Span`): a 1-based source position and, for
 * LAD/FBD/Graph, a network and the element in it. Every part is optional; a project-wide
 * problem has no span at all.
 */
export interface Span {
  file?: string | null;
  line?: number | null;
  column?: number | null;
  end_line?: number | null;
  end_column?: number | null;
  network?: number | null;
  /** The LAD/FBD element id in its network (`e1`, `e2` ...). */
  element?: string | null;
}

/** A compiler or simulator finding (backend `nasaq.diagnostics.Diagnostic`). */
export interface Diagnostic {
  /** Stable catalogue code, e.g. `STL101`. */
  code: string;
  severity: Severity;
  /** Message key the UI translates (`problems.<key>` in the catalogues). */
  key: string;
  /** The message in English, parameters filled in; shown when the UI has no translation. */
  message: string;
  params: Record<string, unknown>;
  span: Span | null;
}

/** What a project file holds, by its suffix: STL, SCL, LAD/FBD, S7-Graph, a symbol table or a watch table. */
export type FileLanguage = 'stl' | 'scl' | 'lad' | 'fbd' | 'graph' | 'symbols' | 'watch' | 'cpu' | 'plant';
/** The language a block is written in: its file's (LAD and FBD blocks are kept as text). */
export type BlockLanguage = Exclude<FileLanguage, 'symbols' | 'watch' | 'cpu' | 'plant'>;

/** One source file of a project (`GET /api/projects/{id}/files`). */
export interface FileInfo {
  name: string;
  language: FileLanguage;
  /** Length of the text in characters. */
  size: number;
  /** Counts the saves; sent back as `base_version` when saving. */
  version: number;
  /** ISO 8601 timestamp */
  created_at: string;
  /** ISO 8601 timestamp */
  updated_at: string;
}

/** One file with its text (`GET /api/projects/{id}/files/{name}`). */
export interface FileOut extends FileInfo {
  text: string;
}

/** Body of `PUT /api/projects/{id}/files/{name}` (autosave). */
export interface FileSave {
  text: string;
  /** The version the editor loaded; a stale one is refused with 409 (API111). */
  base_version?: number | null;
}

/** Body of `PATCH .../files/{name}` (rename) and `POST .../files/{name}/duplicate`. */
export interface FileName {
  name: string;
}

export type BlockKind = 'OB' | 'FB' | 'FC' | 'DB' | 'UDT';

/** A block the project's files define (`GET /api/projects/{id}/blocks`). */
export interface TreeBlock {
  kind: BlockKind;
  number: number;
  /** Symbolic name, empty when the block has none. */
  name: string;
  title: string;
  language: BlockLanguage;
  /** The file that defines the block. */
  file: string;
  /** Line of the block's header in its file; null for an instance DB the compiler created. */
  line: number | null;
  /** Instance DBs: `FB 10`. */
  instance_of?: string | null;
}

/** What a project's files compile to: the block tree and the compiler's diagnostics. */
export interface ProjectBuild {
  blocks: TreeBlock[];
  diagnostics: Diagnostic[];
}

/** Body of `POST /api/projects/{id}/check`: one editor text in place of its stored file. */
export interface UnsavedFile {
  name: string;
  text: string;
}

/** Answer of `POST /api/projects/import`. */
export interface ImportOut {
  project: Project;
  /** The source files imported, by name. */
  files: string[];
  /** Entries that are not sources (README, scenarios...). */
  skipped: string[];
}
