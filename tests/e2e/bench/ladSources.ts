/**
 * The LAD sources of the diagram bench, generated: an OB 1 of 500 networks in the style of real
 * machine ladder (self-holding outputs with interlocks, on-delay timers, compares, MOVE and
 * arithmetic boxes, parallel branches, counters), and an FC of one FBD network of about 40 boxes.
 * Both compile without errors, so the project downloads and runs.
 */

function rung(n: number): string {
  const byte = n % 60;
  const bit = n % 8;
  const word = 2 * (n % 100);
  const timer = n % 64;
  const kinds = [
    // A self-holding output with two interlocks.
    `RUNG
  PARALLEL
    BRANCH Contact(I ${byte}.${bit}) END_BRANCH
    BRANCH Contact(Q ${byte}.${bit}) END_BRANCH
  END_PARALLEL
  ContactNC(I ${byte + 1}.${bit})
  ContactNC(M ${byte}.${(bit + 1) % 8})
  Coil(Q ${byte}.${bit})
END_RUNG`,
    // An on-delay timer box with its reset and value outputs.
    `RUNG
  Contact(I ${byte}.${bit})
  Box(S_ODT, INSTANCE T ${timer}, TV := S5T#${(n % 9) + 1}S, R := I ${byte + 2}.${bit}, BI => MW ${200 + word})
  Coil(M ${byte + 100}.${bit})
END_RUNG`,
    // A compare feeding two outputs.
    `RUNG
  Box(CMP>=I, IN1 := MW ${word}, IN2 := ${n % 500})
  OUTPUTS
    BRANCH Coil(M ${byte + 50}.${bit}) END_BRANCH
    BRANCH ContactNC(I ${byte}.${(bit + 2) % 8}) SetCoil(M ${byte + 50}.${(bit + 1) % 8}) END_BRANCH
  END_OUTPUTS
END_RUNG`,
    // Arithmetic on an edge.
    `RUNG
  Contact(I ${byte}.${bit})
  Edge(P, M ${byte + 150}.${bit})
  Box(ADD_I, IN1 := MW ${word}, IN2 := 1, OUT => MW ${word})
END_RUNG`,
    // MOVE with an enable made of nested branches.
    `RUNG
  PARALLEL
    BRANCH Contact(I ${byte}.${bit}) Contact(I ${byte}.${(bit + 1) % 8}) END_BRANCH
    BRANCH
      PARALLEL
        BRANCH Contact(M ${byte}.${bit}) END_BRANCH
        BRANCH ContactNC(M ${byte + 1}.${bit}) END_BRANCH
      END_PARALLEL
    END_BRANCH
  END_PARALLEL
  Box(MOVE, IN := ${n}, OUT => MW ${400 + word})
END_RUNG`,
  ];
  return kinds[n % kinds.length] as string;
}

/** OB 1 with `count` networks. */
export function ladBlock(count: number): string {
  const networks: string[] = [];
  for (let n = 1; n <= count; n += 1) networks.push(`NETWORK\nTITLE = Network ${n}\n${rung(n)}`);
  return `ORGANIZATION_BLOCK OB 1\nTITLE = Diagram bench, ${count} networks\nBEGIN\n${networks.join('\n')}\nEND_ORGANIZATION_BLOCK\n`;
}

/**
 * An FBD network of about 40 boxes: five outputs, each behind an AND of an OR, a NOT and an edge,
 * all fed from one common AND of the rail logic.
 */
export function fbdBlock(): string {
  const outputs: string[] = [];
  for (let k = 0; k < 5; k += 1) {
    outputs.push(`    BRANCH
      PARALLEL
        BRANCH Contact(I 1.${k}) Contact(I 2.${k}) END_BRANCH
        BRANCH Contact(I 3.${k}) Not END_BRANCH
      END_PARALLEL
      Edge(P, M 20.${k})
      Midline(M 21.${k})
      Coil(Q 5.${k})
    END_BRANCH`);
  }
  return `FUNCTION FC 40 : VOID
TITLE = FBD bench, one network of about 40 boxes
LANGUAGE FBD
BEGIN
NETWORK
TITLE = Five outputs from one common AND
RUNG
  Contact(I 0.0)
  Contact(I 0.1)
  OUTPUTS
${outputs.join('\n')}
  END_OUTPUTS
END_RUNG
END_FUNCTION
`;
}
