"""Parse speed: ``python -m nasaq.lang.scl.bench [LINES]`` parses a generated valid SCL source of
about ``LINES`` lines (20,000 by default) and prints lines/s. The source is a mix of FBs and FCs
with declarations, IF/ELSIF/ELSE, CASE, FOR, WHILE and REPEAT, expressions of every precedence
level, absolute and DB addressing, member and array access, and FB/FC calls (about 7 tokens a
line, as hand-written SCL), and then the README's dense case (one 30-token IF line repeated).
The target (issue 4) is 20,000 lines/s of the mixed source for the parse alone.
"""

from __future__ import annotations

import sys
import time

_FB_HEAD = """FUNCTION_BLOCK FB{block}
TITLE = 'Block {block}'
VERSION : '1.0'
VAR_INPUT
  start : BOOL;
  stop : BOOL := FALSE;
  setpoint : REAL := 2.5E+1;
  limits : ARRAY[1..10] OF INT;
END_VAR
VAR_OUTPUT
  done : BOOL;
  value : REAL;
END_VAR
VAR
  running : BOOL;
  count, total : INT;
  pos : STRUCT
    x : INT;
    y : INT;
  END_STRUCT;
  timer1 : TON;
END_VAR
VAR_TEMP
  i, k : INT;
  tmp : DINT;
END_VAR
BEGIN
"""
_FB_BODY = """  // section {n}
  IF #start AND NOT #stop OR running AND (count > {n} XOR done) THEN
    running := TRUE;
    count := count + 1;
  ELSIF count >= 100 AND count <> {n} THEN
    count := 0;
  ELSE
    value := value * 0.5 + setpoint / 2.0 - REAL#1.5;
  END_IF;
  FOR i := 1 TO 10 BY 1 DO
    total := total + limits[i] * 2 MOD 7 - i DIV 3;
    IF limits[i] > total THEN
      EXIT;
    END_IF;
  END_FOR;
  CASE count OF
    0: value := 0.0;
    1, 2, 3: value := INT_TO_REAL(count) ** 2;
    4..9: pos.x := pos.y + WORD_TO_INT(MW{word}) - WORD_TO_INT(DB10.DW[i]);
  ELSE
    pos.y := -pos.x;
  END_CASE;
  timer1(IN := running, PT := T#2s);
  done := timer1.Q & M{byte}.{bit} OR I{byte}.{bit};
  WHILE k < 10 AND NOT done DO
    k := k + 1;
  END_WHILE;
  tmp := DINT#{n} + DWORD_TO_DINT(WORD_TO_DWORD(W#16#{n:X})) * (tmp - 1);
"""
_FC_HEAD = """FUNCTION FC{block} : INT
VAR_INPUT
  a, b : INT;
  ratio : REAL;
END_VAR
VAR_TEMP
  r : INT;
  j : INT;
END_VAR
BEGIN
"""
_FC_BODY = """  r := a * b + (a - b) / 2;
  IF r < 0 OR r > 32000 THEN
    r := 0;
  END_IF;
  REPEAT
    j := j + 1;
  UNTIL j >= {n} MOD 10 OR r = 0
  END_REPEAT;
  "Data".level := "Data".level + r - a * 3;
  FC{other}(a := r, b := {n}, ratio := ratio * 1.5);
  MW{word} := INT_TO_WORD(WORD_TO_INT(DB1.DBW{word}) + #a);
"""
_FB_END = "END_FUNCTION_BLOCK\n\n"
# The data blocks the code addresses, so that the source also compiles (check and lowering).
_DATA = """DATA_BLOCK DB1
STRUCT
  words : ARRAY[0..499] OF WORD;
END_STRUCT
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB10
STRUCT
  words : ARRAY[0..15] OF WORD;
END_STRUCT
BEGIN
END_DATA_BLOCK

DATA_BLOCK "Data"
STRUCT
  level : INT;
END_STRUCT
BEGIN
END_DATA_BLOCK

"""
_FC_END = "  FC{block} := r;\nEND_FUNCTION\n\n"
SECTIONS_PER_BLOCK = 20


def program(lines: int = 20_000) -> str:
    """A valid SCL source of at least ``lines`` lines."""
    parts: list[str] = []
    count = 0
    block = 0
    while count < lines:
        block += 1
        function = block % 3 == 0
        text = [(_FC_HEAD if function else _FB_HEAD).format(block=block)]
        for section in range(SECTIONS_PER_BLOCK):
            n = block * SECTIONS_PER_BLOCK + section
            byte, bit = divmod(n % 1000, 8)
            body = _FC_BODY if function else _FB_BODY
            other = 3 if block != 3 else 6  # an FC that exists (FC3 is always there)
            text.append(body.format(n=n, byte=byte, bit=bit, word=2 * (n % 500), other=other))
        text.append((_FC_END if function else _FB_END).format(block=block))
        chunk = "".join(text)
        parts.append(chunk)
        count += chunk.count("\n")
    return _DATA + "".join(parts)


_DENSE_LINE = "  IF a > i THEN x := x + i * 2; ELSE y := MW[i] + DB10.DW[i]; END_IF;\n"


def dense(lines: int = 20_000) -> str:
    """One FB of ``lines`` copies of a 30-token line (the README's first measurement)."""
    head = "FUNCTION_BLOCK FB1\nVAR\n  a, i, x, y : INT;\nEND_VAR\nBEGIN\n"
    return head + _DENSE_LINE * lines + "END_FUNCTION_BLOCK\n"


def _measure(name: str, text: str) -> bool:
    from nasaq.lang.scl.parse import parse_source

    best = float("inf")
    for _ in range(3):
        started = time.perf_counter()
        result = parse_source("bench.scl", text)
        best = min(best, time.perf_counter() - started)
    lines = text.count("\n")
    blocks = len(result.source.blocks)
    print(
        f"{name}: {len(text) / 1e6:.2f} MB, {lines} lines, {blocks} blocks: "
        f"parse {best:.3f} s, {lines / best:,.0f} lines/s (best of 3)"
    )
    for diagnostic in result.diagnostics[:5]:
        print(diagnostic)
    return not result.diagnostics


def main(argv: list[str]) -> int:
    from nasaq.lang.scl.parse import parse_source

    lines = int(argv[1]) if len(argv) > 1 else 20_000
    parse_source("warm.scl", "FUNCTION FC1 : VOID\nBEGIN\nEND_FUNCTION\n")  # builds the parser
    ok = _measure("mixed", program(lines))
    ok = _measure("dense", dense(lines)) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
