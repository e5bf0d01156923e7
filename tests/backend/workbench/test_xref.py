"""Cross-references and the assignment list (``nasaq.workbench.xref``) on the course programs
and the examples: STL, SCL and LAD/FBD sources, alone and mixed in one project."""

from __future__ import annotations

from pathlib import Path

import pytest

from nasaq.workbench.names import language_of
from nasaq.workbench.xref import XrefError, assignment_list, references

ROOT = Path(__file__).resolve().parents[3]
MOTOR = ROOT / "examples" / "projects" / "motor-start-stop"
TANK = ROOT / "examples" / "projects" / "tank-level"
LAD = ROOT / "examples" / "lad"
COURSE = ROOT / "tests" / "scenarios" / "course"

# A LAD function called from STL, beside the tank example's STL and SCL blocks: one project of
# three languages sharing one symbol table.
LAD_FC = """\
FUNCTION FC 20 : VOID
TITLE = Pump lamp
BEGIN
NETWORK
TITLE = Lamp follows the pump
RUNG
  Contact("Pump")
  Coil(M 20.0)
END_RUNG
NETWORK
TITLE = Alarm latch
RUNG
  Contact("High level alarm")
  SetCoil(M 20.1)
END_RUNG
END_FUNCTION
"""
CALLS_LAD = """\
ORGANIZATION_BLOCK OB 35
BEGIN
NETWORK
TITLE = the LAD function
      CALL FC 20 ;
      A     "Pump";
      R     M 20.1;
END_ORGANIZATION_BLOCK
"""


def files(folder: Path, *names: str) -> list[tuple[str, str]]:
    chosen = names or tuple(
        path.name
        for path in sorted(folder.iterdir())
        if path.is_file() and language_of(path.name) is not None  # the project's files
    )
    return [(name, (folder / name).read_text("utf-8")) for name in chosen]


def mixed() -> list[tuple[str, str]]:
    return [*files(TANK), ("PumpLamp.lad", LAD_FC), ("OB35.awl", CALLS_LAD)]


def places(target: str, sources: list[tuple[str, str]]) -> list[tuple[object, ...]]:
    found = references(sources, target)
    return [
        (e.file, e.block, e.network, e.line, e.access, e.address, e.exact) for e in found.entries
    ]


def test_every_use_of_a_symbol_with_block_network_and_line() -> None:
    found = references(files(MOTOR), '"Motor"')
    assert (found.address, found.symbol) == ("Q 4.0", "Motor")
    assert [
        (e.block, e.block_name, e.network, e.line, e.column, e.access, e.instruction)
        for e in found.entries
    ] == [
        ("OB 1", "Main", 1, 15, 7, "read", "O"),
        ("OB 1", "Main", 1, 19, 7, "write", "="),
        ("OB 1", "Main", 2, 22, 7, "read", "A"),
    ]
    # The address and the symbol are one operand, however the target is written.
    assert places("Q4.0", files(MOTOR)) == places("motor", files(MOTOR))


def test_uses_in_stl_scl_and_lad_of_one_project() -> None:
    sources = mixed()
    assert places('"Pump"', sources) == [
        (
            "OB1.awl",
            "OB 1",
            2,
            21,
            "write",
            "Q 4.0",
            True,
        ),  # FB parameter OUT := "Pump"
        ("OB35.awl", "OB 35", 1, 6, "read", "Q 4.0", True),
        ("PumpLamp.lad", "FC 20", 1, 4, "read", "Q 4.0", True),  # on its NETWORK line
    ]
    lad = references(sources, '"Pump"').entries[2]
    assert (lad.language, lad.element) == ("lad", "e1")
    # Set and reset of one bit from LAD and STL.
    assert [(e.file, e.access) for e in references(sources, "M 20.1").entries] == [
        ("OB35.awl", "reset"),
        ("PumpLamp.lad", "set"),
    ]
    # A block: called from STL; a DB member: read as a parameter of the SCL FB's call.
    assert places("FC 20", sources) == [("OB35.awl", "OB 35", 1, 5, "call", "FC 20", True)]
    assert [
        (e.file, e.line, e.access, e.address)
        for e in references(sources, '"TankSettings".HighLevel').entries
    ] == [("OB1.awl", 21, "read", "DB1.DBD 4")]
    called = references(sources, '"LevelControl"').entries
    assert [(e.file, e.line, e.access) for e in called] == [("OB1.awl", 21, "call")]


def test_scl_uses_have_the_statement_line_and_no_network() -> None:
    sources = [
        *files(TANK),
        (
            "Use.scl",
            (
                'FUNCTION FC 30 : VOID\nBEGIN\n  "Pump" := "Auto";\n'
                '  IF "Auto" THEN\n    "Level" := 1.0;\n  END_IF;\nEND_FUNCTION\n'
            ),
        ),
    ]
    assert [
        (e.file, e.network, e.line, e.access)
        for e in references(sources, '"Auto"').entries
        if e.file == "Use.scl"
    ] == [("Use.scl", None, 3, "read"), ("Use.scl", None, 4, "read")]


def test_overlapping_accesses_are_listed_after_the_exact_ones() -> None:
    sources = files(COURSE / "ar_000", "e23_load_transfer_byte.awl")
    assert [
        (e.line, e.access, e.address, e.exact) for e in references(sources, "QB 3").entries
    ] == [(10, "write", "QB 3", True)]
    # A bit of that byte: the byte transfer writes it too (STEP 7's overlapping access).
    assert [(e.line, e.address, e.exact) for e in references(sources, "Q 3.5").entries] == [
        (10, "QB 3", False)
    ]


def test_timer_accesses_in_a_course_program() -> None:
    sources = files(COURSE / "ar_000", "e10_sd_on_delay.awl")
    assert [(e.line, e.access, e.instruction) for e in references(sources, "T 1").entries] == [
        (13, "start", "SD"),
        (15, "reset", "R"),
        (16, "read", "A"),
        (20, "read", "L"),
        (22, "read", "LC"),
    ]
    listed = assignment_list(sources)
    assert [(t.kind, t.number, t.accesses) for t in listed.timers] == [
        ("T", 1, ["start", "reset", "read"])
    ]
    assert [(b.area, b.byte, b.widths) for b in listed.bytes if b.area == "M"] == [
        ("M", 10, ["word"]),
        ("M", 12, ["word"]),
    ]


def test_assignment_list_of_the_motor_example() -> None:
    listed = assignment_list(files(MOTOR))
    assert [
        (b.area, b.byte, [(x.bit, x.read, x.write, x.symbol) for x in b.bits]) for b in listed.bytes
    ] == [
        (
            "I",
            0,
            [
                (0, True, False, "Start"),
                (1, True, False, "Stop"),
                (2, True, False, "Overload"),
            ],
        ),
        (
            "Q",
            4,
            [
                (0, True, True, "Motor"),
                (1, False, True, "Running lamp"),
                (2, False, True, "Fault lamp"),
            ],
        ),
    ]
    assert listed.timers == []


def test_assignment_list_of_a_lad_example() -> None:
    listed = assignment_list(
        files(LAD, "vi_e06_motor_start_stop.lad", "vi_e06_motor_start_stop.sdf")
    )
    assert [(b.area, b.byte, [(x.bit, x.read, x.write) for x in b.bits]) for b in listed.bytes] == [
        ("I", 0, [(0, True, False), (1, True, False)]),
        ("Q", 0, [(0, True, True)]),
    ]


@pytest.mark.parametrize(
    ("target", "code"),
    [
        ('"Nothing"', "XRF701"),
        ("", "XRF701"),
        ('"Motor".Speed', "XRF702"),
        ('"TankSettings".Nope', "XRF703"),
    ],
)
def test_unknown_targets_are_refused_with_a_code(target: str, code: str) -> None:
    with pytest.raises(XrefError) as raised:
        references(mixed() if "Tank" in target else files(MOTOR), target)
    assert raised.value.code == code
