"""Random rungs of contacts, parallels, NOT, edges and midlines survive LAD → STL → LAD."""

from __future__ import annotations

from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from lad_from_stl_build import coil, ob1, out, plain

from nasaq.lang.lad.from_stl import REASONS, NotConvertible, lift_block
from nasaq.lang.lad.model import (
    Contact,
    EdgeContact,
    Element,
    Invert,
    Midline,
    Network,
    Parallel,
    Series,
    StatusContact,
)
from nasaq.lang.lad.to_stl import block_to_stl

OPERANDS = ["I 0.0", "I 0.1", "M 1.2", '"Start"', "#run", "DB5.DBX 2.1"]

checks = st.one_of(
    st.builds(Contact, operand=st.sampled_from(OPERANDS), negated=st.booleans()),
    st.builds(
        StatusContact, bit=st.sampled_from(["OV", "BR", "==0", ">=0"]), negated=st.booleans()
    ),
)
flow_elements = st.one_of(
    st.just(Invert()),
    st.builds(EdgeContact, edge=st.sampled_from(["P", "N"]), memory=st.sampled_from(["M 9.0"])),
    st.builds(Midline, operand=st.sampled_from(["M 8.0", "M 8.1"])),
)


def series(elements: st.SearchStrategy[Element]) -> st.SearchStrategy[list[Element]]:
    """A series that starts with a check or a parallel (NOT, edges, midlines need flow)."""
    return st.tuples(elements, st.lists(st.one_of(elements, flow_elements), max_size=3)).map(
        lambda pair: [pair[0], *pair[1]]
    )


def extend(inner: st.SearchStrategy[Element]) -> st.SearchStrategy[Element]:
    branch = series(st.one_of(checks, inner)).map(lambda items: Series(elements=items))
    return st.lists(branch, min_size=2, max_size=3).map(lambda bs: Parallel(branches=bs))


elements = st.recursive(checks, extend, max_leaves=8)
rungs = series(elements).map(
    lambda items: Network(logic=Series(elements=items), outputs=[out(coil("Q 4.0"))])
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rungs)
def test_random_rungs_come_back(network: Network) -> None:
    text, problems = block_to_stl(ob1(network))
    assume(not problems)
    lifted = lift_block(text, "random.awl").blocks[0].networks[0]
    assert plain(lifted) == plain(network), text


LINES = [
    "A I 0.0",
    "AN M 1.0",
    "O I 0.1",
    "ON #x",
    "O",
    "X I 0.2",
    "A(",
    "O(",
    "AN(",
    ")",
    "NOT",
    "FP M 2.0",
    "= Q 4.0",
    "S M 0.0",
    "R M 0.0",
    "= M 3.0",
    "A M 3.0",
    "SET",
    "CLR",
    "L MW 0",
    "L 5",
    "T MW 2",
    "+I",
    ">=I",
    "SRW 2",
    "L S5T#1S",
    "SD T 1",
    "A T 1",
    "R T 1",
    "CU C 1",
    "CD C 1",
    "BLD 101",
    "L C#5",
    "S C 1",
    "JNB _001",
    "_001: A BR",
    "_001: NOP 0",
    "NOP 0",
    "JC M001",
    "JU M001",
    "M001: A I 0.3",
    "BEC",
    "BEU",
    "SAVE",
    "OPN DB 1",
    "CALL FC 1",
    "= #_lad_t0",
    "A #_lad_t0",
    "A BR",
    "AN OV",
    "A ==0",
    "A I [MD 2]",
    "TAK",
    "+ 5",
    "LC T 1",
    "L T 1",
    "A OV",
    "U E 0.0",
    "SPB M001",
    "NETWORK",
]


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(LINES), max_size=14))
def test_any_instruction_sequence_lifts_or_gives_a_reason(lines: list[str]) -> None:
    """Never an exception: every network is a model or a catalogued reason at a real line."""
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n" + "\n".join(lines)
    result = lift_block(text + "\nEND_ORGANIZATION_BLOCK\n", "fuzz.awl")
    for network in result.blocks[0].networks:
        if isinstance(network, NotConvertible):
            assert network.code in REASONS
            assert 3 <= network.line <= len(lines) + 4
        else:
            assert isinstance(network, Network)
