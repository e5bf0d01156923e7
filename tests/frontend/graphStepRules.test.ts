/**
 * The step view's action rules (frontend/src/graph/actionRules.ts) against the Graph checker
 * (backend/nasaq/lang/graph/check_actions.py), row by row on fixtures/graph-action-rules.json
 * (written by fixtures/make_graph_action_rules.py; a pytest fails when it is out of date): every
 * event × qualifier × C pair, operands and values under every qualifier, in a step with an
 * interlock and in one without. Also what the dropdowns offer.
 */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { checkAction, legalEvents, legalPair, legalQualifiers, parseQualifier, type Event, type Qualifier } from '../../frontend/src/graph/actionRules';
import type { Action, Step } from '../../frontend/src/graph/model';

interface Found {
  code: string;
  key: string;
  severity: string;
  params: Record<string, string>;
}
interface Row {
  event: Event | null;
  qualifier: Qualifier;
  interlock: boolean;
  operand: string;
  time: string | null;
  found: { interlock: Found[]; plain: Found[] };
}

const fixture = JSON.parse(fs.readFileSync(path.join(__dirname, 'fixtures', 'graph-action-rules.json'), 'utf-8')) as { rows: Row[] };

function step(number: number, name: string, interlock: boolean): Step {
  return { number, name, initial: false, comment: '', interlock: interlock ? { elements: [] } : null, supervision: null, actions: [] };
}

const idle = step(1, 'Idle', true);
const fill = step(2, 'Fill', false);

describe('action rules: parity with the Graph checker', () => {
  it('has a corpus covering every code the rules give', () => {
    const codes = new Set(fixture.rows.flatMap((row) => [...row.found.interlock, ...row.found.plain].map((f) => f.code)));
    expect([...codes].sort()).toEqual(['GRA230', 'GRA231', 'GRA232', 'GRA233', 'GRA234', 'GRA235', 'GRA236', 'GRA237', 'GRA238', 'GRA239', 'GRA240', 'GRA241', 'GRA242', 'GRA243', 'GRA246', 'GRA247']);
  });

  it('gives the checker’s findings on every row, in a step with and without an interlock', () => {
    let compared = 0;
    for (const row of fixture.rows) {
      const action: Action = { id: 'a1', event: row.event, qualifier: row.qualifier, interlock: row.interlock, operand: row.operand, time: row.time, comment: '' };
      for (const [where, owner] of [['interlock', idle], ['plain', fill]] as const) {
        const got = checkAction(action, owner, [idle, fill]).map(({ code, key, severity, params }) => ({ code, key, severity, params }));
        expect(got, `${JSON.stringify(row)} in ${owner.name}`).toEqual(row.found[where]);
        compared += 1;
      }
    }
    expect(compared).toBeGreaterThan(4000);
  });
});

describe('action rules: what the table offers', () => {
  it('offers only the qualifiers that go with an event', () => {
    expect(legalQualifiers(null)).toEqual(['N', 'NC', 'S', 'SC', 'R', 'RC', 'D', 'DC', 'L', 'LC', 'CALL', 'CALLC']);
    expect(legalQualifiers('S1')).toEqual(['N', 'NC', 'S', 'SC', 'R', 'RC', 'CALL', 'CALLC', 'ON', 'ONC', 'OFF', 'OFFC', 'CS', 'CSC', 'CU', 'CUC', 'CD', 'CDC', 'CR', 'CRC', 'TL', 'TLC', 'TD', 'TDC', 'TR', 'TRC']);
    expect(legalQualifiers('S0')).not.toContain('NC');
    expect(legalQualifiers('S0')).not.toContain('D');
    for (const event of [null, 'S1', 'S0', 'V1', 'V0', 'L1', 'L0', 'A1', 'R1'] as const) {
      for (const text of legalQualifiers(event)) {
        const parsed = parseQualifier(text);
        expect(parsed).not.toBeNull();
        expect(legalPair(event, parsed!.qualifier, parsed!.interlock)).toBe(true);
      }
    }
  });

  it('offers the events a qualifier takes', () => {
    expect(legalEvents('D', false)).toEqual([null]);
    expect(legalEvents('ON', true)).toEqual(['S1', 'V1', 'A1', 'R1']);
    expect(legalEvents('N', false)).toEqual([null, 'S1', 'S0', 'V1', 'V0', 'L1', 'L0', 'A1', 'R1']);
  });

  it('reads a typed qualifier as the source reader does', () => {
    expect(parseQualifier(' nc ')).toEqual({ qualifier: 'N', interlock: true });
    expect(parseQualifier('CS')).toEqual({ qualifier: 'CS', interlock: false });
    expect(parseQualifier('CSC')).toEqual({ qualifier: 'CS', interlock: true });
    expect(parseQualifier('X')).toBeNull();
    expect(parseQualifier('')).toBeNull();
  });
});
