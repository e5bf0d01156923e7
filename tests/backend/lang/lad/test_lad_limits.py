"""LAD/FBD nesting past ``nasaq.lang.limits.MAX_LAD_NESTING``: LAD150 in the reader, LAD151 when
STL is lifted to LAD; never a RecursionError."""

from __future__ import annotations

from lad_from_stl_build import lift

from nasaq.lang.lad.convert import convert
from nasaq.lang.lad.from_stl import NotConvertible
from nasaq.lang.limits import MAX_LAD_NESTING
from nasaq.lang.stl import SourceFile, compile_sources


def parallels(depth: int) -> str:
    return (
        "PARALLEL BRANCH " * depth
        + "Contact(I 0.0)"
        + " END_BRANCH BRANCH Contact(I 0.1) END_BRANCH END_PARALLEL" * depth
    )


def logic_pins(depth: int) -> str:
    return "Box(AND, IN1 := RUNG " * depth + "Contact(I 0.0)" + " END_RUNG)" * depth


def source(rung: str) -> str:
    return (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG\n"
        + rung
        + " Coil(Q 0.0)\nEND_RUNG\nNETWORK\nRUNG\nContact(I 1.0) Coil(Q 1.0)\nEND_RUNG\n"
        "END_ORGANIZATION_BLOCK\n"
    )


def test_parallels_past_the_limit_get_one_lad150_and_the_next_network_is_read() -> None:
    for rung in (parallels(MAX_LAD_NESTING + 1), parallels(5000), logic_pins(3000)):
        result = compile_sources([SourceFile("a.lad", source(rung))])
        found = [(d.code, d.span.line if d.span else None) for d in result.diagnostics]
        assert found == [("LAD150", 5)]
        for target in ("stl", "lad", "fbd"):
            converted = convert("a.lad", source(rung), target)  # type: ignore[arg-type]
            assert [d.code for d in converted.diagnostics] == ["LAD150"]
        stl = convert("a.lad", source(rung), "stl").text
        assert "Q 1.0" in stl


def test_parallels_within_the_limit_are_read() -> None:
    converted = convert("a.lad", source(parallels(MAX_LAD_NESTING - 2)), "fbd")
    assert not any(d.code == "LAD150" for d in converted.diagnostics)


def test_stl_brackets_past_the_limit_stay_stl_with_lad151() -> None:
    body = "A(\n" * 3000 + "A I 0.0\n" + ")\n" * 3000 + "= Q 4.0\n"
    lifted = lift(body)
    assert isinstance(lifted, NotConvertible)
    assert lifted.code == "LAD151"
    text = f"FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nTITLE =\n{body}END_FUNCTION\n"
    converted = convert("a.awl", text, "lad")
    assert converted.kept == 1
