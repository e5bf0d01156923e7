/**
 * The TypeScript ports of the pure LAD functions (frontend/src/lad/: boxes, ids, print, layout,
 * fbd, fbdGraph) against the Python reference, on every entry of fixtures/lad-parity.json: the LAD
 * examples, the course's networks that lift to LAD and random networks of every shape. The fixture
 * is written by fixtures/make_lad_parity.py (`.venv/bin/python tests/frontend/fixtures/make_lad_parity.py`);
 * a pytest fails when it is out of date with the Python code.
 *
 * Results must be the same exactly: the printed text byte for byte, the models deep-equal with
 * their keys in the same order (box pins keep their order, as Python dicts keep it). The fixture
 * stores the objects of the views with their keys factored out (see the generator): `unpacked`
 * rebuilds them.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { CATALOGUE, boxSpec, callTarget, flowPins } from '../../frontend/src/lad/boxes';
import { toFbd } from '../../frontend/src/lad/fbd';
import { fbdLayout } from '../../frontend/src/lad/fbdGraph';
import { numberElements } from '../../frontend/src/lad/ids';
import { ladLayout } from '../../frontend/src/lad/layout';
import type { FbdLayout, FbdNetwork, LadBlock, LadLayout, Network } from '../../frontend/src/lad/model';
import { printLad } from '../../frontend/src/lad/print';

interface Views {
  duplicates: string[];
  lad_layout: LadLayout;
  fbd: FbdNetwork;
  fbd_layout: FbdLayout;
}

interface Entry {
  name: string;
  blocks: LadBlock[];
  text: string;
  /** Per block, per network; packed. */
  views: unknown;
}

interface CatalogueSpec {
  name: string;
  family: string;
  pins: { name: string; direction: string; type: string }[];
  en_eno: boolean;
  op: string;
  can_fail: boolean;
  flow_pin: string | null;
  flow_out: string | null;
  address: string | null;
}

interface NameProbe {
  name: string;
  box_spec: string | null;
  call_target: [string, boolean] | null;
  flow_pins: [string | null, string | null];
}

interface Fixture {
  catalogue: CatalogueSpec[];
  box_names: NameProbe[];
  /** The key lists of the packed objects. */
  keys: string[][];
  entries: Entry[];
}

const fixture = JSON.parse(fs.readFileSync(path.resolve(__dirname, 'fixtures/lad-parity.json'), 'utf8')) as Fixture;

/** A packed value with its objects rebuilt: `{"": [k, v1, v2 ...]}` has the keys `keys[k]`. */
function unpacked(value: unknown): unknown {
  if (Array.isArray(value)) return value.map(unpacked);
  if (value === null || typeof value !== 'object') return value;
  const [index, ...values] = (value as { '': [number, ...unknown[]] })[''];
  const names = fixture.keys[index];
  if (names === undefined || names.length !== values.length) throw new Error(`a packed object with the key list ${index} of the wrong length`);
  return Object.fromEntries(names.map((name, at) => [name, unpacked(values[at])]));
}

/** Deep-equal, and with every object's keys in the same order. */
function expectSame(actual: unknown, expected: unknown, what: string): void {
  expect(actual, what).toEqual(expected);
  expect(JSON.stringify(actual), `${what} (key order)`).toBe(JSON.stringify(expected));
}

/** The network with every id of the numbering's form (`e<n>`) cleared, as an edit leaves it. */
function clearedIds<T>(value: T): T {
  if (Array.isArray(value)) return value.map(clearedIds) as T;
  if (value === null || typeof value !== 'object') return value;
  const copy: Record<string, unknown> = {};
  for (const [key, item] of Object.entries(value)) {
    copy[key] = key === 'id' && typeof item === 'string' && /^e\d+$/.test(item) ? '' : clearedIds(item);
  }
  return copy as T;
}

function checkNetwork(network: Network, views: Views, where: string): void {
  expectSame(numberElements(clearedIds(network)), { network, duplicates: views.duplicates }, `${where}: numberElements`);
  expectSame(ladLayout(network), views.lad_layout, `${where}: ladLayout`);
  expectSame(toFbd(network), views.fbd, `${where}: toFbd`);
  expectSame(fbdLayout(views.fbd), views.fbd_layout, `${where}: fbdLayout`);
}

describe('the LAD parity fixture', () => {
  it('holds hundreds of networks of every origin', () => {
    const networks = (prefix: string) =>
      fixture.entries.filter((entry) => entry.name.startsWith(prefix)).reduce((sum, entry) => sum + entry.blocks.reduce((n, block) => n + block.networks.length, 0), 0);
    expect(networks('examples/lad/')).toBeGreaterThan(50);
    expect(networks('tests/scenarios/course/')).toBeGreaterThan(150);
    expect(networks('random #')).toBeGreaterThan(150);
  });
});

describe('boxes.ts against boxes.py', () => {
  it('has the same catalogue, in the same order', () => {
    const specs = Object.values(CATALOGUE).map((spec) => ({
      name: spec.name,
      family: spec.family,
      pins: spec.pins.map((pin) => ({ name: pin.name, direction: pin.direction, type: pin.type })),
      en_eno: spec.enEno,
      op: spec.op,
      can_fail: spec.canFail,
      flow_pin: spec.flowPin,
      flow_out: spec.flowOut,
      address: spec.address,
    }));
    expectSame(specs, fixture.catalogue, 'CATALOGUE');
  });

  it.each(fixture.box_names)('reads the box name $name as Python does', (probe) => {
    expect(boxSpec(probe.name)?.name ?? null, 'boxSpec').toBe(probe.box_spec);
    expect(callTarget(probe.name), 'callTarget').toEqual(probe.call_target);
    expect(flowPins(probe.name), 'flowPins').toEqual(probe.flow_pins);
  });
});

describe('the ports against the Python functions', () => {
  it.each(fixture.entries)('$name', (entry) => {
    expect(printLad(entry.blocks), `${entry.name}: printLad`).toBe(entry.text);
    const all = unpacked(entry.views) as Views[][];
    entry.blocks.forEach((block, b) => {
      block.networks.forEach((network, n) => {
        const views = all[b]?.[n];
        expect(views, `${entry.name}: views of block ${b + 1} network ${n + 1}`).toBeDefined();
        if (views) checkNetwork(network, views, `${entry.name} ${block.name} network ${n + 1}`);
      });
    });
  });
});
