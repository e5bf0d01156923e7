"""SCALE (FC 105) and UNSCALE (FC 106), the "TI-S7 Converting Blocks" of STEP 7's Standard
Library that S7-300/400 programs call to turn an analog value into engineering units and back.

A program that calls ``SCALE`` or ``UNSCALE`` by name (``CALL SCALE (...)``, ``CALL "SCALE"``)
and neither defines nor names a block so gets the block added, as STEP 7 copies it from the
library into the block folder: an STL FC written here (Nasaq's own code, after the interface
and behaviour the Siemens manual describes), numbered 105/106 or, when the program uses that
number, the lowest free from ``RELOCATED_BASE``.

- SCALE: ``OUT := (IN - K1) / (K2 - K1) * (HI_LIM - LO_LIM) + LO_LIM`` with K1 = 0 (unipolar)
  or -27648 (BIPOLAR), K2 = 27648; an IN beyond K1..K2 gives LO_LIM/HI_LIM and RET_VAL
  W#16#0008, else RET_VAL 0.
- UNSCALE: the inverse, ``OUT := (IN - LO_LIM) / (HI_LIM - LO_LIM) * (K2 - K1) + K1`` rounded
  to an INT; an IN beyond LO_LIM..HI_LIM gives K1/K2 and RET_VAL W#16#0008.
"""

from __future__ import annotations

from collections.abc import Iterable

from nasaq.lang.iec_library import RELOCATED_BASE
from nasaq.lang.stl import ast
from nasaq.lang.stl.addresses import AddressError, parse_address
from nasaq.lang.stl.library import CALL_SPELLINGS
from nasaq.lang.stl.symbols import Symbol, SymbolTable

LIBRARY_FILE = "<TI-S7 Converting Blocks>"


def _converter(name: str, title: str, types: tuple[str, str], norm: str, formula: str) -> str:
    """The STL text of SCALE or UNSCALE: the bounds K1/K2, ``norm`` (leaves the value to clamp
    in #X, between #K1 and #K2 for SCALE, 0.0 and 1.0 for UNSCALE), the clamp with RET_VAL
    W#16#0008, then ``formula`` from #X to the OUT value in ACCU1. ``{{number}}`` stays a
    placeholder for ``sources``."""
    low, high = ("#K1", "#K2") if name == "SCALE" else ("0.000000e+000", "1.000000e+000")
    return f"""\
FUNCTION FC {{number}} : WORD
TITLE = {name}: {title}
FAMILY : CONVERT
NAME : {name}
VERSION : 2.1
VAR_INPUT
  IN : {types[0]};
  HI_LIM : REAL;
  LO_LIM : REAL;
  BIPOLAR : BOOL;
END_VAR
VAR_OUTPUT
  OUT : {types[1]};
END_VAR
VAR_TEMP
  K1 : REAL;
  K2 : REAL;
  X : REAL;
  SPAN : REAL;
END_VAR
BEGIN
      L     0.000000e+000;
      T     #K1;
      A     #BIPOLAR;
      JCN   UNI;
      L     -2.764800e+004;
      T     #K1;
UNI:  L     2.764800e+004;
      T     #K2;
      L     W#16#0;
      T     #RET_VAL;
{norm}
      L     #X;
      L     {high};
      >R    ;
      JCN   NHI;
      T     #X;
      L     W#16#8;
      T     #RET_VAL;
      JU    CALC;
NHI:  L     #X;
      L     {low};
      <R    ;
      JCN   CALC;
      T     #X;
      L     W#16#8;
      T     #RET_VAL;
CALC: NOP   0;
{formula}
      T     #OUT;
END_FUNCTION
"""


_SCALE = _converter(
    "SCALE",
    "an analog input value (INT) in engineering units (REAL)",
    ("INT", "REAL"),
    """\
      L     #IN;
      ITD   ;
      DTR   ;
      T     #X;""",
    """\
      L     #K2;
      L     #K1;
      -R    ;
      T     #SPAN;
      L     #X;
      L     #K1;
      -R    ;
      L     #SPAN;
      /R    ;
      T     #X;
      L     #HI_LIM;
      L     #LO_LIM;
      -R    ;
      L     #X;
      *R    ;
      L     #LO_LIM;
      +R    ;""",
)

_UNSCALE = _converter(
    "UNSCALE",
    "a value in engineering units (REAL) as an analog output value (INT)",
    ("REAL", "INT"),
    """\
      L     #HI_LIM;
      L     #LO_LIM;
      -R    ;
      T     #SPAN;
      L     #IN;
      L     #LO_LIM;
      -R    ;
      L     #SPAN;
      /R    ;
      T     #X;""",
    """\
      L     #K2;
      L     #K1;
      -R    ;
      L     #X;
      *R    ;
      L     #K1;
      +R    ;
      RND   ;""",
)

BLOCKS = {"SCALE": (105, _SCALE), "UNSCALE": (106, _UNSCALE)}


def called(items: Iterable[ast.CodeItem], symbols: SymbolTable, defined: set[str]) -> set[str]:
    """The names of this library that ``CALL`` names and no symbol or block of the program
    (``defined``: upper-case names of the sources' blocks) defines."""
    found: set[str] = set()
    for item in items:
        # every instruction of the program passes here: one set lookup for most of them
        if type(item) is not ast.InstrNode or item.mnemonic not in CALL_SPELLINGS:
            continue
        if not item.operands:
            continue
        target = item.operands[0]
        if (isinstance(target, ast.BareNode) and target.arg is None) or (
            isinstance(target, ast.SymbolNode) and not target.local and not target.path
        ):
            name = target.name
        else:
            continue
        key = name.upper()
        if key in BLOCKS and key not in defined and symbols.get(name) is None:
            found.add(key)
    return found


def sources(names: Iterable[str], symbols: SymbolTable, used: set[int]) -> list[str]:
    """The STL text of each block ``names`` asks for, numbered, with its symbol added."""
    texts: list[str] = []
    for name in sorted(names):
        number, text = BLOCKS[name]
        if number in used or symbols.block_symbol("FC", number) is not None:
            number = RELOCATED_BASE
            while number in used or symbols.block_symbol("FC", number) is not None:
                number += 1
        used.add(number)
        address = f"FC {number}"
        symbols.symbols[name.casefold()] = Symbol(
            name, address, parse_address(address), "", "", LIBRARY_FILE, 0
        )
        texts.append(text.format(number=number))
    return texts


def fc_numbers(idents: Iterable[str]) -> set[int]:
    """The FC numbers among absolute block ids (``FC 105``)."""
    numbers: set[int] = set()
    for ident in idents:
        try:
            parsed = parse_address(ident)
        except AddressError:
            continue
        if parsed.kind == "block" and parsed.block is not None and parsed.block.value == "FC":
            numbers.add(parsed.number)
    return numbers
