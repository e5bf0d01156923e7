import { useEffect, useState } from 'react';
import { request } from '../api/client';
import type { PlantInfo } from './types';

let catalogue: Promise<PlantInfo[]> | null = null;

/** `GET /api/plants`: every plant kind with its signals, faults and usual wiring (asked once). */
export function listPlants(): Promise<PlantInfo[]> {
  if (!catalogue) {
    catalogue = request<PlantInfo[]>('/api/plants').catch((error: unknown) => {
      catalogue = null; // asked again next time
      throw error;
    });
  }
  return catalogue;
}

/** Forgets the catalogue (tests start from none). */
export function forgetPlantCatalogue(): void {
  catalogue = null;
}

export interface PlantCatalogue {
  plants: readonly PlantInfo[];
  status: 'loading' | 'ready' | 'error';
}

/** The plant catalogue for a view; an error leaves the drawings working from the frames alone. */
export function usePlantCatalogue(): PlantCatalogue {
  const [state, setState] = useState<PlantCatalogue>({ plants: [], status: 'loading' });
  useEffect(() => {
    let alive = true;
    listPlants().then(
      (plants) => alive && setState({ plants, status: 'ready' }),
      () => alive && setState({ plants: [], status: 'error' }),
    );
    return () => {
      alive = false;
    };
  }, []);
  return state;
}
