"""File names a project may hold, and the language each suffix means."""

import pytest

from nasaq.workbench.archive import folder_name
from nasaq.workbench.names import SOURCE_SUFFIXES, is_valid_name, language_of


def test_the_suffixes_are_what_the_compiler_reads() -> None:
    assert SOURCE_SUFFIXES == (
        ".awl",
        ".stl",
        ".scl",
        ".db",
        ".udt",
        ".lad",
        ".fbd",
        ".graph",
        ".sdf",
        ".asc",
        ".seq",
        ".csv",
    )
    assert [language_of(f"x{s.upper()}") for s in SOURCE_SUFFIXES] == [
        "stl",
        "stl",
        "scl",
        "scl",
        "scl",
        "lad",
        "fbd",
        "graph",
        "symbols",
        "symbols",
        "symbols",
        "symbols",
    ]
    assert language_of("x.txt") is None
    assert language_of("awl") is None


@pytest.mark.parametrize(
    ("name", "valid"),
    [
        ("OB1.awl", True),
        ("Motor control.scl", True),
        ("موتور.scl", True),
        ("v1.2.awl", True),
        ("Latch.lad", True),
        ("Gates.FBD", True),
        ("Recipe data.db", True),  # TIA Portal's DB and PLC data type exports (SCL)
        ("MotorData.udt", True),
        ("nul.awl", False),
        ("COM1.backup.awl", False),
        ("OB1.awl.", False),
        ("tab\t.awl", False),
        ("x.awl" + "\x00", False),
        ("x" * 124 + ".awl", True),
        ("x" * 125 + ".awl", False),
    ],
)
def test_valid_names(name: str, valid: bool) -> None:
    assert is_valid_name(name) is valid


def test_an_export_folder_is_never_a_relative_path() -> None:
    assert folder_name("Tank") == "Tank"
    assert folder_name("..") == "project"
    assert folder_name(". .") == "project"
