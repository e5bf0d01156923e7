"""The lifted rung means what the STL does on our CPU: hand-typed bit logic (AND before OR,
``O`` with and without operand, brackets, NOT, midlines) is run for every combination of four
inputs and compared with the truth value of the lifted tree."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from lad_from_stl_build import c, lift, net, par, plain, s

from nasaq.cpu import Cpu
from nasaq.headless.addresses import parse_address
from nasaq.ir import Direct
from nasaq.lang.lad.model import Contact, Element, Invert, Midline, Network, Parallel, Series
from nasaq.lang.stl import SourceFile, compile_sources

INPUTS = ["I 0.0", "I 0.1", "I 0.2", "I 0.3"]


def _direct(text: str) -> Direct:
    found = parse_address(text.replace(" ", ""))
    assert isinstance(found, Direct)
    return found


def _series(series: Series, flow: bool, values: dict[str, bool]) -> bool:
    for element in series.elements:
        flow = _element(element, flow, values)
    return flow


def _element(element: Element, flow: bool, values: dict[str, bool]) -> bool:
    if isinstance(element, Contact):
        return flow and (values[element.operand] != element.negated)
    if isinstance(element, Invert):
        return not flow
    if isinstance(element, Midline):
        values[element.operand] = flow
        return flow
    if isinstance(element, Parallel):
        return flow and any(_series(b, True, values) for b in element.branches)
    raise AssertionError(element)


def _stl_truth(code: str) -> list[bool]:
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n" + code.replace(";", "\n")
    result = compile_sources([SourceFile("hand.awl", text + "\nEND_ORGANIZATION_BLOCK\n")])
    assert not [d for d in result.diagnostics if d.severity == "error"]
    cpu = Cpu(result.program)
    cpu.start()
    truth = []
    for combination in itertools.product([0, 1], repeat=len(INPUTS)):
        for address, value in zip(INPUTS, combination, strict=True):
            cpu.set_input(_direct(address), value)
        cpu.run(1)
        truth.append(bool(cpu.read(_direct("Q 4.0"))))
    return truth


def _model_truth(network: Network) -> list[bool]:
    truth = []
    for combination in itertools.product([False, True], repeat=len(INPUTS)):
        values = dict(zip(INPUTS, combination, strict=True))
        truth.append(_series(network.logic, True, values))
    return truth


HAND_TYPED = [
    "A I 0.0; A I 0.1; O I 0.2; A I 0.3; = Q 4.0",
    "A I 0.0; A I 0.1; O; A I 0.2; A I 0.3; = Q 4.0",
    "A I 0.0; O I 0.1; A I 0.2; = Q 4.0",
    "O I 0.0; O I 0.1; AN I 0.2; = Q 4.0",
    "A I 0.0; O; A I 0.1; O I 0.2; A I 0.3; = Q 4.0",
    "A I 0.0; O; A I 0.1; O; AN I 0.2; A I 0.3; = Q 4.0",
    "A(; O I 0.0; O I 0.1; ); A(; O I 0.2; ON I 0.3; ); = Q 4.0",
    "O(; A I 0.0; A I 0.1; ); O(; A I 0.2; A I 0.3; ); = Q 4.0",
    "A I 0.0; A(; A I 0.1; O I 0.2; ); NOT; = Q 4.0",
    "AN(; O I 0.0; O I 0.1; ); A I 0.2; = Q 4.0",
    "A I 0.3; ON(; A I 0.0; A I 0.1; ); = Q 4.0",
    "A I 0.0; = M 1.0; A M 1.0; A I 0.1; = Q 4.0",
    "O I 0.0; O(; A I 0.1; A(; O I 0.2; O I 0.3; ); ); = Q 4.0",
]


@pytest.mark.parametrize("code", HAND_TYPED)
def test_the_lifted_rung_computes_what_the_cpu_computes(code: str) -> None:
    lifted = lift(code)
    assert isinstance(lifted, Network), lifted
    assert _model_truth(lifted) == _stl_truth(code)


def test_and_before_or_needs_the_bare_o() -> None:
    """``O`` without operand parks the AND group: (a AND b) OR (c AND d) ..."""
    grouped = lift("A a; A b; O; A c; A d; = Q 4.0")
    assert plain(grouped) == plain(net(par(s(c("a"), c("b")), s(c("c"), c("d"))))), grouped
    # ... while ``O c`` ORs with everything so far (the S7 status tables, as the CPU runs
    # it): ((a AND b) OR c) AND d.
    chained = lift("A a; A b; O c; A d; = Q 4.0")
    assert plain(chained) == plain(net(par(s(c("a"), c("b")), c("c")), c("d"))), chained


def test_a_reloaded_midline_that_is_ored_is_a_chain_of_its_own() -> None:
    """After ``= M 1.0`` a new chain starts: ``A M 1.0; O I 0.1`` is (M OR I 0.1), which no
    midline in series can draw; the CPU shows the difference (I 0.0 off, I 0.1 and I 0.2 on)."""
    code = "A I 0.0; = M 1.0; A M 1.0; O I 0.1; A I 0.2; = Q 4.0"
    lifted = lift(code)
    assert not isinstance(lifted, Network)
    assert (lifted.code, lifted.instruction) == ("LAD306", "A M 1.0")
    assert _stl_truth(code)[6]  # I 0.0 = 0, I 0.1 = 1, I 0.2 = 1: Q 4.0 is on


CHECK_LINES = ["A I 0.0", "AN I 0.1", "O I 0.2", "ON I 0.3", "A I 0.3", "O I 0.0", "A I 0.2"]
BIT_LINES = [
    *CHECK_LINES,
    *CHECK_LINES,
    "O",
    "A(",
    "AN(",
    "O(",
    "ON(",
    ")",
    ")",
    "NOT",
    "= M 1.0; A M 1.0",  # M 1.0 is read right after it is written: no state between scans
]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(BIT_LINES), min_size=1, max_size=10))
def test_random_bit_logic_that_lifts_computes_what_the_cpu_computes(lines: list[str]) -> None:
    code = "; ".join([*lines, "= Q 4.0"])
    lifted = lift(code)
    assume(isinstance(lifted, Network))
    assert isinstance(lifted, Network)
    assert _model_truth(lifted) == _stl_truth(code), code
