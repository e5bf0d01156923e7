import { useCallback, useState } from 'react';

/** Reads a value from localStorage; storage can be missing or refuse access (private modes). */
export function readStored(key: string): string | null {
  try {
    return window.localStorage.getItem(key);
  } catch {
    return null;
  }
}

export function writeStored(key: string, value: string): void {
  try {
    window.localStorage.setItem(key, value);
  } catch {
    // Not remembering a UI preference is harmless.
  }
}

/** A boolean UI preference remembered across visits under `key`. */
export function usePersistentFlag(key: string, initial: boolean): [boolean, (next: boolean) => void] {
  const [value, setValue] = useState<boolean>(() => {
    const stored = readStored(key);
    if (stored === 'true') return true;
    if (stored === 'false') return false;
    return initial;
  });
  const update = useCallback(
    (next: boolean) => {
      setValue(next);
      writeStored(key, String(next));
    },
    [key],
  );
  return [value, update];
}
