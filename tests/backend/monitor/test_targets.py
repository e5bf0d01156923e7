"""Watch and modify targets: what users type resolves to typed addresses of a compiled program, and
values written through them read back as the same typed values."""

from __future__ import annotations

import pytest

from nasaq.cpu import Cpu
from nasaq.ir import Area, BlockKind, Direct, Program, Width
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.symbols import SymbolTable, read_symbol_table
from nasaq.monitor.targets import (
    Target,
    TargetError,
    encode,
    is_input,
    is_output,
    read,
    resolve,
    write,
)

PLANT = """
TYPE UDT 7
  STRUCT
    a : INT;
    b : REAL;
  END_STRUCT;
END_TYPE

DATA_BLOCK DB 1
  STRUCT
    level : INT := -5;
    flag : BOOL;
    s : STRUCT
      x : BOOL;
      y : DINT;
    END_STRUCT;
    arr : ARRAY[1..4] OF INT;
    bits : ARRAY[0..9] OF BOOL;
    m : ARRAY[1..2, 1..3] OF REAL;
    name : STRING[8];
    u : UDT 7;
    ua : ARRAY[1..2] OF UDT 7;
    c : CHAR;
    t : TIME;
    delay : S5TIME;
    day : DATE;
    tod : TIME_OF_DAY;
    when : DATE_AND_TIME;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

DATA_BLOCK DB 2
  STRUCT
    recs : ARRAY[1..2] OF STRUCT
      a : INT;
      b : BOOL;
    END_STRUCT;
    tm : TIMER;
  END_STRUCT;
BEGIN
END_DATA_BLOCK

FUNCTION_BLOCK FB 3
VAR
  count : INT;
  done : BOOL;
END_VAR
BEGIN
  L #count;
  + 1;
  T #count;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB 2
VAR_INPUT
  start : BOOL;
END_VAR
VAR_IN_OUT
  buf : ARRAY[1..4] OF INT;
  io : INT;
END_VAR
VAR
  count : INT;
  inner : FB 3;
  t1 : "TON";
END_VAR
VAR_TEMP
  tmp : INT;
END_VAR
BEGIN
  CALL #inner;
  CALL #t1 (IN := #start, PT := T#2S);
END_FUNCTION_BLOCK

DATA_BLOCK DB 5
FB 2
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
  CALL FB 2, DB 5 (start := M 0.0, buf := "Tank".arr, io := MW 30);
  A M 0.0;
  L S5T#2S;
  SD T 3;
  A M 0.1;
  CU C 2;
END_ORGANIZATION_BLOCK
"""

# FB 20 holds an array and FB 3 as a multi-instance; DB 21 is its instance DB.
EXTRA_SCL = """
FUNCTION_BLOCK FB 20
VAR
  values : ARRAY[1..3] OF INT;
  sub : FB 3;
  ok : BOOL;
END_VAR
BEGIN
  values[1] := values[2];
  sub();
END_FUNCTION_BLOCK

DATA_BLOCK DB 21 FB 20
BEGIN
END_DATA_BLOCK
"""

SYMBOLS = """"Motor","Q 4.0","BOOL","motor contactor"
"Speed","MW 10","INT","set speed"
"Level","MD 20","REAL",""
"Tank","DB 1","DB 1",""
"Drive","FB 2","FB 2",""
"Drive 1","DB 5","FB 2",""
"Raw in","PEW 256","WORD",""
"Delay","T 3","TIMER",""
"Parts","Z 2","COUNTER",""
"TON","SFB 4","SFB 4",""
"Start","E 0.1","BOOL",""
"""


@pytest.fixture(scope="module")
def program() -> Program:
    sources = [
        SourceFile("plant.awl", PLANT),
        SourceFile("symbols.sdf", SYMBOLS),
        SourceFile("extra.scl", EXTRA_SCL),
    ]
    result = compile_sources(sources)
    assert result.ok, [item.message for item in result.diagnostics]
    return result.program


@pytest.fixture(scope="module")
def symbol_types() -> dict[str, str]:
    table = SymbolTable()
    assert read_symbol_table("symbols.sdf", SYMBOLS, table) == []
    return {symbol.name: symbol.type for symbol in table.symbols.values()}


@pytest.fixture
def cpu(program: Program) -> Cpu:
    cpu = Cpu(program)
    cpu.start()
    return cpu


def db(number: int, width: Width, byte: int, bit: int = 0) -> Direct:
    return Direct(Area.DB, width, byte, bit, db=number)


# -- resolving ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "canonical", "type_", "direct"),
    [
        ("I0.0", "I0.0", "BOOL", Direct(Area.I, Width.BIT, 0, 0)),
        ("i 1.7", "I1.7", "BOOL", Direct(Area.I, Width.BIT, 1, 7)),
        ("E 0.1", "I0.1", "BOOL", Direct(Area.I, Width.BIT, 0, 1)),
        ("IB2", "IB2", "BYTE", Direct(Area.I, Width.BYTE, 2)),
        ("QW 4", "QW4", "WORD", Direct(Area.Q, Width.WORD, 4)),
        ("A 4.1", "Q4.1", "BOOL", Direct(Area.Q, Width.BIT, 4, 1)),
        ("mw10", "MW10", "WORD", Direct(Area.M, Width.WORD, 10)),
        ("MD 20", "MD20", "DWORD", Direct(Area.M, Width.DWORD, 20)),
        ("DB1.DBX2.1", "DB1.DBX2.1", "BOOL", db(1, Width.BIT, 2, 1)),
        ("db1.dbw 2", "DB1.DBW2", "WORD", db(1, Width.WORD, 2)),
        ("DB 1 . DBD 4", "DB1.DBD4", "DWORD", db(1, Width.DWORD, 4)),
        ("DB5.DBB0", "DB5.DBB0", "BYTE", db(5, Width.BYTE, 0)),
        ("PIW256", "PIW256", "WORD", Direct(Area.PI, Width.WORD, 256)),
        ("pew 256", "PIW256", "WORD", Direct(Area.PI, Width.WORD, 256)),
        ("PIB 3", "PIB3", "BYTE", Direct(Area.PI, Width.BYTE, 3)),
        ("PID 8", "PID8", "DWORD", Direct(Area.PI, Width.DWORD, 8)),
        ("PQB 3", "PQB3", "BYTE", Direct(Area.PQ, Width.BYTE, 3)),
        ("PAW 260", "PQW260", "WORD", Direct(Area.PQ, Width.WORD, 260)),
        ("PQD 8", "PQD8", "DWORD", Direct(Area.PQ, Width.DWORD, 8)),
    ],
)
def test_addresses_resolve_to_their_width_type(
    program: Program, text: str, canonical: str, type_: str, direct: Direct
) -> None:
    assert resolve(text, program) == Target(canonical, type_, direct)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("T1", Target("T1", "TIMER", None, timer=1)),
        ("t 3", Target("T3", "TIMER", None, timer=3)),
        ("C2", Target("C2", "COUNTER", None, counter=2)),
        ("Z 2", Target("C2", "COUNTER", None, counter=2)),
        ('"Delay"', Target('"Delay"', "TIMER", None, timer=3)),
        ("Parts", Target('"Parts"', "COUNTER", None, counter=2)),
    ],
)
def test_timers_and_counters(program: Program, text: str, expected: Target) -> None:
    assert resolve(text, program) == expected


@pytest.mark.parametrize(
    ("text", "canonical", "type_", "direct"),
    [
        ('"Motor"', '"Motor"', "BOOL", Direct(Area.Q, Width.BIT, 4, 0)),
        ("Motor", '"Motor"', "BOOL", Direct(Area.Q, Width.BIT, 4, 0)),
        ('  "motor" ', '"Motor"', "BOOL", Direct(Area.Q, Width.BIT, 4, 0)),
        ("Start", '"Start"', "BOOL", Direct(Area.I, Width.BIT, 0, 1)),
        ('"Speed"', '"Speed"', "WORD", Direct(Area.M, Width.WORD, 10)),
        ('"Level"', '"Level"', "DWORD", Direct(Area.M, Width.DWORD, 20)),
        ("Raw in", '"Raw in"', "WORD", Direct(Area.PI, Width.WORD, 256)),
        ('"Raw in"', '"Raw in"', "WORD", Direct(Area.PI, Width.WORD, 256)),
    ],
)
def test_symbols_without_types_resolve_by_width(
    program: Program, text: str, canonical: str, type_: str, direct: Direct
) -> None:
    assert resolve(text, program, {}) == Target(canonical, type_, direct)


def test_the_program_carries_its_symbol_types(
    program: Program, symbol_types: dict[str, str]
) -> None:
    assert program.symbol_types == symbol_types
    assert resolve('"Speed"', program).type == "INT"


def test_symbol_table_types_type_symbols(program: Program, symbol_types: dict[str, str]) -> None:
    assert resolve('"Speed"', program, symbol_types).type == "INT"
    assert resolve("level", program, symbol_types).type == "REAL"
    assert resolve('"Raw in"', program, symbol_types).type == "WORD"
    # A type that does not fit the address's width is ignored.
    assert resolve('"Speed"', program, {"Speed": "REAL"}).type == "WORD"


@pytest.mark.parametrize(
    ("text", "canonical", "type_", "direct"),
    [
        ("DB1.level", "DB1.level", "INT", db(1, Width.WORD, 0)),
        ("db1 . LEVEL", "DB1.level", "INT", db(1, Width.WORD, 0)),
        ('"Tank".level', '"Tank".level', "INT", db(1, Width.WORD, 0)),
        ("Tank.level", '"Tank".level', "INT", db(1, Width.WORD, 0)),
        ("DB1.flag", "DB1.flag", "BOOL", db(1, Width.BIT, 2, 0)),
        ("DB1.s.x", "DB1.s.x", "BOOL", db(1, Width.BIT, 4, 0)),
        ("DB1.s.y", "DB1.s.y", "DINT", db(1, Width.DWORD, 6)),
        ("DB1.arr[1]", "DB1.arr[1]", "INT", db(1, Width.WORD, 10)),
        ("DB1.arr [4]", "DB1.arr[4]", "INT", db(1, Width.WORD, 16)),
        ("DB1.bits[9]", "DB1.bits[9]", "BOOL", db(1, Width.BIT, 19, 1)),
        ("DB1.m[1,1]", "DB1.m[1,1]", "REAL", db(1, Width.DWORD, 20)),
        ("DB1.m[2, 3]", "DB1.m[2,3]", "REAL", db(1, Width.DWORD, 40)),
        ("DB1.u.b", "DB1.u.b", "REAL", db(1, Width.DWORD, 56)),
        ("DB1.ua[2].b", "DB1.ua[2].b", "REAL", db(1, Width.DWORD, 68)),
        ("DB1.c", "DB1.c", "CHAR", db(1, Width.BYTE, 72)),
        ("DB1.t", "DB1.t", "TIME", db(1, Width.DWORD, 74)),
        ("DB1.delay", "DB1.delay", "S5TIME", db(1, Width.WORD, 78)),
        ("DB1.day", "DB1.day", "DATE", db(1, Width.WORD, 80)),
        ("DB1.tod", "DB1.tod", "TIME_OF_DAY", db(1, Width.DWORD, 82)),
        ('"Tank".DBW2', '"Tank".DBW2', "WORD", db(1, Width.WORD, 2)),
        ('"Tank" . dbx 2.0', '"Tank".DBX2.0', "BOOL", db(1, Width.BIT, 2, 0)),
        ("DB2.tm", "DB2.tm", "WORD", db(2, Width.WORD, 8)),  # a TIMER variable: its number
    ],
)
def test_db_variables(
    program: Program, text: str, canonical: str, type_: str, direct: Direct
) -> None:
    assert resolve(text, program) == Target(canonical, type_, direct)


@pytest.mark.parametrize(
    ("text", "canonical", "type_", "direct"),
    [
        ("DB5.start", "DB5.start", "BOOL", db(5, Width.BIT, 0, 0)),
        ("DB5.io", "DB5.io", "INT", db(5, Width.WORD, 8)),
        ("DB5.count", "DB5.count", "INT", db(5, Width.WORD, 10)),
        ("DB5.inner.count", "DB5.inner.count", "INT", db(5, Width.WORD, 12)),
        ("DB5.inner.done", "DB5.inner.done", "BOOL", db(5, Width.BIT, 14, 0)),
        ("DB5.t1.ET", "DB5.t1.ET", "TIME", db(5, Width.DWORD, 24)),
        ('"Drive 1".t1.q', '"Drive 1".t1.Q', "BOOL", db(5, Width.BIT, 22, 0)),
        ("DB21.values[2]", "DB21.values[2]", "INT", db(21, Width.WORD, 2)),
        ("DB21.sub.done", "DB21.sub.done", "BOOL", db(21, Width.BIT, 8, 0)),
        ("DB21.ok", "DB21.ok", "BOOL", db(21, Width.BIT, 10, 0)),
    ],
)
def test_instance_db_variables_and_multi_instances(
    program: Program, text: str, canonical: str, type_: str, direct: Direct
) -> None:
    assert resolve(text, program) == Target(canonical, type_, direct)


def test_instance_db_without_interface_uses_its_fb(program: Program) -> None:
    instance = program.get(BlockKind.DB, 5)
    assert instance is not None
    bare = Program(dict(program.blocks), dict(program.symbols))
    bare.add(type(instance)(BlockKind.DB, 5, instance_of=2, data=instance.data))
    assert resolve("DB5.inner.count", bare).direct == db(5, Width.WORD, 12)
    with pytest.raises(TargetError, match="no variable tmp"):
        resolve("DB5.tmp", bare)  # the FB's TEMP variables are no instance data


def test_inputs_and_outputs(program: Program) -> None:
    assert [is_input(resolve(text, program)) for text in ("I0.0", "PIW256", "Q0.0", "PQB3")] == [
        True,
        True,
        False,
        False,
    ]
    assert [is_output(resolve(text, program)) for text in ('"Motor"', "PQB3", "I0.0")] == [
        True,
        True,
        False,
    ]
    for text in ("MW10", "DB1.level", "T1"):
        assert not is_input(resolve(text, program))
        assert not is_output(resolve(text, program))


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("", "type an address, a symbol or a DB variable"),
        ("Motr", 'did you mean "Motor"?'),
        ("Pump", "neither an address nor a symbol"),
        ('"Pump".level', "neither an address nor a symbol"),
        ("DB9.DBW0", "DB9 is not in the downloaded program (its data blocks: DB1, DB2, DB5, DB21)"),
        ("DB9.level", "DB9 is not in the downloaded program"),
        ("DB1.DBW200", "DB1 is 94 bytes long: its last byte is DB1.DBB93"),
        ("M10.8", "the bit number must be 0 to 7"),
        ("DB1.DBX0.9", "the bit number must be 0 to 7"),
        ("MW10.1", "only bit addresses have a bit number"),
        ("M10", "needs a bit number"),
        ("DB1.levl", "DB1 has no variable levl (it has level, flag, s,"),
        ("DB1.s", "DB1.s has type STRUCT: name one of its variables, e.g. DB1.s.x (it has x, y)"),
        ("DB1.u", "DB1.u has type UDT 7: name one of its variables, e.g. DB1.u.a"),
        ("DB1.ua[1]", "DB1.ua[1] has type UDT 7: name one of its variables"),
        ("DB1.arr", "add an index, e.g. DB1.arr[1]"),
        ("DB1.arr.x", "give an index first, e.g. DB1.arr[1]"),
        ("DB1.arr[5]", "index 5 is outside 1..4"),
        ("DB1.bits[-1]", "index -1 is outside 0..9"),
        ("DB1.m[1]", "it takes 2 index(es), e.g. DB1.m[1,1]"),
        ("DB1.arr[x]", "an array index is a whole number"),
        ("DB2.recs[2].a", "watch recs[2] by address, from DB2.DBB4"),
        ("DB2.recs[1]", "the STRUCT elements of DB2.recs"),
        ("DB1.when", "DATE_AND_TIME (8 bytes), not one elementary value"),
        ("DB1.level[1]", "DB1.level has type INT, not an ARRAY"),
        ("DB1[1]", "DB1 is a data block, not an ARRAY"),
        ("DB1.level.x", "DB1.level has type INT, which has no variables"),
        ("DB1", "DB1 is a data block: name one of its variables, e.g. DB1.level"),
        ('"Tank"', '"Tank" is a data block: name one of its variables, e.g. "Tank".level'),
        ('"Drive"', '"Drive" is the block FB 2, which has no value to watch'),
        ('"Motor".x', '"Motor" is Q 4.0, not a data block'),
        ("DB5.buf", "IN_OUT parameter of type ARRAY[1..4] OF INT"),
        ("DB5.tmp", "DB5 has no variable tmp (it has start, buf, io, count, inner, t1)"),
        ("DB5.t1", "DB5.t1 has type SFB 4: name one of its variables, e.g. DB5.t1.IN"),
        ("#count", "exists only while its block runs"),
        ("LW0", "exists only while its block runs"),
        ("PI 0.0", "by byte, word or doubleword"),
        ("PIW", "neither an address nor a symbol"),
        ("DBW2", "say which data block"),
        ("MW 10 +", "not an address, a symbol or a DB variable"),
    ],
)
def test_unknown_targets(program: Program, text: str, reason: str) -> None:
    with pytest.raises(TargetError) as caught:
        resolve(text, program)
    assert caught.value.code == "MON603"
    assert caught.value.params == {"target": text.strip(), "reason": caught.value.params["reason"]}
    assert reason in str(caught.value)
    assert str(caught.value).startswith(f"{text.strip()}: ")


def test_db_length_error_matches_the_cpu(program: Program, cpu: Cpu) -> None:
    size = len(cpu.db_bytes(1) or b"")
    assert resolve(f"DB1.DBB{size - 1}", program).direct == db(1, Width.BYTE, size - 1)
    with pytest.raises(TargetError, match=f"DB1 is {size} bytes long"):
        resolve(f"DB1.DBW{size - 1}", program)


# -- reading -------------------------------------------------------------------------------------


def test_reads_are_typed(program: Program, cpu: Cpu, symbol_types: dict[str, str]) -> None:
    assert read(resolve("DB1.level", program), cpu) == -5  # the DB's initial value
    cpu.write(Direct(Area.M, Width.WORD, 10), 0xFFFD)
    assert read(resolve('"Speed"', program, symbol_types), cpu) == -3
    assert read(resolve('"Speed"', program, {}), cpu) == 0xFFFD
    cpu.write(Direct(Area.M, Width.DWORD, 20), 0x3FC00000)
    assert read(resolve('"Level"', program, symbol_types), cpu) == 1.5
    cpu.write(db(1, Width.DWORD, 6), 0xFFFFFFFF)
    assert read(resolve("DB1.s.y", program), cpu) == -1
    assert read(resolve("DB1.DBD6", program), cpu) == 0xFFFFFFFF
    cpu.write(db(1, Width.BIT, 4, 0), 1)
    assert read(resolve("DB1.s.x", program), cpu) is True
    assert read(resolve("DB1.flag", program), cpu) is False
    cpu.write(db(1, Width.BYTE, 72), 0x41)
    assert read(resolve("DB1.c", program), cpu) == "A"
    cpu.write(db(1, Width.WORD, 78), 0x2127)  # base 1 s, 127 units
    assert read(resolve("DB1.delay", program), cpu) == 127_000


@pytest.mark.parametrize(
    ("pattern", "expected"), [(0x7FC00000, "NaN"), (0x7F800000, "+Inf"), (0xFF800000, "-Inf")]
)
def test_real_specials_read_as_text(
    program: Program, cpu: Cpu, pattern: int, expected: str
) -> None:
    target = resolve("DB1.m[2,3]", program)
    cpu.write(db(1, Width.DWORD, 40), pattern)
    assert read(target, cpu) == expected


def test_timers_counters_and_instances_while_running(program: Program, cpu: Cpu) -> None:
    cpu.write(Direct(Area.M, Width.BIT, 0, 0), 1)  # starts T3 (SD 2 s) and the TON of DB5
    cpu.run(50)
    remaining = read(resolve('"Delay"', program), cpu)
    assert isinstance(remaining, int)
    assert 1400 <= remaining < 2000
    elapsed = read(resolve("DB5.t1.ET", program), cpu)
    assert isinstance(elapsed, int)
    assert 400 <= elapsed <= 500
    assert read(resolve("DB5.inner.count", program), cpu) == 50  # FB 3 counts its calls
    for _ in range(3):  # three rising edges on CU C 2
        cpu.write(Direct(Area.M, Width.BIT, 0, 1), 1)
        cpu.run(1)
        cpu.write(Direct(Area.M, Width.BIT, 0, 1), 0)
        cpu.run(1)
    assert read(resolve("Z 2", program), cpu) == 3


def test_reading_a_db_that_is_not_loaded_gives_none(program: Program) -> None:
    without_db1 = Program(
        {key: block for key, block in program.blocks.items() if key != (BlockKind.DB, 1)},
        dict(program.symbols),
    )
    cpu = Cpu(without_db1)
    target = resolve("DB1.level", program)
    assert read(target, cpu) is None
    with pytest.raises(TargetError, match="DB1 is not loaded") as caught:
        write(target, cpu, 5)
    assert caught.value.code == "MON603"


def test_addresses_beyond_the_cpu(program: Program, cpu: Cpu) -> None:
    with pytest.raises(TargetError, match="the S7-300 has MB0 to MB2047") as caught:
        read(resolve("MW 5000", program), cpu)
    assert caught.value.code == "MON603"
    with pytest.raises(TargetError, match="the S7-300 has T0 to T255"):
        read(resolve("T 300", program), cpu)
    with pytest.raises(TargetError, match="the S7-300 has C0 to C255"):
        read(resolve("C 256", program), cpu)
    with pytest.raises(TargetError, match="the S7-300 has PQB0 to PQB2047"):
        write(resolve("PQW 4096", program), cpu, 1)


# -- writing -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "value", "expected"),
    [
        ("DB1.level", -300, -300),
        ("DB1.level", "-32768", -32768),
        ("DB1.level", "16#7FFF", 32767),
        ("DB1.level", "2#1010", 10),
        ("DB1.level", 12.0, 12),
        ("DB1.s.y", "L#-100000", -100000),
        ("DB1.s.y", "-16#10", -16),
        ("DB1.DBW2", "16#FFFF", 0xFFFF),
        ("DB1.DBW2", "W#16#1234", 0x1234),
        ("DB1.DBW2", -1, 0xFFFF),
        ("DB1.DBB2", "B#16#80", 0x80),
        ("DB1.DBD6", "DW#16#DEADBEEF", 0xDEADBEEF),
        ("DB1.m[1,1]", "1.5", 1.5),
        ("DB1.m[1,1]", -2, -2.0),
        ("DB1.m[1,1]", 0.25, 0.25),
        ("DB1.m[1,1]", "1e3", 1000.0),
        ("DB1.m[1,1]", "NaN", "NaN"),
        ("DB1.m[1,1]", "-Inf", "-Inf"),
        ("DB1.bits[9]", "TRUE", True),
        ("DB1.bits[9]", "false", False),
        ("DB1.bits[9]", 1, True),
        ("DB1.bits[9]", True, True),
        ("DB1.bits[9]", "0", False),
        ("DB1.t", "T#1m30s", 90_000),
        ("DB1.t", "T#-2S", -2000),
        ("DB1.t", "T#500MS", 500),
        ("DB1.t", 2500, 2500),
        ("DB1.delay", "S5T#2S", 2000),
        ("DB1.delay", "s5t#1h", 3_600_000),
        ("DB1.delay", "T#1M", 60_000),
        ("DB1.delay", 12_345, 12_300),  # 10 ms units do not hold it: 100 ms units
        ("DB1.day", "D#1990-1-2", 1),
        ("DB1.day", 365, 365),
        ("DB1.tod", "TOD#0:0:1.5", 1500),
        ("DB1.c", "'A'", "A"),
        ("DB1.c", '"B"', "B"),
        ("DB1.c", "C", "C"),
        ("DB1.c", "7", "7"),
        ("DB1.c", 68, "D"),
        ("DB1.c", "16#45", "E"),
        ("MW10", "16#ABCD", 0xABCD),
        ("Q 4.0", "TRUE", True),
        ("PQW 256", 1234, 1234),
        ("DB5.t1.PT", "T#2S", 2000),
    ],
)
def test_written_values_read_back(
    program: Program, cpu: Cpu, text: str, value: bool | int | float | str, expected: object
) -> None:
    target = resolve(text, program)
    write(target, cpu, value)
    result = read(target, cpu)
    assert result == expected
    assert type(result) is type(expected)


def test_write_leaves_neighbouring_bits_alone(program: Program, cpu: Cpu) -> None:
    cpu.write(db(1, Width.BYTE, 19), 0b0000_0101)
    write(resolve("DB1.bits[9]", program), cpu, True)
    assert cpu.read(db(1, Width.BYTE, 19)) == 0b0000_0111


@pytest.mark.parametrize(
    ("text", "value", "pattern"),
    [
        ("DB1.delay", "S5T#2S", 0x0200),
        ("DB1.delay", "S5T#1H", 0x3360),
        ("DB1.delay", "S5T#2H46M30S", 0x3999),
        ("DB1.delay", "S5T#10S", 0x1100),
        ("DB1.m[1,1]", 1.5, 0x3FC00000),
        ("DB1.level", -1, 0xFFFF),
        ("DB1.t", "T#-1MS", 0xFFFFFFFF),
        ("DB1.c", "'a'", 0x61),
    ],
)
def test_encoded_patterns(program: Program, text: str, value: str | float, pattern: int) -> None:
    assert encode(resolve(text, program), value) == pattern


def test_encode_takes_a_type_without_an_address() -> None:
    """The debugger encodes values for locals of a held block by their declared type."""
    assert encode(Target("#t", "TOD", None), "TOD#1:0:0") == 3_600_000
    assert encode(Target("#n", "INT", None), "-2") == 0xFFFE


@pytest.mark.parametrize(
    ("text", "value", "reason"),
    [
        ("DB1.level", 40000, "40000 does not fit type INT: -32768 to 32767"),
        ("DB1.level", "-40000", "-40000 does not fit type INT"),
        ("DB1.level", "1.5", "1.5 is not a whole number; type INT holds -32768 to 32767"),
        ("DB1.level", "ten", "'ten' is not a value of type INT (e.g. -5)"),
        ("DB1.level", "T#2S", "T#2S is of type TIME, not INT"),
        ("DB1.level", "16#XYZ", "16#XYZ: not a base-16 number"),
        ("DB1.level", None, "a value of type INT is needed, e.g. -5"),
        ("DB1.DBB2", 256, "does not fit type BYTE: -128 to 255"),
        ("DB1.DBD6", 2**32, "does not fit type DWORD"),
        ("DB1.bits[9]", 2, "2 is not a BOOL: write TRUE or FALSE (1 or 0)"),
        ("DB1.bits[9]", "yes", "is not a BOOL"),
        ("DB1.m[1,1]", "1e39", "1e39 does not fit type REAL"),
        ("DB1.m[1,1]", True, "is not a REAL"),
        ("DB1.m[1,1]", "abc", "'abc' is not a value of type REAL"),
        ("DB1.t", "T#25D", "T#25D does not fit type TIME: T#-24D20H31M23S647MS"),
        ("DB1.t", "T#2X", "a duration is written like 1H2M3S4MS"),
        ("DB1.t", "D#1990-1-1", "is of type DATE, not TIME"),
        ("DB1.delay", "S5T#3H", "S5T#3H does not fit type S5TIME: S5T#0MS to S5T#2H46M30S"),
        ("DB1.delay", -10, "does not fit type S5TIME: S5T#0MS to S5T#2H46M30S"),
        ("DB1.day", "D#2200-1-1", "does not fit type DATE: D#1990-1-1 to D#2168-12-31"),
        ("DB1.c", "AB", "'AB' is not a value of type CHAR"),
        ("DB1.c", "€", "does not fit type CHAR: one character of code 0 to 255"),
        ("T 1", 5, "the program runs timers and counters"),
        ('"Parts"', "3", "the program runs timers and counters"),
    ],
)
def test_values_that_do_not_fit(
    program: Program, text: str, value: bool | int | float | str | None, reason: str
) -> None:
    target = resolve(text, program)
    with pytest.raises(TargetError) as caught:
        encode(target, value)
    assert caught.value.code == "MON606"
    assert caught.value.params["target"] == target.text
    assert str(caught.value) == f"{target.text}: {caught.value.params['reason']}"
    assert reason in str(caught.value)


def test_write_refuses_timers_without_touching_the_cpu(program: Program, cpu: Cpu) -> None:
    cpu.write(Direct(Area.M, Width.BIT, 0, 0), 1)
    cpu.run(10)
    before = read(resolve("T3", program), cpu)
    with pytest.raises(TargetError) as caught:
        write(resolve("T3", program), cpu, 0)
    assert caught.value.code == "MON606"
    assert read(resolve("T3", program), cpu) == before
