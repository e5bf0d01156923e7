/**
 * The shapes the plant drawings read: a plant's part of a session frame and the plant catalogue
 * of `GET /api/plants` (backend/nasaq/plants, brief of issue 17 section 6).
 */

import type { MonitorCommand } from '../api/monitorClient';

export type PlantValue = number | boolean | string;

/** A plant as a frame carries it: what the drawing animates (generated from the protocol). */
export type { PlantFrame } from '../api/monitor';

export type SignalDirection = 'sensor' | 'control' | 'actuator';

export interface PlantSignalInfo {
  name: string;
  direction: SignalDirection;
  kind: 'bool' | 'word';
  normally_closed: boolean;
  description: string;
}

export interface PlantFaultInfo {
  code: string;
  injectable: boolean;
  description: string;
}

/** One plant kind of the catalogue. */
export interface PlantInfo {
  kind: string;
  title: string;
  signals: PlantSignalInfo[];
  faults: PlantFaultInfo[];
  defaults: Record<string, number>;
  default_wiring: Record<string, string>;
}

/** What a project's `<kind>.plant` file holds (the backend's PlantConfig). */
export interface PlantConfig {
  kind: string;
  wiring: Record<string, string>;
  params: Record<string, number>;
  faults: string[];
}

/** The socket commands of the operator panel (backend/nasaq/monitor/protocol.py). */
export type PlantCommand = Extract<MonitorCommand, { type: 'plant_operate' | 'plant_fault' | 'plant_reset' }>;
