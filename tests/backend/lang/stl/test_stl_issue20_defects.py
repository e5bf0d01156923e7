"""Issue 20's defects on the STL side: a STRING parameter an FC passes on, the FB whose header
vanished after "too many syntax errors", the range of TIME, and the DB/DI registers inside a
multi-instance (cpu/COMPATIBILITY.md, "Defects (issue 20, the defects part)")."""

from __future__ import annotations

from cpu_run import run

from nasaq.cpu import Cpu
from nasaq.diagnostics import Severity
from nasaq.headless.addresses import parse_address
from nasaq.ir import BlockKind, Direct
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.parse import MAX_SYNTAX_ERRORS


def _run(text: str, scans: int = 1) -> Cpu:
    return run(compile_sources([SourceFile("prog.awl", text)]), scans)


def _read(cpu: Cpu, text: str) -> int:
    address = parse_address(text)
    assert isinstance(address, Direct)
    return int(cpu.read(address))


def _text(cpu: Cpu, db: int, byte: int) -> str:
    """The characters of the STRING at DBn.DBB byte (its current length, not its maximum)."""
    length = _read(cpu, f"DB{db}.DBB{byte + 1}")
    return bytes(_read(cpu, f"DB{db}.DBB{byte + 2 + k}") for k in range(length)).decode()


def test_a_string_input_passed_on_by_an_fc_arrives_whole() -> None:
    """A STRING handed on from FC to FC (OB 1's constant, through one and two levels, and from
    a DB) reaches the IEC function MID whole at every level."""
    source = """
DATA_BLOCK DB 5
  STRUCT
   direct : STRING [20];
   passed : STRING [20];
   twice : STRING [20];
  END_STRUCT;
BEGIN
END_DATA_BLOCK

FUNCTION FC 1 : VOID
VAR_INPUT
  s : STRING [254];
END_VAR
VAR_OUTPUT
  copy : STRING [20];
END_VAR
BEGIN
      CALL "MID" (IN := #s, L := 20, P := 1, RET_VAL := #copy);
END_FUNCTION

FUNCTION FC 2 : VOID
VAR_INPUT
  s : STRING [254];
END_VAR
BEGIN
      CALL "MID" (IN := #s, L := 20, P := 1, RET_VAL := DB5.direct);
      CALL FC 1 (s := #s, copy := DB5.passed);
END_FUNCTION

FUNCTION FC 3 : VOID
VAR_INPUT
  s : STRING [254];
END_VAR
BEGIN
      CALL FC 2 (s := #s);
END_FUNCTION

ORGANIZATION_BLOCK OB 1
BEGIN
      CALL FC 2 (s := 'hello');
      CALL FC 3 (s := 'two levels');
      CALL FC 1 (s := DB5.passed, copy := DB5.twice);
END_ORGANIZATION_BLOCK
"""
    cpu = _run(source)
    assert _text(cpu, 5, 0) == "two levels"  # FC 2's own copy (its last call came from FC 3)
    assert _text(cpu, 5, 22) == "two levels"  # passed on twice: OB 1 -> FC 3 -> FC 2 -> FC 1
    assert _text(cpu, 5, 44) == "two levels"  # from a DB: the pointer reaches it directly


def test_a_string_passed_on_through_p_param_pointers_is_read_in_place() -> None:
    """The callee reads the DB pointer STEP 7 gives it (``L P##s``) and follows it: the
    current length it finds is that of the string the FC was given."""
    source = (
        """
DATA_BLOCK DB 5
  STRUCT
   n1 : INT;
   n2 : INT;
  END_STRUCT;
BEGIN
END_DATA_BLOCK
"""
        + _length_fc(1, "n1")
        + """
FUNCTION FC 2 : VOID
VAR_INPUT
  s : STRING [254];
END_VAR
BEGIN
      CALL FC 1 (s := #s);
END_FUNCTION

ORGANIZATION_BLOCK OB 1
VAR_TEMP
  text : STRING [10];
END_VAR
BEGIN
      CALL FC 2 (s := 'seven!!');
      L     DB5.n1;
      T     DB5.n2;
      CALL FC 2 (s := 'abc');
END_ORGANIZATION_BLOCK
"""
    )
    cpu = _run(source)
    assert _read(cpu, "DB5.DBW2") == 7
    assert _read(cpu, "DB5.DBW0") == 3


def _length_fc(number: int, target: str) -> str:
    """An FC that stores the current length of its STRING input, found through ``L P##s``."""
    return f"""
FUNCTION FC {number} : VOID
VAR_INPUT
  s : STRING [254];
END_VAR
VAR_TEMP
  db : WORD;
  at : DWORD;
END_VAR
BEGIN
      L     P##s;
      LAR1  ;
      L     W [AR1,P#0.0];
      T     #db;
      L     D [AR1,P#2.0];
      T     #at;
      OPN   DB [#db];
      L     #at;
      LAR1  ;
      L     B [AR1,P#1.0];
      T     DB5.{target};
END_FUNCTION
"""


def _broken_fb(lines: int) -> str:
    body = "\n".join(f"      L     #x;\n      FOO   {k} bar;" for k in range(lines))
    return f"""
FUNCTION_BLOCK FB 5
VAR_INPUT
  x : INT;
END_VAR
BEGIN
NETWORK
TITLE = many mistakes
{body}
END_FUNCTION_BLOCK
"""


def test_too_many_syntax_errors_never_compile_an_fb_as_ob1() -> None:
    complete = """
FUNCTION FC 7 : VOID
BEGIN
      SET   ;
      =     M 0.0;
END_FUNCTION
"""
    result = compile_sources(
        [SourceFile("prog.awl", complete + _broken_fb(MAX_SYNTAX_ERRORS + 10))]
    )
    codes = [d.code for d in result.diagnostics]
    assert codes.count("STL104") == 1
    assert codes.count("STL101") == MAX_SYNTAX_ERRORS
    assert not result.ok
    blocks = set(result.program.blocks)
    assert (BlockKind.OB, 1) not in blocks  # nothing the user did not write
    assert (BlockKind.FC, 7) in blocks  # the block closed before the limit is kept
    assert all(d.span is None or d.span.file == "prog.awl" for d in result.diagnostics)


def test_loose_code_before_the_limit_stays_loose_code() -> None:
    """awlsim's form (code outside any block) is still OB 1, limit or not."""
    loose = "      SET   ;\n      =     M 0.0;\n"
    broken = "\n".join(f"      FOO   {k} bar;" for k in range(MAX_SYNTAX_ERRORS + 5))
    result = compile_sources([SourceFile("prog.awl", loose + broken + "\n")])
    assert "STL104" in [d.code for d in result.diagnostics]
    assert (BlockKind.OB, 1) in result.program.blocks


TIME_LIMITS = """
ORGANIZATION_BLOCK OB 1
BEGIN
      L     T#-24D_20H_31M_23S_648MS;
      T     MD 0;
      L     T#24D_20H_31M_23S_647MS;
      T     MD 4;
      L     TIME#-24d20h31m23s648ms;
      T     MD 8;
END_ORGANIZATION_BLOCK
"""


def test_the_least_and_greatest_time_are_in_range() -> None:
    cpu = _run(TIME_LIMITS)
    assert _read(cpu, "MD0") == 0x80000000  # -2^31 ms
    assert _read(cpu, "MD4") == 0x7FFFFFFF
    assert _read(cpu, "MD8") == 0x80000000


def test_one_millisecond_beyond_time_is_out_of_range() -> None:
    source = """
ORGANIZATION_BLOCK OB 1
BEGIN
      L     T#-24D_20H_31M_23S_649MS;
      T     MD 0;
      L     T#24D_20H_31M_23S_648MS;
      T     MD 4;
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("prog.awl", source)])
    found = [(d.code, d.span.line if d.span else 0) for d in result.diagnostics]
    assert found == [("STL214", 4), ("STL214", 6)]
    assert all(d.severity is Severity.ERROR for d in result.diagnostics)


MULTI_INSTANCE = """
FUNCTION_BLOCK FB 2
VAR
  v : INT;
END_VAR
BEGIN
      L     DBNO;
      T     MW 10;
      L     DINO;
      T     MW 12;
      TAR2  ;
      T     MD 14;
      L     7;
      T     #v;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 1
VAR
  guard : WORD;
  inner : FB 2;
END_VAR
BEGIN
      L     DBNO;
      T     MW 20;
      L     DINO;
      T     MW 22;
      OPN   DB 9;
      CALL  #inner;
      L     DBNO;
      T     MW 24;
      L     DINO;
      T     MW 26;
      TAR2  ;
      T     MD 28;
END_FUNCTION_BLOCK

DATA_BLOCK DB 1
  FB 1
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 9
  STRUCT
   x : INT;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
      OPN   DB 9;
      CALL  FB 1, DB 1;
END_ORGANIZATION_BLOCK
"""


def test_a_multi_instance_starts_with_the_callers_instance_db_in_both_registers() -> None:
    """STEP 7's FB call swaps DB and DI ("Programming with STEP 7", 15.8): inside the
    multi-instance DB = the caller's DI (DB 1, which holds it), DI = DB 1, AR2 = the caller's
    AR2 plus the instance offset (P#DBX 2.0); after the call both registers hold DB 1 and AR2
    is the caller's again."""
    cpu = _run(MULTI_INSTANCE)
    assert (_read(cpu, "MW20"), _read(cpu, "MW22")) == (0, 1)  # CALL FB 1, DB 1: DB = OB 1's DI
    assert (_read(cpu, "MW10"), _read(cpu, "MW12")) == (1, 1)  # inside the multi-instance
    assert _read(cpu, "MD14") == 0x84000010  # P#DBX 2.0
    assert (_read(cpu, "MW24"), _read(cpu, "MW26")) == (1, 1)  # after it, in FB 1
    assert _read(cpu, "MD28") == 0x84000000  # FB 1's own instance base again
    assert _read(cpu, "DB1.DBW2") == 7  # the multi-instance wrote its own static
