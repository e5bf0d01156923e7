import { ApiError, getBlocks, listFiles, saveFile } from '../api/client';
import type { FileInfo } from '../api/types';
import { freeSourceName, newSourceText, nameTaken } from '../projects/fileNames';
import { sourceExample } from './examples';

export type StartLanguage = 'stl' | 'scl';

const SUFFIX: Record<StartLanguage, 'awl' | 'scl'> = { stl: 'awl', scl: 'scl' };
const SOURCE = /\.(awl|stl|scl|db|udt|lad|fbd|graph)$/i;

export interface CreatedSource {
  info: FileInfo;
  text: string;
}

type Api = { listFiles: typeof listFiles; getBlocks: typeof getBlocks; saveFile: typeof saveFile };

/**
 * Creates the Start page's new source as a file of the project, so its text is saved from the
 * first keystroke. A project without sources gets the example program (OB 1 with a motor
 * circuit); one that has sources gets an empty FC with a free number, which cannot clash with
 * its blocks, as the project tree's "New STL source" does. The name is the first free
 * `SourceN`; the list is read from the server just before, and a name taken meanwhile (API108)
 * moves on to the next number.
 */
export async function createStartSource(
  projectId: number,
  language: StartLanguage,
  api: Api = { listFiles, getBlocks, saveFile },
): Promise<CreatedSource> {
  const files = [...(await api.listFiles(projectId))];
  let text = sourceExample(language); // commented in the page's language
  if (files.some((file) => SOURCE.test(file.name))) {
    const build = await api.getBlocks(projectId);
    text = newSourceText(language, build.blocks);
  }
  for (let attempt = 0; attempt < 20; attempt++) {
    const name = freeSourceName(files, SUFFIX[language]);
    try {
      const info = await api.saveFile(projectId, name, { text });
      return { info, text };
    } catch (caught) {
      if (!(caught instanceof ApiError) || caught.code !== 'API108' || nameTaken(files, name)) throw caught;
      files.push({ name, language, size: 0, version: 0, created_at: '', updated_at: '' });
    }
  }
  throw new Error('no free source name');
}
