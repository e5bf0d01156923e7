/**
 * The course's two-conveyor sequence (tests/scenarios/graph/g17_conveyors.graph, made linear so
 * that a user builds it in a minute): Start switches belt B on and belt A 5 s later, Stop
 * switches both off; a jam of belt B while it starts is a supervision error (acknowledgement
 * required). graph-editor.spec.ts builds it by hand and compares with CONVEYORS;
 * graph-monitor.spec.ts runs it.
 */
/** The sequence as a file. */
export const CONVEYORS = `FUNCTION_BLOCK FB 1
TITLE = Two conveyors
COMMENT = Start: belt B, belt A 5 s later. Stop: both off. A jam while B starts is an error.
SETTINGS
  PARAMETERS := STANDARD;
  ACKNOWLEDGE := TRUE;
END_SETTINGS
BEGIN
SEQUENCER Sequencer1

INITIAL_STEP Step1 (1)
ACTIONS
  N "Ready";
END_ACTIONS
END_STEP

TRANSITION Trans1 (1) FROM Step1 TO B_on
CONDITION Contact("Start") END_CONDITION
END_TRANSITION

STEP B_on (2)
SUPERVISION Contact("Jam") END_SUPERVISION
ACTIONS
  S "Belt_B";
END_ACTIONS
END_STEP

TRANSITION Trans2 (2) FROM B_on TO Step3
CONDITION Box(CMP>=D, IN1 := B_on.T, IN2 := T#5S) END_CONDITION
END_TRANSITION

STEP Step3 (3)
ACTIONS
  S "Belt_A";
END_ACTIONS
END_STEP

TRANSITION Trans3 (3) FROM Step3 TO Step4
CONDITION Contact("Stop") END_CONDITION
END_TRANSITION

STEP Step4 (4)
ACTIONS
  R "Belt_A";
  R "Belt_B";
END_ACTIONS
END_STEP

TRANSITION Trans4 (4) FROM Step4 JUMP Step1
CONDITION ContactNC("Stop") END_CONDITION
END_TRANSITION

END_SEQUENCER
END_FUNCTION_BLOCK
`;

export const OB1 = `ORGANIZATION_BLOCK OB 1
TITLE = Calls the conveyor sequence every cycle
BEGIN
NETWORK
TITLE = The S7-Graph FB with its instance DB
      CALL "Conveyors", "IDB_Conveyors";
END_ORGANIZATION_BLOCK
`;

export const SYMBOLS = [
  ['Start', 'I 0.0', 'BOOL', 'Start button'],
  ['Stop', 'I 0.1', 'BOOL', 'Stop button'],
  ['Jam', 'I 0.3', 'BOOL', 'Belt B jammed'],
  ['Belt_A', 'Q 0.0', 'BOOL', 'Conveyor belt A'],
  ['Belt_B', 'Q 0.1', 'BOOL', 'Conveyor belt B'],
  ['Ready', 'Q 0.2', 'BOOL', 'Ready lamp'],
  ['Conveyors', 'FB 1', 'FB 1', 'The two-conveyor sequence'],
  ['IDB_Conveyors', 'DB 1', 'FB 1', 'Its instance DB'],
]
  .map((row) => row.map((cell) => `"${cell}"`).join(','))
  .join('\r\n');

