"""Hypothesis strategies for LAD networks that STEP 7 could draw and lower to STL.

Every rung and branch starts with something that reads a value (a contact, a status contact, a
compare box or a parallel): NOT, edges, midlines and EN/ENO boxes (MOVE, ADD_I) act on the flow
before them, so a branch cannot start with one. Operands come from small pools, so that contacts
repeat and compares hit equality often; midlines, edge memories, coils and box results have
pools of their own that no contact reads, which keeps the Python oracle of the tests simple (a
midline never changes a later contact).

``lad_random`` stays beside this module: it draws *any* model shape (empty branches, NOT first,
jumps, OPN, timer boxes with logic pins) for the views that must show whatever a file holds;
these strategies draw the networks that lower to STL and come back.
"""

from __future__ import annotations

from hypothesis import strategies as st

from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Invert,
    LadBlock,
    Midline,
    Network,
    Output,
    Parallel,
    Series,
    StatusContact,
)

BITS = ("I 0.0", "I 0.1", "I 0.2", "M 1.0", "M 1.1")
WORDS = ("MW 10", "MW 12")
MIDLINES = ("M 2.0", "M 2.1")
EDGE_MEMORIES = ("M 3.0", "M 3.1")
COILS = ("Q 4.0", "Q 4.1", "M 5.0")
RESULTS = ("MW 14", "MW 16")  # what MOVE and ADD_I boxes write; no contact or compare reads them
COMPARES = ("==I", "<>I", ">I", "<I", ">=I", "<=I")
STATUS_BITS = ("OV", "BR", "==0", "<>0", ">=0", "<0")


def contacts() -> st.SearchStrategy[Element]:
    return st.builds(Contact, operand=st.sampled_from(BITS), negated=st.booleans())


def compares() -> st.SearchStrategy[Element]:
    """A compare box on two words, or a word and a small constant."""
    second = st.one_of(st.sampled_from(WORDS), st.integers(-2, 2).map(str))
    return st.builds(
        lambda op, first, other: Box(name=f"CMP{op}", inputs={"IN1": first, "IN2": other}),
        st.sampled_from(COMPARES),
        st.sampled_from(WORDS),
        second,
    )


def status_contacts() -> st.SearchStrategy[Element]:
    return st.builds(StatusContact, bit=st.sampled_from(STATUS_BITS), negated=st.booleans())


def en_boxes() -> st.SearchStrategy[Element]:
    """MOVE and ADD_I boxes in the rung: EN is the flow into them, ENO the flow out (small
    words never overflow, so ENO is EN)."""
    move = st.builds(
        lambda source, target: Box(name="MOVE", inputs={"IN": source}, outputs={"OUT": target}),
        st.sampled_from(WORDS),
        st.sampled_from(RESULTS),
    )
    add = st.builds(
        lambda first, second, target: Box(
            name="ADD_I", inputs={"IN1": first, "IN2": second}, outputs={"OUT": target}
        ),
        st.sampled_from(WORDS),
        st.one_of(st.sampled_from(WORDS), st.integers(-2, 2).map(str)),
        st.sampled_from(RESULTS),
    )
    return st.one_of(move, add)


def flow_elements() -> st.SearchStrategy[Element]:
    """Elements that act on the flow before them: NOT, edges, midlines, EN/ENO boxes."""
    return st.one_of(
        st.just(Invert()),
        st.builds(
            EdgeContact, edge=st.sampled_from(["P", "N"]), memory=st.sampled_from(EDGE_MEMORIES)
        ),
        st.builds(Midline, operand=st.sampled_from(MIDLINES)),
        en_boxes(),
    )


def _series(
    first: st.SearchStrategy[Element], rest: st.SearchStrategy[Element], longest: int
) -> st.SearchStrategy[Series]:
    return st.tuples(first, st.lists(rest, max_size=longest)).map(
        lambda pair: Series(elements=[pair[0], *pair[1]])
    )


def elements(status: bool = False) -> st.SearchStrategy[Element]:
    """A check (contact, compare, status contact when ``status``) or nested parallels of
    series of them, with NOT, edges and midlines after the first element of each series."""
    checks = st.one_of(contacts(), compares(), *([status_contacts()] if status else []))

    def extend(inner: st.SearchStrategy[Element]) -> st.SearchStrategy[Element]:
        item = st.one_of(checks, inner)
        branch = _series(item, st.one_of(item, flow_elements()), 2)
        return st.lists(branch, min_size=2, max_size=3).map(
            lambda branches: Parallel(branches=branches)
        )

    return st.recursive(checks, extend, max_leaves=8)


def outputs(status: bool = False) -> st.SearchStrategy[list[Output]]:
    """One to three outputs: ``=``/``S``/``R`` coils, each with conditions of its own (none
    for a single output: those would just be more logic), each on its own operand (STEP 7's
    LAD view shows no network that mixes ``=``, ``S`` and ``R`` on one operand)."""
    target = st.builds(Coil, coil=st.sampled_from(["=", "S", "R"]), operand=st.sampled_from(COILS))
    item = elements(status)
    conditions = st.one_of(st.just(Series()), _series(item, st.one_of(item, flow_elements()), 1))
    several = st.lists(
        st.builds(Output, conditions=conditions, target=target),
        min_size=2,
        max_size=3,
        unique_by=lambda output: output.target.operand,  # type: ignore[union-attr]
    )
    return st.one_of(target.map(lambda coil: [Output(target=coil)]), several)


def networks(status: bool = False) -> st.SearchStrategy[Network]:
    """A rung: a series that starts with a check or a parallel, then its outputs. ``status``
    adds status contacts (OV, BR, ==0 ...), whose value depends on the CPU's status word."""
    item = elements(status)
    logic = _series(item, st.one_of(item, flow_elements()), 4)
    return st.builds(lambda lg, outs: Network(logic=lg, outputs=outs), logic, outputs(status))


def blocks(status: bool = False, language: str = "LAD") -> st.SearchStrategy[LadBlock]:
    """An OB 1 of one to three such networks."""
    return st.lists(networks(status), min_size=1, max_size=3).map(
        lambda found: LadBlock(language=language, kind="OB", name="OB 1", networks=found)  # type: ignore[arg-type]
    )
