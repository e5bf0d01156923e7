"""Random well-formed sequencers: the compiled FB on the CPU and the reference of
``graph_reference`` agree after every call on every step's state and every action operand.

A sequencer is drawn as a main line from its initial step: single steps, alternative
branches closed by an alternative convergence, simultaneous branches closed by a
simultaneous convergence; it ends in a jump back to a main-line step or a sequence end. Steps
carry N/S/R/D/L rows (some with events, some with the C suffix) on a small pool of Q and M bits so
that steps fight over them, and now and then an interlock or a supervision; conditions are
contacts on I bits, parallels and step-time comparators. The inputs then change at random for
about 30 calls with random cycle times, with INIT_SQ, ACK_EF and the mode inputs pulsed now and
then.

``derandomize`` keeps ``make test`` repeatable; ``NASAQ_LONG_PROPERTIES=1`` searches wider
(the bench's run).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import pytest
from graph_harness import Compiled, Modelled, anyof, c, cmp, cond, fb, nc
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from nasaq.lang.graph.model import (
    Action,
    GraphBlock,
    Sequencer,
    Settings,
    Step,
    Transition,
)
from nasaq.lang.lad.model import Element, Series

LONG = os.environ.get("NASAQ_LONG_PROPERTIES") == "1"
PROPERTY = settings(
    max_examples=300 if LONG else 10,
    deadline=None,
    derandomize=not LONG,
    # NASAQ_NO_SHRINK=1: report the first failure as found (shrinking a case costs minutes)
    phases=(Phase.explicit, Phase.reuse, Phase.generate, Phase.target)
    + (() if os.environ.get("NASAQ_NO_SHRINK") else (Phase.shrink,)),
)

INPUTS = [f"I 0.{bit}" for bit in range(8)] + ["I 1.0", "I 1.1"]
BITS = ["Q 0.0", "Q 0.1", "Q 0.2", "Q 0.3", "M 10.0", "M 10.1", "M 10.2"]
TIMES = ["T#100MS", "T#200MS", "T#300MS", "T#500MS"]


@dataclass
class Chart:
    """A sequencer being drawn: its steps, transitions and the numbers used so far."""

    draw: st.DrawFn
    numbers: list[int]  # [next step number, next transition number], shared by the FB
    control: bool  # ON/OFF rows allowed
    steps: list[Step] = field(default_factory=list)
    transitions: list[Transition] = field(default_factory=list)

    def step(self, initial: bool = False) -> str:
        draw = self.draw
        number = self.numbers[0]
        self.numbers[0] += 1
        name = f"Step{number}"
        actions = draw(st.lists(action(number, self.control), max_size=3))
        interlock = draw(st.one_of(st.none(), st.none(), st.none(), condition(name)))
        supervision = draw(st.one_of(st.none(), st.none(), st.none(), condition(name)))
        self.steps.append(
            Step(
                name=name,
                number=number,
                initial=initial,
                interlock=interlock,
                supervision=supervision,
                actions=actions,
            )
        )
        return name

    def transition(self, source: list[str], target: list[str], jump: bool = False) -> None:
        number = self.numbers[1]
        self.numbers[1] += 1
        # A jump always has a condition: a loop of transitions without one is refused (GRA212).
        choices = [condition(source[0])] if jump else [st.none(), condition(source[0])]
        when = self.draw(st.one_of(*choices, condition(source[0])))
        self.transitions.append(
            Transition(
                number=number,
                name=f"Trans{number}",
                source=source,
                target=target,
                jump=jump,
                condition=when,
            )
        )


def action(number: int, control: bool) -> st.SearchStrategy[Action]:
    """A row of step ``number``; its ON/OFF (when ``control``) name a step drawn so far."""
    plain = st.builds(
        lambda q, operand, interlock: Action(qualifier=q, operand=operand, interlock=interlock),
        st.sampled_from(["N", "S", "R"]),
        st.sampled_from(BITS),
        st.booleans(),
    )
    timed = st.builds(
        lambda q, operand, time: Action(qualifier=q, operand=operand, time=time),
        st.sampled_from(["D", "L"]),
        st.sampled_from(BITS),
        st.sampled_from(TIMES),
    )
    event = st.builds(
        lambda e, q, operand: Action(event=e, qualifier=q, operand=operand),
        st.sampled_from(["S1", "S0", "L1", "L0", "V1", "V0", "A1"]),
        st.sampled_from(["N", "S", "R"]),
        st.sampled_from(BITS),
    )
    steps = st.builds(
        lambda e, q, number: Action(event=e, qualifier=q, operand=f"S{number}"),
        st.sampled_from(["S1", "V1"]),
        st.sampled_from(["ON", "OFF"]),
        st.integers(1, number),
    )
    rows = [plain, plain, timed, event]
    return st.one_of(*rows, steps) if control else st.one_of(*rows)


def condition(step: str) -> st.SearchStrategy[Series]:
    contact = st.builds(
        lambda i, neg: nc(i) if neg else c(i), st.sampled_from(INPUTS), st.booleans()
    )
    timed = st.builds(lambda t: cmp(">=", f"{step}.T", t), st.sampled_from(TIMES))
    either = st.builds(lambda a, b: anyof(a, b), contact, contact)
    element: st.SearchStrategy[Element] = st.one_of(contact, contact, timed, either)
    return st.lists(element, min_size=1, max_size=2).map(lambda e: cond(*e))


@st.composite
def sequencer(draw: st.DrawFn, index: int, numbers: list[int], control: bool) -> Sequencer:
    chart = Chart(draw, numbers, control)
    main = [chart.step(initial=True)]
    current = main[0]
    for _ in range(draw(st.integers(1, 3))):
        shape = draw(st.sampled_from(["step", "alternative", "simultaneous"]))
        if shape == "step":
            following = chart.step()
            chart.transition([current], [following])
        elif shape == "alternative":
            left, right = chart.step(), chart.step()
            following = chart.step()
            chart.transition([current], [left])
            chart.transition([current], [right])
            chart.transition([left], [following])
            chart.transition([right], [following])
        else:
            left, right = chart.step(), chart.step()
            following = chart.step()
            chart.transition([current], [left, right])
            chart.transition([left, right], [following])
        main.append(following)
        current = following
    if draw(st.integers(0, 4)) == 0:
        chart.transition([current], [])
    else:
        chart.transition([current], [draw(st.sampled_from(main[:-1]))], jump=True)
    return Sequencer(name=f"Seq{index}", steps=chart.steps, transitions=chart.transitions)


PULSED = ["INIT_SQ", "OFF_SQ", "ACK_EF", "SW_AUTO", "SW_MAN", "SW_TAP", "T_PUSH"]
PULSED += ["S_NEXT", "S_PREV", "S_ON", "S_OFF"]
MORE = ["SW_TOP", "HALT_SQ", "HALT_TM", "ZERO_OP", "EN_IL", "EN_SV", "EN_SSKIP", "EN_ACKREQ"]
MEMBERS = ["X", "S1", "S0", "V1", "V0", "L1", "L0", "A1", "LA", "VA", "T", "U"]
Case = tuple[GraphBlock, list[tuple[dict[str, int], int]]]


@st.composite
def cases(draw: st.DrawFn) -> Case:
    """A block and the inputs of its calls (FB inputs of its parameter set among them)."""
    numbers = [1, 1]
    count = draw(st.integers(1, 2))
    skip = draw(st.booleans())
    # ON/OFF, S_ON and EN_SSKIP can put a second token on a chain; what Skip Step does when a
    # skipped chain reaches a step already active is not specified (SEMANTICS §2 phase 4), so
    # charts with Skip Step keep one token per chain.
    chart = [draw(sequencer(i, numbers, not skip)) for i in range(count)]
    options = Settings(
        parameters=draw(st.sampled_from(["STANDARD", "STANDARD", "USER_DEFINED"])),
        skip_steps=skip,
        acknowledge_required=draw(st.booleans()),
        interlock_blocks=draw(st.booleans()),
    )
    block = fb(*chart, settings=options)
    names = PULSED + (MORE if options.parameters == "USER_DEFINED" else [])
    names = [n for n in names if n != ("S_ON" if skip else "EN_SSKIP")]
    inputs = st.dictionaries(st.sampled_from(INPUTS), st.integers(0, 1), max_size=4)
    pulses = st.dictionaries(st.sampled_from(names), st.integers(0, 1), max_size=1)
    selected = st.dictionaries(st.just("S_SEL"), st.integers(0, numbers[0]), max_size=1)
    one = st.tuples(
        st.builds(lambda a, b, c: {**a, **b, **c}, inputs, pulses, selected),
        st.sampled_from([50, 100, 200]),
    )
    return block, draw(st.lists(one, min_size=20, max_size=35))


def snapshot(ex: Compiled | Modelled, block: GraphBlock) -> dict[str, int]:
    seen: dict[str, int] = {}
    for sequencer in block.sequencers:
        for step in sequencer.steps:
            for member in MEMBERS:
                seen[f"{step.name}.{member}"] = ex.step(step.name, member)
        for transition in sequencer.transitions:
            seen[f"{transition.name}.TT"] = ex.tt(transition.name)
    for bit in BITS:
        seen[bit] = ex.bit(bit)
    outputs = ["S_NO", "S_MORE", "S_ACTIVE", "ERR_FLT", "AUTO_ON", "MAN_ON", "TAP_ON"]
    if block.settings.parameters == "USER_DEFINED":
        outputs += ["TOP_ON", "ERROR", "FAULT", "SQ_ISOFF", "SQ_HALTED", "OP_ZEROED"]
    for name in outputs:
        seen[name] = ex.out(name)
    seen["G7_MODE"] = ex.mode()
    return seen


@PROPERTY
@given(cases())
def test_the_compiled_fb_agrees_with_the_reference(case: Case) -> None:
    block, sequence = case
    compiled, reference = Compiled(block), Modelled(block)
    for number, (inputs, dt) in enumerate(sequence):
        compiled.call(inputs, dt)
        reference.call(inputs, dt)
        want, got = snapshot(reference, block), snapshot(compiled, block)
        differences = {k: (want[k], got[k]) for k in want if want[k] != got[k]}
        if differences:
            calls = "\n".join(
                f"  {n}: {i} +{d} ms" for n, (i, d) in enumerate(sequence[: number + 1])
            )
            pytest.fail(
                f"after call {number}, (reference, CPU) differ: {differences}\n"
                f"calls:\n{calls}\nsource:\n{compiled.text}"
            )
