"""The bodies of TIA's text instructions (``nasaq.cpu.text_instructions``): VAL_STRG and STRG_VAL
as the S7-1200 System Manual describes them (SIZE, PREC, FORMAT, P), the number conversions with
WSTRING and the character conversions between the two widths. Each body runs on references to
buffers laid out as the CPU passes them; the self-checking programs of
``tests/selfcheck/strings`` run the same through compiled SCL."""

from __future__ import annotations

import struct

import pytest

from nasaq.cpu import Cpu
from nasaq.cpu.iec_library import BODIES, REACHING
from nasaq.cpu.pointers import ANY_TYPES, any_pointer
from nasaq.cpu.profile import Profile
from nasaq.ir import Area
from nasaq.lang.iec_library import BY_NUMBER, FUNCTIONS
from nasaq.lang.stl import SourceFile, compile_sources

Ref = tuple[bytearray, int, int]


def text(value: str, room: int = 30, width: int = 1) -> Ref:
    buf = bytearray(2 * width + width * room)
    buf[:width] = room.to_bytes(width, "big")
    buf[width : 2 * width] = len(value).to_bytes(width, "big")
    for i, char in enumerate(value):
        start = 2 * width + width * i
        buf[start : start + width] = ord(char).to_bytes(width, "big")
    return (buf, 0, 0)


def read_text(ref: Ref, width: int = 1) -> str:
    buf = ref[0]
    length = int.from_bytes(buf[width : 2 * width], "big")
    data = buf[2 * width : 2 * width + width * length]
    return "".join(
        chr(int.from_bytes(data[i : i + width], "big")) for i in range(0, len(data), width)
    )


def number(fmt: str, value: float) -> Ref:
    return (bytearray(struct.pack(fmt, value)), 0, 0)


def val_strg(
    kind: str,
    value: bytes,
    size: int,
    prec: int,
    form: int,
    p: int,
    out: str = "",
    room: int = 20,
) -> tuple[int, str]:
    target = text(out, room)
    refs = [
        (bytearray(value), 0, 0),
        (bytearray([size]), 0, 0),
        (bytearray([prec]), 0, 0),
        (bytearray(form.to_bytes(2, "big")), 0, 0),
        (bytearray(p.to_bytes(2, "big")), 0, 0),
        target,
    ]
    done = BODIES[f"VAL_STRG_{kind}"](refs)
    return done, read_text(target)


REAL_PI = struct.pack(">f", 3.14159)
INT_M1234 = struct.pack(">h", -1234)


@pytest.mark.parametrize(
    ("kind", "value", "size", "prec", "form", "p", "out", "expected"),
    [
        (
            "REAL",
            REAL_PI,
            8,
            2,
            0,
            1,
            "",
            "    3.14",
        ),  # right-justified, rounded to PREC
        ("REAL", REAL_PI, 8, 2, 1, 1, "", "    3,14"),  # bit 0: a comma
        ("REAL", REAL_PI, 8, 2, 4, 1, "", "   +3.14"),  # bit 2: "+" too
        ("REAL", REAL_PI, 10, 3, 2, 1, "", "  3.142E+0"),  # bit 1: exponential
        (
            "INT",
            INT_M1234,
            7,
            1,
            0,
            1,
            "",
            " -123.4",
        ),  # an integer's PREC places the point
        ("INT", INT_M1234, 0, 0, 0, 1, "", "-1234"),  # SIZE 0: as long as the text
        # SIZE characters from P replaced: the manual's "Pump pressure = 120 psi"
        (
            "UINT",
            struct.pack(">H", 120),
            3,
            0,
            0,
            17,
            "Pump pressure =     psi",
            "Pump pressure = 120 psi",
        ),
        (
            "INT",
            struct.pack(">h", 5),
            2,
            0,
            0,
            6,
            "ab",
            "ab    5",
        ),  # P past the end: blanks
        ("LREAL", struct.pack(">d", -0.5), 6, 3, 0, 1, "", "-0.500"),
    ],
)
def test_val_strg_writes_the_field_the_manual_describes(
    kind: str,
    value: bytes,
    size: int,
    prec: int,
    form: int,
    p: int,
    out: str,
    expected: str,
) -> None:
    done, written = val_strg(kind, value, size, prec, form, p, out, room=30)
    assert (done, written) == (1, expected)


@pytest.mark.parametrize(
    ("size", "prec", "form", "p", "room", "why"),
    [
        (3, 2, 0, 1, 20, "the text is longer than SIZE"),
        (8, 2, 8, 1, 20, "FORMAT 8 and above are illegal"),
        (8, 8, 0, 1, 20, "a REAL keeps at most 7 fractional digits"),
        (8, 2, 0, 0, 20, "P = 0 names no character"),
        (8, 2, 0, 1, 6, "the field is past OUT's maximum length"),
    ],
)
def test_val_strg_errors_leave_out_unchanged_with_eno_false(
    size: int, prec: int, form: int, p: int, room: int, why: str
) -> None:
    assert val_strg("REAL", REAL_PI, size, prec, form, p, "keep", room) == (
        0,
        "keep",
    ), why


def test_val_strg_of_a_nan_is_an_error() -> None:
    assert val_strg("REAL", struct.pack(">I", 0x7FC00000), 8, 2, 0, 1, "x") == (0, "x")


def strg_val(kind: str, value: str, form: int, p: int, fmt: str) -> tuple[int, float, int]:
    out = (bytearray(struct.calcsize(fmt)), 0, 0)
    position = (bytearray(p.to_bytes(2, "big")), 0, 0)
    done = BODIES[f"STRG_VAL_{kind}"](
        [text(value), (bytearray(form.to_bytes(2, "big")), 0, 0), out, position]
    )
    result: float = struct.unpack(fmt, out[0])[0]
    return done, result, int.from_bytes(position[0], "big")


@pytest.mark.parametrize(
    ("kind", "value", "form", "p", "fmt", "expected"),
    [
        (
            "REAL",
            "T= 1,234.5 C",
            0,
            3,
            ">f",
            (1, 1234.5, 11),
        ),  # "," a thousands separator
        ("REAL", "1.234,5", 1, 1, ">f", (1, 1234.5, 8)),  # FORMAT 1: "," the point
        ("REAL", "-2.5E2x", 2, 1, ">f", (1, -250.0, 7)),  # FORMAT 2: an exponent
        ("DINT", "  17 items", 0, 1, ">i", (1, 17, 5)),  # leading blanks skipped
        ("INT", "2.5", 0, 1, ">h", (1, 2, 4)),  # rounded, ties to even
        ("INT", "40000", 0, 1, ">h", (0, 0, 1)),  # out of range: nothing written
        ("USINT", "abc", 0, 1, ">B", (0, 0, 1)),  # no number at P
        ("REAL", "5", 4, 1, ">f", (0, 0.0, 1)),  # FORMAT 4 and above are illegal
        ("REAL", "12", 0, 3, ">f", (0, 0.0, 3)),  # P past the text
    ],
)
def test_strg_val_reads_from_p_and_moves_p_past_the_number(
    kind: str, value: str, form: int, p: int, fmt: str, expected: tuple[int, float, int]
) -> None:
    assert strg_val(kind, value, form, p, fmt) == expected


def test_number_conversions_with_wstring_write_the_string_versions_text() -> None:
    for name, value in (("INT", number(">h", -42)), ("REAL", number(">f", 2.5))):
        narrow, wide = text("", 20), text("", 20, width=2)
        assert BODIES[f"{name}_TO_STRING"]([value, narrow]) == 1
        assert BODIES[f"{name}_TO_WSTRING"]([value, wide]) == 1
        assert read_text(wide, 2) == read_text(narrow)
        assert "42" in read_text(wide, 2) or "2.5" in read_text(wide, 2)
    nan = (bytearray(struct.pack(">I", 0x7FC00000)), 0, 0)
    kept = text("old", 20, width=2)
    assert BODIES["REAL_TO_WSTRING"]([nan, kept]) == 0
    assert read_text(kept, 2) == "old"


def test_wstring_to_number_reads_as_the_string_version() -> None:
    result = (bytearray(2), 0, 0)
    assert BODIES["WSTRING_TO_INT"]([text(" 1234", width=2), result]) == 1
    assert int.from_bytes(result[0], "big", signed=True) == 1234
    assert BODIES["WSTRING_TO_INT"]([text("12\u20ac", width=2), result]) == 0  # not Latin-1


def test_character_conversions_between_the_widths() -> None:
    code = (bytearray(2), 0, 0)
    assert BODIES["WSTRING_TO_WCHAR"]([text("\u20acx", width=2), code]) == 1
    assert int.from_bytes(code[0], "big") == 0x20AC
    assert BODIES["WSTRING_TO_WCHAR"]([text("", width=2), code]) == 0  # no first character
    narrow = text("", 5)
    assert BODIES["WCHAR_TO_STRING"]([(bytearray(b"\x20\xac"), 0, 0), narrow]) == 0
    assert read_text(narrow) == "?"
    wide = text("", 5, width=2)
    assert BODIES["CHAR_TO_WSTRING"]([(bytearray(b"A"), 0, 0), wide]) == 1
    assert read_text(wide, 2) == "A"


def test_every_new_library_fc_has_a_number_of_its_own_and_a_body() -> None:
    names = [f"VAL_STRG_{k}" for k in ("INT", "REAL", "LREAL")] + ["STRG_VAL_UDINT"]
    names += ["INT_TO_WSTRING", "WSTRING_TO_ULINT", "WCHAR_TO_WSTRING"]
    for name in names:
        function = FUNCTIONS[name]
        assert BY_NUMBER[function.number] is function
        assert name in BODIES
    assert len(BY_NUMBER) == len(FUNCTIONS)


# ---- ATH, HTA, Strg_TO_Chars, Chars_TO_Strg: bodies that follow an ANY -------------------------


class _Memory:
    """The parts of the CPU's memory the bodies use: DBs and the M area."""

    def __init__(self) -> None:
        self.dbs = {5: bytearray(16)}
        self.m = bytearray(16)

    def area(self, area: Area) -> bytearray:
        assert area is Area.M
        return self.m


def any_to(area: Area, byte: int, type_name: str, count: int, db: int = 0) -> Ref:
    return (
        bytearray(any_pointer(area, byte, 0, ANY_TYPES[type_name], count, db)),
        0,
        0,
    )


def word(value: int = 0) -> Ref:
    return (bytearray(value.to_bytes(2, "big", signed=value < 0)), 0, 0)


def test_ath_reads_and_writes_through_the_any() -> None:
    memory, frame = _Memory(), bytearray(b"0aF7x1")
    ret = word()
    refs = [
        any_to(Area.V, 0, "CHAR", 6),
        word(6),
        any_to(Area.DB, 2, "BYTE", 4, db=5),
        ret,
    ]
    assert REACHING["ATH"](refs, memory, frame) == 0  # (ENO = 0: 'x' is no digit)
    assert memory.dbs[5][2:6] == bytes([0x0A, 0xF7, 0x01, 0x00])
    assert ret[0] == b"\x00\x07"
    refs[1] = word(3)
    assert REACHING["ATH"](refs, memory, frame) == 1  # an odd count: the last low digit 0
    assert memory.dbs[5][2:4] == bytes([0x0A, 0xF0])


@pytest.mark.parametrize(
    ("source", "n", "target", "code"),
    [
        (any_to(Area.DB, 0, "CHAR", 4, db=9), 4, any_to(Area.M, 0, "BYTE", 2), 0x8101),
        (any_to(Area.M, 0, "CHAR", 4), 4, any_to(Area.DB, 0, "BYTE", 2, db=9), 0x8301),
        (
            any_to(Area.M, 14, "CHAR", 4),
            4,
            any_to(Area.M, 0, "BYTE", 2),
            0x8101,
        ),  # past M
        (any_to(Area.M, 0, "CHAR", 4), 5, any_to(Area.M, 8, "BYTE", 4), 0x8182),
        (any_to(Area.M, 0, "CHAR", 4), -1, any_to(Area.M, 8, "BYTE", 4), 0x8182),
        (any_to(Area.M, 0, "CHAR", 4), 4, any_to(Area.M, 8, "BYTE", 1), 0x8382),
    ],
)
def test_ath_errors_leave_out_unchanged(source: Ref, n: int, target: Ref, code: int) -> None:
    memory = _Memory()
    memory.m[0:4] = b"1234"
    memory.m[8:12] = b"\xee" * 4
    ret = word()
    assert REACHING["ATH"]([source, word(n), target, ret], memory, bytearray()) == 0
    assert int.from_bytes(ret[0], "big") == code
    assert memory.m[8:12] == b"\xee" * 4


def test_hta_writes_two_capital_digits_a_byte() -> None:
    memory, ret = _Memory(), word()
    memory.dbs[5][0:3] = bytes([0x0B, 0xE4, 0x7F])
    refs = [
        any_to(Area.DB, 0, "BYTE", 3, db=5),
        word(3),
        any_to(Area.M, 2, "CHAR", 6),
        ret,
    ]
    assert REACHING["HTA"](refs, memory, bytearray()) == 1
    assert memory.m[2:8] == b"0BE47F"
    assert ret[0] == b"\x00\x00"
    refs[2] = any_to(Area.M, 2, "CHAR", 5)  # one character short
    assert REACHING["HTA"](refs, memory, bytearray()) == 0
    assert int.from_bytes(ret[0], "big") == 0x8382


def test_strg_to_chars_limits() -> None:
    memory, cnt = _Memory(), word()
    array = any_to(Area.M, 0, "CHAR", 4)
    body = REACHING["STRG_TO_CHARS"]
    assert body([text("abcdef"), (bytearray(b"\0\0\0\x01"), 0, 0), cnt, array], memory, b"") == 0
    assert memory.m[0:4] == b"\0abc"  # what fits, ENO = 0
    assert cnt[0] == b"\x00\x03"
    outside = (bytearray(b"\0\0\0\x04"), 0, 0)  # pChars past the last element
    assert body([text("z"), outside, cnt, array], memory, bytearray()) == 0
    assert cnt[0] == b"\x00\x00"
    assert memory.m[0:4] == b"\0abc"
    words = any_to(Area.M, 0, "WORD", 2)  # an ARRAY OF WORD is no array of characters
    assert body([text("z"), (bytearray(4), 0, 0), cnt, words], memory, bytearray()) == 0
    assert memory.m[0] == 0


def test_chars_to_strg_limits() -> None:
    memory, frame = _Memory(), bytearray(b"PLC\x00S7")
    chars = any_to(Area.V, 0, "CHAR", 6)
    body = REACHING["CHARS_TO_STRG"]
    target = text("old", 10)
    start, count = (bytearray(b"\0\0\0\x04"), 0, 0), word(5)
    assert body([chars, start, count, target], memory, frame) == 0  # past the end: to the end
    assert read_text(target) == "S7"
    assert body([chars, (bytearray(4), 0, 0), word(0), target], memory, frame) == 0
    assert read_text(target) == "PLC"  # a NUL ends the text, ENO = 0
    negative = (bytearray(b"\xff\xff\xff\xff"), 0, 0)
    assert body([chars, negative, word(0), target], memory, frame) == 0
    assert read_text(target) == "PLC"  # unchanged
    short = text("", 2)
    assert body([chars, (bytearray(4), 0, 0), word(3), short], memory, frame) == 0
    assert read_text(short) == "PL"


def test_the_wide_forms_move_utf16_code_units() -> None:
    memory, frame, cnt = _Memory(), bytearray(8), word()
    wide = any_to(Area.V, 0, "BYTE", 8)  # ARRAY[0..3] OF WCHAR: its bytes
    body = REACHING["STRG_TO_CHARS_WSTRING"]
    assert (
        body(
            [text("\u20acz", 5, width=2), (bytearray(4), 0, 0), cnt, wide],
            memory,
            frame,
        )
        == 1
    )
    assert frame[0:4] == b"\x20\xac\x00z"
    assert cnt[0] == b"\x00\x02"
    target = text("", 5, width=2)
    assert (
        REACHING["CHARS_TO_STRG_WSTRING"](
            [wide, (bytearray(4), 0, 0), word(2), target], memory, frame
        )
        == 1
    )
    assert read_text(target, 2) == "\u20acz"


def test_the_character_instructions_are_library_fcs_with_their_numbers() -> None:
    numbers = {name: FUNCTIONS[name].number for name in REACHING}
    assert numbers["ATH"] == 94
    assert numbers["HTA"] == 95
    assert all(BY_NUMBER[n] is FUNCTIONS[name] for name, n in numbers.items())
    assert not REACHING.keys() & BODIES.keys()


def test_ath_and_hta_are_called_from_stl_with_pointer_constants() -> None:
    source = """ORGANIZATION_BLOCK OB 1
BEGIN
      L     '12AB';
      T     MD 0;
      CALL "ATH" (IN := P#M 0.0 BYTE 4, N := 4, RET_VAL := MW 10, OUT := P#M 20.0 BYTE 2);
      CALL "HTA" (IN := P#M 20.0 BYTE 2, N := 2, RET_VAL := MW 12, OUT := P#M 30.0 BYTE 4);
END_ORGANIZATION_BLOCK
"""
    result = compile_sources([SourceFile("ob1.awl", source)])  # STEP 7 classic: FC 94, FC 95
    assert [d.code for d in result.diagnostics] == []
    cpu = Cpu(result.program, profile=Profile("S7-300"), cycle_ms=10)
    cpu.start()
    cpu.run(1)
    m = cpu.area_bytes("M")
    assert m[20:22] == b"\x12\xab"
    assert m[30:34] == b"12AB"
    assert m[10:14] == bytes(4)  # both RET_VAL 16#0000
