"""Every reason a network stays STL, one construct each: the code, and the instruction and
line the message names."""

from __future__ import annotations

import pytest
from lad_from_stl_build import lift

from nasaq.diagnostics.catalogue import entry
from nasaq.lang.lad.from_stl import REASONS, NotConvertible, lift_block, lift_network
from nasaq.lang.lad.model import LadBlock, Network
from nasaq.lang.lad.to_stl import block_to_stl

# code -> (network body, the instruction the reason names)
CASES: dict[str, tuple[str, str]] = {
    "LAD303": ("A I 0.0\nL MW 10\n= Q 4.0", "L MW 10"),
    "LAD304": ("A I 0.0\nM001: A I 0.1\n= Q 4.0", "M001"),
    "LAD305": ("A I 0.0\nX I 0.1\n= Q 4.0", "X I 0.1"),
    "LAD306": ("A I 0.0\n= Q 4.0\nA I 0.1\n= Q 4.1", "A I 0.1"),
    "LAD307": ("A I 0.0\n= M 0.0\nS M 0.0", "S M 0.0"),
    "LAD308": ("T MW 10", "T MW 10"),
    "LAD309": ("= Q 4.0", "= Q 4.0"),
    "LAD310": ("A I 0.0\nCLR\n= Q 4.0", "CLR"),
    "LAD311": ("A I 0.0\n)\n= Q 4.0", ")"),
    "LAD312": ("A I 0.0\nA I 0.1", "A I 0.1"),
    "LAD313": ("A(\nA I 0.0\n= Q 4.0\n)\n= Q 4.1", "= Q 4.0"),
    "LAD314": ("A I 0.0\nJC M001\n= Q 4.0", "= Q 4.0"),
    "LAD315": ("A I 0.0\n= Q 4.0\nJU M001", "JU M001"),
    "LAD316": ("A I [MD 2]\n= Q 4.0", "A I [MD 2]"),
    "LAD317": ("A I 0.0\n= 5", "= 5"),
    "LAD318": ("L MW 0\nL MW 2\nL MW 4\n+I\nT MW 6", "L MW 0"),
    "LAD319": ("A I 0.0\nAN(\nO I 0.1\nO I 0.2\n)\n= Q 4.0", "AN("),
    "LAD320": ("A I 0.0\nO\nA I 0.1\nNOT\n= Q 4.0", "NOT"),
    "LAD321": ("A I 0.0\nCALL FC 1", "CALL FC 1"),
    "LAD322": ("L MW 0\nL MW 2\n+I", "+I"),
    "LAD323": ("A I 0.0\nSD T 1", "SD T 1"),
    "LAD324": ("A(\n)\n= Q 4.0", ")"),
    "LAD325": ("A I 0.0\nJNB _001\nL MW 0\nT MW 2\nA I 0.1\n_001: A BR\n= Q 4.0", "A I 0.1"),
    "LAD326": ("OPN DB 5\nL DBW 0\nT MW 0", "OPN DB 5"),
    "LAD327": ("A I 0.0\nA(\nA I 0.1\nNOT\n)\n= Q 4.0", "A("),
}


def test_every_reason_is_catalogued_and_tested() -> None:
    # LAD151 (brackets past nasaq.lang.limits) is tested in test_lad_limits.py
    assert set(CASES) | {"LAD302", "LAD151"} == set(REASONS)
    for code in REASONS:
        found = entry(code)
        assert found.key.startswith("lad_lift_")
        assert "{instruction}" in found.template
        assert "{line}" in found.template


@pytest.mark.parametrize("code", sorted(CASES))
def test_the_reason_names_the_instruction(code: str) -> None:
    body, instruction = CASES[code]
    lifted = lift(body)
    assert isinstance(lifted, NotConvertible), lifted
    assert (lifted.code, lifted.instruction) == (code, instruction), lifted.message
    line = 4 + next(i for i, text in enumerate(body.split("\n")) if instruction in text)
    assert lifted.line == line
    assert instruction in lifted.message
    assert f"Line {line}" in lifted.message
    assert lifted.diagnostic("x.awl", 1).span is not None


def test_a_not_inside_a_nested_parallel_after_a_check_stays_stl() -> None:
    """``A x; A( O y; O( A z; NOT ) )`` is x AND (y OR NOT z); the rung x, (y | z NOT) would
    invert x AND z instead (a branch starts from the flow into the parallel), so LAD327."""
    lifted = lift("A I 0.0\nA(\nO I 0.1\nO(\nA I 0.2\nNOT\n)\n)\n= Q 4.0")
    assert isinstance(lifted, NotConvertible), lifted
    assert (lifted.code, lifted.instruction) == ("LAD327", "A(")


def test_a_syntax_error_in_the_network_is_a_reason() -> None:
    """LAD302: the parser skipped part of the network; it is shown as it was typed."""
    result = lift_block(
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nA I 0.0 +\n= Q 4.0\nEND_ORGANIZATION_BLOCK\n",
        "bad.awl",
    )
    [network] = result.blocks[0].networks
    assert isinstance(network, NotConvertible)
    assert network.code == "LAD302"
    codes = [d.code for d in result.diagnostics]
    assert codes[0].startswith("STL1")
    assert codes[-1] == "LAD302"


def test_an_empty_item_list_is_an_empty_rung() -> None:
    assert lift_network([]) == Network()


def test_an_empty_network_lifts_to_an_empty_rung_and_a_lone_label_keeps_its_label() -> None:
    """As STEP 7 shows them: an empty STL network is an empty LAD network, and ``M001: NOP 0``
    (a jump target) an empty network with the label, which lowers back to the same line. A
    ``NOP 0`` without a label is an instruction with no LAD element."""
    text = (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nTITLE = nothing yet\nNETWORK\nM001: NOP 0\n"
        "NETWORK\nNOP 0\nEND_ORGANIZATION_BLOCK\n"
    )
    empty, labelled, nop = lift_block(text, "empty.awl").blocks[0].networks
    assert empty == Network(title="nothing yet")
    assert labelled == Network(label="M001")
    assert isinstance(nop, NotConvertible)
    assert nop.code == "LAD310"
    lowered, problems = block_to_stl(LadBlock(kind="OB", name="OB 1", networks=[empty, labelled]))
    assert problems == []
    assert lowered.split("BEGIN\n")[1] == (
        "NETWORK\nTITLE = nothing yet\nNETWORK\nTITLE =\nM001: NOP   0\nEND_ORGANIZATION_BLOCK\n"
    )


def test_a_jump_from_another_network_into_a_box_label_keeps_the_network_stl() -> None:
    """The EN/ENO label ``_001`` of network 1 is reached from network 2: a jump into the
    middle (LAD304), though network 1 alone is a MOVE box."""
    code = "A I 0.0\nJNB _001\nL MW 0\nT MW 2\n_001: NOP 0\nNETWORK\nA I 0.1\nJC _001\n"
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n" + code + "END_ORGANIZATION_BLOCK\n"
    first, second = lift_block(text, "jump.awl").blocks[0].networks
    assert isinstance(first, NotConvertible)
    assert first.code == "LAD304"
    assert not isinstance(second, NotConvertible)


def test_a_network_that_goes_on_combining_an_open_chain_stays_stl() -> None:
    """Network 1 ends its chain without an output (/FC stays 1), so ``A M 1.4`` in network 2
    ANDs with it on the CPU; a rung from the rail would show another program (LAD309)."""
    code = "A(\nO I 0.0\nO M 0.1\n)\nNETWORK\nA M 1.4\n= Q 1.2\nNETWORK\nA I 0.1\n= Q 1.3\n"
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n" + code + "END_ORGANIZATION_BLOCK\n"
    first, second, third = lift_block(text, "chain.awl").blocks[0].networks
    assert isinstance(first, NotConvertible)
    assert first.code == "LAD312"
    assert isinstance(second, NotConvertible)
    assert (second.code, second.instruction, second.line) == ("LAD309", "A M 1.4", 9)
    assert not isinstance(third, NotConvertible)  # network 2's assignment ended the chain
