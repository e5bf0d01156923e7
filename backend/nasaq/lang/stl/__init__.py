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

Accepted export forms (``.awl`` as TIA Portal's "Generate source from blocks" and STEP 7
Classic's "Generate source" write them; ``test_stl_tia_export``, ``test_stl_classic_export``):
- files: a UTF-8 BOM, CRLF or LF, no newline at the end, Windows-1252 when not UTF-8;
- block names quoted and symbolic (``FUNCTION_BLOCK "Motor"``, ``FUNCTION "Scale" : Void``,
  ``DATA_BLOCK "Data"``, ``TYPE "Udt"``, ``ORGANIZATION_BLOCK "Main"``) or absolute (``FB 1``);
  a name no symbol table gives a number is numbered as TIA does (``stl.numbering``: lowest
  free number; OBs by event "Main", "Startup", "Cyclic interrupt" ... or by STEP 7's OB
  symbols "CYCL_EXC", "Cyclic Interrupt 5" ..., ``nasaq.lang.tia_names``); an instance DB
  named in ``CALL "Fb", "Fb_DB"`` that nothing defines is created (``STL229``, as for ``DB 5``);
- block properties in any order before BEGIN: ``TITLE =`` (with or without text) and its
  ``//`` comment lines, ``{ S7_Optimized_Access := 'FALSE' }`` and other attributes,
  ``AUTHOR``/``FAMILY``/``NAME``/``VERSION : 0.1``, ``KNOW_HOW_PROTECT``, ``NON_RETAIN`` ...;
  ``S7_Optimized_Access := 'TRUE'`` is ``STL500`` under S7-300/400 (only the S7-1200/1500
  family has optimized blocks); under S7-1500 such a block is laid out as a standard one, which
  symbolic STL accesses cannot tell apart; an absolute address in an optimized DB (``L DB10.DBW
  0``, ``L "Data".DBW 0``) is ``STL604``, as in TIA;
- constants by type name as TIA writes them (``L INT#5``, ``L DINT#-7``, ``L WORD#16#FF``,
  ``L REAL#1.5``: what ``L 5``, ``L L#-7``, ``L W#16#FF``, ``L 1.5`` load); ``UDINT#``, ``UINT#``,
  ``USINT#``, ``SINT#`` are ``STL500`` under S7-300/400, the 64-bit ``LREAL#``, ``LINT#`` ...
  ``STL603`` (no accumulator holds them);
- declarations in TIA spelling (``Bool``, ``Int``, ``S5Time``, ``Date_And_Time``, ``String[20]``,
  ``Array[0..3] of Int``, ``Struct ... END_STRUCT;``, ``"Udt"``, ``TON``/``CTU`` ... for the
  IEC SFBs), member attributes (``{ S7_SetPoint := 'True'}``, ``{ExternalAccessible :=
  'False'}``, ``{InstructionName := 'TON'; LibVersion := '1.0'}``), names that are no
  identifiers quoted (``"Start Button" : Bool;``, ``#"Start Button"``, ``"Start Button" :=``);
  ``VAR RETAIN``/``VAR NON_RETAIN`` (static data) and ``VAR CONSTANT`` (``#Limit`` is its value;
  ``STL601`` when it has none);
- DB values after BEGIN (``Speed := 7;``, ``Table[2] := 9;``, ``First.Amount := 12;``);
- code: ``NETWORK`` with ``TITLE =`` (empty or not), ``//`` comments, German or English
  mnemonics, ``#local`` and ``"DB".member`` operands, ``%I0.0``/``%DB1.DBX0.0`` (``%`` read as
  STEP 7 addresses, case-insensitive: ``db20.dbw0``), ``L P##x``, ``CALL #inst`` and ``CALL
  "Fb" , "Db"`` with the parameter list on the CALL line (Classic) or on the following lines
  (TIA), ``CALL TON , "IEC_Timer_0_DB"``; S7-1500 exports: ``{time_type := 'Time'}`` before
  the parameters (``STL500`` under S7-300/400, ``STL602`` for a type other than Time/Int) and
  jump labels longer than four characters (``STL209`` under S7-300/400, as STEP 7);
- STEP 7 Classic: a local variable written without its ``#`` (``L position1``) where no symbol
  has that name; ``CALL SCALE`` / ``CALL UNSCALE`` of the Standard Library's TI-S7 Converting
  Blocks add FC 105/106 (``stl.converting``) when the program lacks them;
- a UDT that several sources each carry (Classic exports a DB with its UDTs) is one UDT when
  written alike; written differently it is ``STL215``. A variable whose type is unknown is
  reported once, at its declaration, not at each use.
"""

from nasaq.lang.stl.compiler import CompileResult, SourceFile, compile_sources

__all__ = ["CompileResult", "SourceFile", "compile_sources"]
