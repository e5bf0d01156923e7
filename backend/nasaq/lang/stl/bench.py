"""Compile speed: ``python -m nasaq.lang.stl.bench [MB]`` compiles a generated valid program of
mixed STEP 7-style networks (FBs with locals, FCs with DB, symbol and indirect accesses and calls,
OBs of bit logic; about 50 bytes a line) and prints the time of each phase.

The parse is mostly Lark's own work (its lexer and LALR tables); everything around it (the
token loop, the AST, binding, lowering) is ours and is what this measures against it.
"""

from __future__ import annotations

import sys
import time

_FB = (
    "NETWORK\nTITLE = Motor {n}\n// comment line of network {n}\n"
    "      A     #start;\n      AN    #stop;\n      O     #running;\n      =     #running;\n"
    "      L     #count;\n      +     1;\n      T     #count;\n"
    "      A(    ;\n      O     I {byte}.{bit};\n      O     M {byte}.{bit};\n      )     ;\n"
    "      JCN   M{label:03d};\n      L     #setpoint;\n      L     2.5E+1;\n      *R    ;\n"
    "      T     #value;\nM{label:03d}: L     S5T#2S;\n      SD    T {timer};\n"
    "      A     T {timer};\n      =     #done;\n      L     #arr[{index}];\n      T     #tmp;\n"
    "      L     #pos.x;\n      T     #pos.y;\n"
)
_FC = (
    "NETWORK\nTITLE = Calc {n}\n"
    '      L     "Data".level;\n      L     #limit;\n      >I    ;\n      =     #alarm;\n'
    "      L     DB1.DBW {word};\n      L     W#16#{n:X};\n      AW    ;\n      T     MW {word};\n"
    "      L     P#M {byte}.0;\n      LAR1  ;\n      L     MW [AR1, P#0.0];\n      T     LW 0;\n"
    "      L     L#{n};\n      L     #in1;\n      +D    ;\n      T     #out1;\n"
    "      CALL  FC 900 (\n            a := MW {word},\n            b := I {byte}.{bit},\n"
    "            r := MD {word});\n"
)
_OB = (
    "NETWORK\nTITLE = Main {n}\n"
    "      A     I {byte}.{bit};\n      AN    M {byte}.{bit};\n      =     Q {byte}.{bit};\n"
    "      L     MW {word};\n      L     {n};\n      ==I   ;\n      S     M {byte}.{bit};\n"
    "      L     'AB';\n      T     MW {word};\n      L     T#1S500MS;\n      T     MD {word};\n"
)
_HEAD = {
    "FB": (
        "FUNCTION_BLOCK FB {block}\nTITLE = Block {block}\nVERSION : 0.1\nVAR_INPUT\n"
        "  start : BOOL;\n  stop : BOOL;\n  setpoint : REAL;\nEND_VAR\nVAR_OUTPUT\n  done : BOOL;\n"
        "  value : REAL;\nEND_VAR\nVAR\n  running : BOOL;\n  count : INT;\n"
        "  arr : ARRAY[1..4] OF INT;\n  pos : STRUCT\n    x : INT;\n    y : INT;\n  END_STRUCT;\n"
        "END_VAR\nVAR_TEMP\n  tmp : INT;\nEND_VAR\nBEGIN\n"
    ),
    "FC": (
        "FUNCTION FC {block} : VOID\nTITLE = Block {block}\nVAR_INPUT\n  limit : INT;\n"
        "  in1 : DINT;\nEND_VAR\nVAR_OUTPUT\n  alarm : BOOL;\n  out1 : DINT;\nEND_VAR\nBEGIN\n"
    ),
    "OB": "ORGANIZATION_BLOCK OB {block}\nTITLE = Block {block}\nBEGIN\n",
}
_END = {"FB": "END_FUNCTION_BLOCK\n", "FC": "END_FUNCTION\n", "OB": "END_ORGANIZATION_BLOCK\n"}
_BODY = {"FB": _FB, "FC": _FC, "OB": _OB}
PRELUDE = (
    "DATA_BLOCK DB 1\n  STRUCT\n"
    + "".join(f"    w{i} : INT := {i};\n" for i in range(100))
    + "  END_STRUCT;\nBEGIN\nEND_DATA_BLOCK\n"
    'DATA_BLOCK "Data"\n  STRUCT\n    level : INT;\n    flags : ARRAY[1..16] OF BOOL;\n'
    "  END_STRUCT;\nBEGIN\n  level := 5;\nEND_DATA_BLOCK\n"
    "FUNCTION FC 900 : VOID\nVAR_INPUT\n  a : INT;\n  b : BOOL;\nEND_VAR\nVAR_OUTPUT\n  r : DINT;\n"
    "END_VAR\nBEGIN\n  L #a;\n  ITD;\n  T #r;\nEND_FUNCTION\n"
)
SYMBOLS = "Data,DB 2\n"  # the symbol table the program needs (a .csv)
NETWORKS_PER_BLOCK = 100


def mixed_program(size_chars: int) -> str:
    """A valid program of at least ``size_chars`` characters (with ``SYMBOLS``)."""
    parts = [PRELUDE]
    size = len(PRELUDE)
    block = 0
    while size < size_chars:
        block += 1
        kind = ("FB", "FC", "OB")[block % 3]
        text = [_HEAD[kind].format(block=block)]
        for label in range(NETWORKS_PER_BLOCK):
            n = block * NETWORKS_PER_BLOCK + label
            byte, bit = divmod(n % 1000, 8)
            text.append(
                _BODY[kind].format(
                    n=n,
                    byte=byte,
                    bit=bit,
                    word=2 * (n % 500),
                    label=label,
                    timer=n % 128,
                    index=n % 4 + 1,
                )
            )
        text.append(_END[kind])
        chunk = "".join(text)
        parts.append(chunk)
        size += len(chunk)
    return "".join(parts)


def main(argv: list[str]) -> int:
    from nasaq.lang.stl import SourceFile, compile_sources
    from nasaq.lang.stl.parse import parse_source

    megabytes = float(argv[1]) if len(argv) > 1 else 3.5
    text = mixed_program(int(megabytes * 1024 * 1024))
    sources = [SourceFile("bench.awl", text), SourceFile("bench.csv", SYMBOLS)]
    compile_sources([SourceFile("warm.awl", "NOP 0\n")])  # builds the parser
    started = time.perf_counter()
    parsed = parse_source("bench.awl", text)
    parse_seconds = time.perf_counter() - started
    started = time.perf_counter()
    result = compile_sources(sources)
    total = time.perf_counter() - started
    lines = text.count("\n")
    print(f"{len(text) / 1e6:.2f} MB, {lines} lines, {len(parsed.source.blocks)} blocks")
    print(f"compile {total:.2f} s ({lines / total:,.0f} lines/s), parse {parse_seconds:.2f} s")
    return 0 if result.ok else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
