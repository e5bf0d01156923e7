"""A block far over S7-Graph's 256 steps is refused before it is read, with the checker's own
limit diagnostics; a block just over the limit is read and checked as usual; the other blocks
of the file compile either way."""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.compile import lower_file
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.graph.text_limits import FAR_OVER, refuse_oversized


def chain(fb: int, steps: int, end: bool = True) -> str:
    lines = [f"FUNCTION_BLOCK FB {fb}", "BEGIN", "SEQUENCER Chain"]
    for k in range(1, steps + 1):
        lines += [
            f"{'INITIAL_STEP' if k == 1 else 'STEP'} Step{k} ({k})",
            "ACTIONS",
            f"  N M {k % 100}.{k % 8};",
            "END_ACTIONS",
            "END_STEP",
            f"TRANSITION Tr{k} ({k}) FROM Step{k} "
            + ("JUMP Step1" if k == steps else f"TO Step{k + 1}"),
            f"CONDITION Contact(I 0.{k % 8}) END_CONDITION",
            "END_TRANSITION",
        ]
    lines += ["END_SEQUENCER"] + (["END_FUNCTION_BLOCK"] if end else [])
    return "\n".join(lines) + "\n"


def shown(diagnostics: list[Diagnostic]) -> list[tuple[str, int | None, str | None, str]]:
    return [
        (d.code, d.span.line if d.span else None, d.span.element if d.span else None, d.message)
        for d in diagnostics
        if d.code in ("GRA208", "GRA209")
    ]


def test_a_block_far_over_the_limit_gets_the_checkers_diagnostics_without_being_read() -> None:
    text = chain(1, 3) + chain(2, FAR_OVER + 500) + chain(3, 4)
    kept, refused = refuse_oversized("big.graph", text)
    # The same diagnostics the full parse and check give, on the same lines.
    full = parse_graph(text, "big.graph")
    assert shown(refused) == shown(check_block(full, 1))
    assert [d.code for d in refused] == ["GRA208", "GRA209"]
    assert refused[0].span is not None
    assert refused[0].span.element == "S257"
    assert "1524 steps" in refused[0].message
    # The block's text is gone, its lines kept: the other blocks stay where they were.
    assert kept.count("\n") == text.count("\n")
    assert "Step600" not in kept
    after = parse_graph(kept, "big.graph")
    assert [block.name for block in after.blocks] == ["FB 1", "FB 3"]
    assert after.places[1]["BLOCK"] == full.places[2]["BLOCK"]


def test_the_compiler_refuses_the_huge_block_and_compiles_the_others() -> None:
    text = chain(1, 3) + chain(2, FAR_OVER + 1) + chain(3, 4)
    lowered = lower_file("big.graph", text)
    errors = [d for d in lowered.diagnostics if d.severity == "error"]
    assert [d.code for d in errors] == ["GRA208", "GRA209"]
    assert "FUNCTION_BLOCK FB 1" in lowered.stl
    assert "FUNCTION_BLOCK FB 3" in lowered.stl
    assert "FUNCTION_BLOCK FB 2" not in lowered.stl


def test_a_huge_block_without_its_end_is_refused_up_to_the_end_of_the_file() -> None:
    text = chain(1, 3) + chain(2, FAR_OVER + 1, end=False)
    lowered = lower_file("big.graph", text)
    assert [d.code for d in lowered.diagnostics if d.severity == "error"] == ["GRA208", "GRA209"]
    assert "FUNCTION_BLOCK FB 1" in lowered.stl


def test_a_block_just_over_the_limit_is_read_and_checked_with_its_other_problems() -> None:
    text = chain(1, 300).replace("  N M 7.7;", "  N M 7.7", 1)  # a row without its ';'
    assert refuse_oversized("over.graph", text) == (text, [])
    codes = [d.code for d in lower_file("over.graph", text).diagnostics]
    assert "GRA208" in codes
    assert "GRA123" in codes  # found by reading the block
