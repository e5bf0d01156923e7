"""The S7-1200/1500 elementary types in SCL (and their refusal in STL and under the classic
profiles): SINT USINT UINT UDINT LINT ULINT LREAL LWORD LTIME: declarations, typed constants,
ranges, implicit and explicit conversions, result types, the lowering and runs on the CPU."""

from __future__ import annotations

import struct

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.profile import Profile
from nasaq.ir import BlockKind
from nasaq.lang.scl.typecheck.types import Elementary, IntConst, assignable, wider
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.lang.stl.format import format_block

TYPES = ["SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT", "LREAL", "LWORD", "LTIME"]
CONSTANTS = {
    "SINT": "SINT#-128",
    "USINT": "USINT#255",
    "UINT": "UINT#16#FFFF",
    "UDINT": "UDINT#4000000000",
    "LINT": "LINT#-5",
    "ULINT": "ULINT#18446744073709551615",
    "LREAL": "LREAL#1.5",
    "LWORD": "LW#16#FFFF_0000_FFFF_0000",
    "LTIME": "LTIME#1D2H",
}


def _codes(text: str, profile: str, name: str = "t.scl") -> list[tuple[str, int, int, str]]:
    result = compile_sources([SourceFile(name, text)], profile=profile)
    return [
        (d.code, d.span.line, d.span.column, d.message)
        for d in result.diagnostics
        if d.span is not None and d.severity == "error"
    ]


def _program(text: str, profile: str = "S7-1500") -> Cpu:
    result = compile_sources([SourceFile("prog.scl", text)], profile=profile)
    errors = [f"{d.code} {d.span} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, errors
    cpu = Cpu(result.program, profile=Profile(profile), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def _db(cpu: Cpu, number: int, start: int, size: int) -> bytes:
    data = cpu.db_bytes(number)
    assert data is not None
    return bytes(data[start : start + size])


# ---- the classic profiles refuse them, at the declaration ---------------------------------------


@pytest.mark.parametrize("profile", ["S7-300", "S7-400"])
@pytest.mark.parametrize("type_name", TYPES)
def test_each_type_needs_the_s7_1500_profile_in_scl(profile: str, type_name: str) -> None:
    text = f"FUNCTION F1 : VOID\nVAR_INPUT\n  x : {type_name};\nEND_VAR\nBEGIN\n  ;\nEND_FUNCTION\n"
    message = f"{type_name} needs the S7-1200/1500 profile; this program is compiled for {profile}."
    assert _codes(text, profile) == [("SCL500", 3, 7, message)]
    assert _codes(text, "S7-1500") == []


@pytest.mark.parametrize("type_name", TYPES)
def test_each_typed_constant_needs_the_s7_1500_profile(type_name: str) -> None:
    constant = CONSTANTS[type_name]
    text = (
        f"FUNCTION F1 : VOID\nVAR_TEMP\n  x : DINT;\nEND_VAR\n"
        f"BEGIN\n  x := {constant};\nEND_FUNCTION\n"
    )
    found = _codes(text, "S7-300")
    assert [(code, line, column) for code, line, column, _ in found] == [("SCL500", 6, 8)]
    assert found[0][3].startswith(f"{constant} needs the S7-1200/1500 profile")


@pytest.mark.parametrize("type_name", TYPES)
def test_each_type_needs_the_s7_1500_profile_in_stl(type_name: str) -> None:
    text = (
        "FUNCTION FC 5 : VOID\nVAR_TEMP\n"
        f"  x : {type_name};\nEND_VAR\nBEGIN\nNETWORK\nTITLE =\n      NOP 0;\nEND_FUNCTION\n"
    )
    assert [c[:3] for c in _codes(text, "S7-300", "t.awl")] == [("STL500", 3, 7)]
    assert _codes(text, "S7-1500", "t.awl") == []


@pytest.mark.parametrize(
    ("declaration", "what"),
    [("ARRAY[*] OF INT", "ARRAY[*]"), ("VARIANT", "VARIANT"), ("DB_ANY", "DB_ANY")],
)
def test_array_star_variant_and_db_any_need_the_s7_1500_profile(
    declaration: str, what: str
) -> None:
    text = (
        f"FUNCTION F1 : VOID\nVAR_IN_OUT\n  p : {declaration};\nEND_VAR\nBEGIN\n  ;\nEND_FUNCTION\n"
    )
    classic = _codes(text, "S7-300")
    assert [c[0] for c in classic] == ["SCL500"]
    assert classic[0][3].startswith(f"{what} needs the S7-1200/1500 profile")
    assert _codes(text, "S7-1500") == []  # they run there (test_scl_variant.py)


# ---- ranges, conversions, result types -----------------------------------------------------------


@pytest.mark.parametrize(
    "constant",
    [
        "SINT#200",
        "SINT#-129",
        "USINT#256",
        "UINT#70000",
        "UDINT#4294967296",
        "LINT#9223372036854775808",
        "ULINT#18446744073709551616",
        "LW#16#1_0000_0000_0000_0000",
        "LREAL#1e400",
        "LTIME#106752D",
    ],
)
def test_typed_constants_out_of_range_are_scl218(constant: str) -> None:
    text = (
        f"FUNCTION F1 : VOID\nVAR_TEMP\n  x : LREAL;\nEND_VAR\n"
        f"BEGIN\n  x := {constant};\nEND_FUNCTION\n"
    )
    assert [c[:3] for c in _codes(text, "S7-1500")] == [("SCL218", 6, 8)]


@pytest.mark.parametrize(
    ("source", "target"),
    [
        ("SINT", "INT"),
        ("INT", "LINT"),
        ("USINT", "UINT"),
        ("UINT", "UDINT"),
        ("UDINT", "ULINT"),
        ("USINT", "INT"),
        ("UINT", "DINT"),
        ("UDINT", "LINT"),
        ("DINT", "LREAL"),
        ("UDINT", "REAL"),
        ("REAL", "LREAL"),
        ("DWORD", "LWORD"),
        ("TIME", "LTIME"),
    ],
)
def test_tia_widening_is_implicit(source: str, target: str) -> None:
    assert assignable(Elementary(source), Elementary(target)).code is None


@pytest.mark.parametrize(
    ("source", "target"),
    [
        ("LREAL", "REAL"),
        ("UINT", "INT"),
        ("INT", "UINT"),
        ("DINT", "UDINT"),
        ("LINT", "DINT"),
        ("LINT", "REAL"),
        ("ULINT", "LINT"),
        ("LWORD", "DWORD"),
        ("SINT", "USINT"),
    ],
)
def test_narrowing_needs_the_named_conversion(source: str, target: str) -> None:
    verdict = assignable(Elementary(source), Elementary(target))
    assert verdict.code == "SCL213"
    assert verdict.params["function"] == f"{source}_TO_{target}"


def test_integer_constants_must_fit_the_s7_1500_types() -> None:
    assert assignable(IntConst(65535), Elementary("UINT")).code is None
    assert assignable(IntConst(-1), Elementary("UINT")).code == "SCL218"
    assert assignable(IntConst(-128), Elementary("SINT")).code is None
    assert assignable(IntConst(2**40), Elementary("LINT")).code is None
    assert assignable(IntConst(2**40), Elementary("LREAL")).code is None


@pytest.mark.parametrize(
    ("left", "right", "common"),
    [
        ("INT", "UINT", "DINT"),
        ("DINT", "UDINT", "LINT"),
        ("LINT", "ULINT", "LREAL"),
        ("SINT", "USINT", "INT"),
        ("REAL", "LINT", "LREAL"),
        ("SINT", "SINT", "SINT"),
        ("BYTE", "LWORD", "LWORD"),
    ],
)
def test_operations_meet_in_the_smallest_common_type(left: str, right: str, common: str) -> None:
    assert wider(left, right) == common


def test_an_untyped_constant_takes_the_other_operands_type() -> None:
    text = (
        "FUNCTION F1 : VOID\nVAR_TEMP\n  u : UINT;\n  s : SINT;\nEND_VAR\nBEGIN\n"
        "  u := u + 2;\n  s := s - 1;\n  u := u + 70000;\nEND_FUNCTION\n"
    )
    # u + 70000 does not fit a UINT: the sum is a DINT, which TIA stores into the UINT
    # implicitly (IEC check off) keeping its low bits, with the warning SCL705
    assert _codes(text, "S7-1500") == []
    found = compile_sources([SourceFile("t.scl", text)], profile="S7-1500").diagnostics
    assert [(d.code, d.span.line) for d in found if d.span] == [("SCL705", 9)]


# ---- lowering ------------------------------------------------------------------------------------


def _stl(text: str) -> str:
    result = compile_sources([SourceFile("t.scl", text)], profile="S7-1500")
    assert not [d for d in result.diagnostics if d.severity == "error"], result.diagnostics
    return "\n".join(format_block(block) for _file, block in result.generated)


def test_64_bit_operations_call_the_hidden_library() -> None:
    stl = _stl(
        "FUNCTION F1 : VOID\nVAR_TEMP\n  a : LREAL;\n  b : LREAL;\n  x : BOOL;\nEND_VAR\nBEGIN\n"
        "  a := a + b;\n  x := a > 2.5;\nEND_FUNCTION\n"
    )
    assert 'CALL "ADD_LREAL"' in stl
    assert 'CALL "GT_LREAL"' in stl
    result = compile_sources(
        [
            SourceFile(
                "t.scl",
                "FUNCTION F1 : VOID\nVAR_TEMP\n  a : LREAL;\nEND_VAR\nBEGIN\n"
                "  a := a * 2.0;\nEND_FUNCTION\n",
            )
        ],
        profile="S7-1500",
    )
    library = [b for b in result.program.blocks.values() if b.kind is BlockKind.FC]
    assert {b.name for b in library} >= {"MUL_LREAL"}


def test_sint_is_sign_extended_where_it_meets_a_wider_type() -> None:
    stl = _stl(
        "FUNCTION F1 : VOID\nVAR_TEMP\n  s : SINT;\n  i : INT;\nEND_VAR\nBEGIN\n"
        "  i := s;\nEND_FUNCTION\n"
    )
    assert "SLD   24" in stl
    assert "SSD   24" in stl


# ---- runs on the CPU -----------------------------------------------------------------------------

_RUN = """
DATA_BLOCK DB1
STRUCT
  s : SINT;
  u : USINT;
  w : UINT;
  d : UDINT;
  l : LINT;
  q : ULINT;
  r : LREAL;
  lw : LWORD;
  t : LTIME;
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB1
BEGIN
  DB1.s := SINT#127;
  DB1.s := DB1.s + 1;
  DB1.u := USINT#250;
  DB1.u := DB1.u + 10;
  DB1.w := UINT#65535;
  DB1.d := DB1.w * UDINT#70000;
  DB1.l := LINT#-2;
  DB1.l := DB1.l * LINT#4611686018427387904;
  DB1.q := ULINT#18446744073709551615;
  DB1.r := LREAL#0.1 + 0.2;
  DB1.lw := LW#16#0123_4567_89AB_CDEF;
  DB1.t := LTIME#1S + LTIME#1NS;
END_ORGANIZATION_BLOCK
"""


def test_values_are_stored_with_their_width_big_endian_and_wrapped() -> None:
    cpu = _program(_RUN)
    # layout: s 0, u 1, w 2, d 4, l 8, q 16, r 24, lw 32, t 40
    assert _db(cpu, 1, 0, 1) == b"\x80"  # 127 + 1 wraps to -128
    assert _db(cpu, 1, 1, 1) == bytes([4])  # 250 + 10 wraps to 4
    assert _db(cpu, 1, 2, 2) == b"\xff\xff"
    assert int.from_bytes(_db(cpu, 1, 4, 4), "big") == (65535 * 70000) % 2**32
    assert (
        int.from_bytes(_db(cpu, 1, 8, 8), "big", signed=True)
        == (-2 * 2**62 + 2**63) % 2**64 - 2**63
    )
    assert _db(cpu, 1, 16, 8) == b"\xff" * 8
    assert struct.unpack(">d", _db(cpu, 1, 24, 8))[0] == 0.1 + 0.2
    assert _db(cpu, 1, 32, 8).hex() == "0123456789abcdef"
    assert int.from_bytes(_db(cpu, 1, 40, 8), "big", signed=True) == 1_000_000_001


def test_a_classic_profile_does_not_run_them() -> None:
    result = compile_sources([SourceFile("prog.scl", _RUN)], profile="S7-300")
    codes = {d.code for d in result.diagnostics if d.severity == "error"}
    assert codes == {"SCL500"}


def test_the_monitor_shows_the_narrow_types_with_their_sign() -> None:
    from nasaq.monitor.values import decode

    assert decode("SINT", 0xFF) == -1
    assert decode("USINT", 0xFF) == 255
    assert decode("UINT", 0xFFFF) == 65535
    assert decode("UDINT", 0xFFFFFFFF) == 4294967295
