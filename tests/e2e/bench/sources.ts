/**
 * The sources of the editor bench, generated: an STL function of 500 networks in the style of
 * real machine code (bit logic, timers, arithmetic, jumps) called from OB1, and an SCL source of
 * 5,000 lines of functions with IF, CASE and FOR. Both compile without errors, so the project
 * downloads and runs.
 */

/** One network of the STL block; `n` varies the addresses so no two networks are the same. */
function stlNetwork(n: number): string {
  const byte = n % 60;
  const bit = n % 8;
  const word = 2 * (n % 100);
  const timer = n % 64;
  const kinds = [
    // A self-holding output with an interlock.
    `      A(
      O     I ${byte}.${bit}
      O     Q ${byte}.${bit}
      )
      AN    I ${byte + 1}.${bit}
      AN    M ${byte}.${(bit + 1) % 8}
      =     Q ${byte}.${bit}`,
    // An on-delay timer.
    `      A     I ${byte}.${bit}
      L     S5T#${(n % 9) + 1}S
      SD    T ${timer}
      A     T ${timer}
      =     M ${byte + 100}.${bit}`,
    // Integer arithmetic with a limit.
    `      L     MW ${word}
      +     1
      T     MW ${word}
      L     MW ${word}
      L     1000
      >I
      JCN   N${n}
      L     0
      T     MW ${word}
N${n}: NOP   0`,
    // A comparison that sets and resets a flag.
    `      L     IW ${word % 40}
      L     ${n * 7}
      >=I
      S     M ${byte + 200}.${bit}
      A     I ${byte}.${(bit + 3) % 8}
      R     M ${byte + 200}.${bit}`,
    // A jump over a block of logic.
    `      A     M ${byte}.${bit}
      JC    J${n}
      O     I ${byte}.${bit}
      ON    I ${byte + 2}.${bit}
      =     M ${byte + 300}.${bit}
J${n}: NOP   0`,
  ];
  return `NETWORK\nTITLE = Network ${n}\n${kinds[n % kinds.length]}\n`;
}

export function stlBlock(networks: number): string {
  const body = Array.from({ length: networks }, (_, index) => stlNetwork(index + 1)).join('');
  return `FUNCTION FC 100 : VOID\nTITLE = Machine logic of ${networks} networks\nBEGIN\n${body}END_FUNCTION\n`;
}

export const OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Main cycle
VAR_TEMP
  Info : ARRAY [0 .. 19] OF BYTE;
END_VAR
BEGIN
NETWORK
TITLE = The machine logic
      CALL  FC   100
NETWORK
TITLE = The SCL functions
      CALL  FC   200
END_ORGANIZATION_BLOCK
`;

/** One SCL function of about `lines` lines: IF, CASE and FOR over a local array. */
function sclFunction(n: number): string[] {
  return [
    `FUNCTION FC ${n + 200} : INT`,
    `// Generated function ${n}: a sum, a case and a limit`,
    'VAR_INPUT',
    '  Mode : INT;',
    '  Limit : INT;',
    'END_VAR',
    'VAR_TEMP',
    '  Values : ARRAY[0..9] OF INT;',
    '  I : INT;',
    '  Sum : INT;',
    'END_VAR',
    'BEGIN',
    '  Sum := 0;',
    '  FOR I := 0 TO 9 DO',
    `    Values[I] := I * ${(n % 7) + 1};`,
    '    Sum := Sum + Values[I];',
    '  END_FOR;',
    '  CASE Mode OF',
    '    0:',
    `      Sum := Sum + ${n};`,
    '    1:',
    '      Sum := Sum - Limit;',
    '    2..5:',
    '      Sum := Sum * 2;',
    '  ELSE',
    '    Sum := 0;',
    '  END_CASE;',
    '  IF Sum > Limit THEN',
    '    Sum := Limit;',
    '  ELSIF Sum < (-Limit) THEN',
    '    Sum := 0 - Limit;',
    '  END_IF;',
    `  FC${n + 200} := Sum;`,
    'END_FUNCTION',
    '',
  ];
}

/**
 * `lines` lines of SCL: FC 200 calls the first few generated functions (so they run), the
 * functions FC 201 onwards fill the rest.
 */
export function sclSource(lines: number): string {
  const out: string[] = [];
  const perFunction = sclFunction(1).length;
  const count = Math.max(1, Math.floor((lines - 12) / perFunction));
  for (let n = 1; n <= count; n += 1) out.push(...sclFunction(n));
  const head = [
    'FUNCTION FC 200 : VOID',
    'VAR_TEMP',
    '  R : INT;',
    'END_VAR',
    'BEGIN',
    ...Array.from({ length: Math.min(count, 5) }, (_, i) => `  R := FC${i + 201}(Mode := ${i}, Limit := 100);`),
    'END_FUNCTION',
    '',
  ];
  out.push(...head);
  while (out.length < lines) out.push(`// filler line ${out.length + 1}`);
  return out.slice(0, lines).join('\n') + '\n';
}
