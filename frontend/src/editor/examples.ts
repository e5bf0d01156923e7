/**
 * What a new source opens with: small programs that compile with Nasaq's compilers as they
 * stand (`nasaq compile`). Kept apart from the language definitions, which load with Monaco.
 */

/** A small program for a new STL source: a self-holding motor circuit in OB1. */
export const STL_EXAMPLE = `ORGANIZATION_BLOCK OB 1
TITLE = Main cycle
VERSION : 0.1

VAR_TEMP
  info : ARRAY [0 .. 19] OF BYTE;   // start information
END_VAR

BEGIN
NETWORK
TITLE = Motor with a start and a stop button
      A(    ;
      O     I      0.0;             // start button
      O     Q      4.0;             // motor contactor holds itself
      )     ;
      AN    I      0.1;             // stop button
      =     Q      4.0;

NETWORK
TITLE = Count the starts
      A     I      0.0;
      FP    M     10.0;
      JCN   M001;
      L     MW    20;
      +     1;
      T     MW    20;
M001: NOP   0;
END_ORGANIZATION_BLOCK
`;

/** A small program for a new SCL source: a tank filled between two levels. */
export const SCL_EXAMPLE = `FUNCTION_BLOCK FB 10
TITLE = 'Tank filling'
VERSION : '0.1'

VAR_INPUT
  level : INT;            // level sensor, 0..1000
  low : INT := 200;
  high : INT := 800;
END_VAR
VAR_OUTPUT
  pump : BOOL;
END_VAR
VAR
  fills : DINT;           (* how often the pump started *)
END_VAR

BEGIN
  IF level < low AND NOT pump THEN
    pump := TRUE;
    fills := fills + 1;
  ELSIF level >= high THEN
    pump := FALSE;
  END_IF;
  MW20 := INT_TO_WORD(level);
  Q4.0 := pump;
END_FUNCTION_BLOCK
`;
