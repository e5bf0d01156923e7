"""The STL (AWL) compiler front end: STEP 7 STL sources → ``nasaq.ir.Program``.

``parse`` (Lark LALR, ``grammars/stl.lark``) → ``bind`` (blocks, symbols, types, layouts) →
``lower`` (``resolve`` operands, ``check`` them, ``calls``) → IR; ``dbdata`` fills data blocks.

What STEP 7 accepts is accepted; where awlsim's test programs go beyond it, STEP 7 wins. awlsim's
own syntax is accepted only where it is harmless, and then only with test instructions enabled
(``test_ops``, the switch that admits ``__ASSERT==``); without it, it is an error that says so:
- ``SFC -3`` / ``SFB -1`` (awlsim's own system blocks, also in a symbol table): ``STL218``;
- ``P#DB42.member`` / ``P#"Data".member`` (a pointer to a DB variable): made the STEP 7 constant
  ``P#DB42.DBX 4.0``; for an ANY parameter with awlsim's type (the element type of an array,
  else the widest of DWORD/WORD/BYTE that fits); without test instructions ``STL107``;
- ``#str[i]`` (character ``i`` of a STRING, a CHAR): without test instructions ``STL235``.
Accepted in any case, as STEP 7 does: block properties before or after a DB's structure or
instance FB; ``DT#...`` and ``'text'`` constants as actual values of DATE_AND_TIME and STRING
parameters (IR constant types DATE_AND_TIME and STRING: they never reach an accumulator);
``DB [MW 14]`` / ``FC [MW 12]`` / ``T [MW 2]`` for BLOCK_DB/BLOCK_FC/TIMER ... parameters; a
declared variable as an ANY actual becomes STEP 7's ``P#DB5.DBX 2.0 INT 1`` (STRUCTs as BYTEs).
"""

from nasaq.lang.stl.compiler import CompileResult, SourceFile, compile_sources

__all__ = ["CompileResult", "SourceFile", "compile_sources"]
