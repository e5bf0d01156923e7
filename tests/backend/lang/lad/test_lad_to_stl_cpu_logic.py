"""Lowered rungs run on the CPU and compute what the diagram means: for random series/parallel
trees (with NOT and midlines) and several outputs, every combination of four inputs gives the
outputs and midline bits a Python evaluation of the power flow gives."""

from __future__ import annotations

import itertools

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lad_to_stl_run import c, coil, get, net, ob1, par, plc, put, s, scan

from nasaq.lang.lad.model import (
    Contact,
    EdgeContact,
    Element,
    Invert,
    Midline,
    Output,
    Parallel,
    Series,
)

INPUTS = ("I 0.0", "I 0.1", "I 0.2", "I 0.3")
_bits = itertools.count()


def _midline() -> Midline:
    n = next(_bits) % 400
    return Midline(operand=f"M {10 + n // 8}.{n % 8}")


def _series(children: st.SearchStrategy[Element]) -> st.SearchStrategy[Series]:
    """A series whose later elements may be followed by NOT or a midline (never at its start:
    there is no flow there to act on)."""
    extra = st.sampled_from([None, None, "not", "mid"])

    def build(items: list[tuple[Element, str | None]]) -> Series:
        elements: list[Element] = []
        for element, after in items:
            elements.append(element)
            if after == "not":
                elements.append(Invert())
            elif after == "mid":
                elements.append(_midline())
        return Series(elements=elements)

    return st.lists(st.tuples(children, extra), min_size=1, max_size=3).map(build)


contacts = st.builds(Contact, operand=st.sampled_from(INPUTS), negated=st.booleans())
elements = st.recursive(
    contacts,
    lambda children: st.lists(_series(children), min_size=2, max_size=3).map(
        lambda branches: Parallel(branches=branches)
    ),
    max_leaves=7,
)
rungs = _series(elements)


def flow(series: Series, power: bool, env: dict[str, bool], mids: dict[str, bool]) -> bool:
    for element in series.elements:
        if isinstance(element, Contact):
            power = power and env[element.operand] != element.negated
        elif isinstance(element, Invert):
            power = not power
        elif isinstance(element, Midline):
            mids[element.operand] = power
        elif isinstance(element, Parallel):
            each = [flow(branch, power, env, mids) for branch in element.branches]  # all: midlines
            power = any(each)
        else:  # pragma: no cover - the strategies make no other element
            raise AssertionError(element)
    return power


def check(logic: Series, outputs: list[Output]) -> None:
    network = net(*logic.elements, outputs=outputs)
    cpu = plc(ob1(network))
    for values in itertools.product((0, 1), repeat=len(INPUTS)):
        env = dict(zip(INPUTS, map(bool, values), strict=True))
        put(cpu, **{name.replace(" ", "").replace(".", "_"): v for name, v in env.items()})
        scan(cpu)
        mids: dict[str, bool] = {}
        common = flow(logic, True, env, mids)
        for out in outputs:
            expected = flow(out.conditions, common, env, mids)
            assert get(cpu, out.target.operand) == expected, (values, out)  # type: ignore[union-attr]
        for bit, expected in mids.items():
            assert get(cpu, bit) == expected, (values, bit)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rungs)
def test_random_rungs_compute_their_power_flow(logic: Series) -> None:
    check(logic, [coil("Q 4.0")])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rungs, st.lists(st.one_of(st.just(Series()), _series(elements)), min_size=2, max_size=3))
def test_several_outputs_with_conditions_keep_the_common_flow(
    logic: Series, conditions: list[Series]
) -> None:
    outputs = [
        Output(conditions=cond, target=coil(f"Q 5.{i}").target) for i, cond in enumerate(conditions)
    ]
    check(logic, outputs)


def test_shapes_that_need_brackets_and_the_kept_flow() -> None:
    a, b, x, y = (c(name) for name in INPUTS)
    check(s(par(a, s(b, x)), y), [coil("Q 4.0")])  # a parallel before more elements: A( ... )
    check(s(x, par(s(a, Invert()), b)), [coil("Q 4.0")])  # NOT in a branch sees x too
    check(s(x, par(s(a, _midline()), b), y), [coil("Q 4.0")])
    check(s(par(a, b)), [coil("Q 4.0"), coil("Q 4.1")])  # unconditional outputs: = q1; = q2


def test_outputs_straight_from_the_rail_are_powered() -> None:
    cpu = plc(ob1(net(outputs=[coil("Q 4.0"), coil("Q 4.1")])))
    scan(cpu)
    assert (get(cpu, "Q 4.0"), get(cpu, "Q 4.1")) == (1, 1)


def test_set_and_reset_coils_and_edges_over_scans() -> None:
    cpu = plc(
        ob1(
            net(c("I 0.0"), outputs=[coil("M 0.0", "S")]),
            net(c("I 0.1"), outputs=[coil("M 0.0", "R")]),
            net(c("I 0.2"), EdgeContact(edge="P", memory="M 1.0"), outputs=[coil("Q 4.0")]),
            net(c("I 0.2"), EdgeContact(edge="N", memory="M 1.1"), outputs=[coil("Q 4.1")]),
            net(c("M 0.0"), outputs=[coil("Q 4.2")]),
        )
    )
    trace = []
    for i0, i1, i2 in [(1, 0, 0), (0, 0, 1), (0, 0, 1), (0, 1, 0), (0, 0, 0)]:
        put(cpu, I0_0=i0, I0_1=i1, I0_2=i2)
        scan(cpu)
        trace.append((get(cpu, "Q 4.0"), get(cpu, "Q 4.1"), get(cpu, "Q 4.2")))
    assert trace == [(0, 0, 1), (1, 0, 1), (0, 0, 1), (0, 1, 0), (0, 0, 0)]


def test_edge_inside_a_parallel_after_a_contact_sees_the_whole_flow() -> None:
    edge = EdgeContact(edge="P", memory="M 1.0")
    cpu = plc(ob1(net(c("I 0.0"), par(s(c("I 0.1"), edge), c("I 0.2")))))
    trace = []
    for i0, i1 in [(0, 1), (1, 1), (1, 1), (0, 1), (1, 1)]:
        put(cpu, I0_0=i0, I0_1=i1, I0_2=0)
        scan(cpu)
        trace.append(get(cpu, "Q 4.0"))
    # The edge sees I 0.0 AND I 0.1: it rises when I 0.0 comes, not when I 0.1 did.
    assert trace == [0, 1, 0, 0, 1]
