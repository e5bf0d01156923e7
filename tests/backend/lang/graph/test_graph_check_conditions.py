"""The condition rules of the Graph checker (``check_conditions``): only contacts, branches
and comparators in transitions, interlocks and supervisions; at most 32 elements; permanent
networks end in =, S, R coils or block calls."""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block
from nasaq.lang.graph.model import GraphBlock, Sequencer, Step, Transition
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text import parse_graph
from nasaq.lang.lad.model import Contact, Invert, Series

CHAIN = """SEQUENCER Main
INITIAL_STEP Idle (1)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
TRANSITION Go (1) FROM Idle TO Run
CONDITION {go} END_CONDITION
END_TRANSITION
STEP Run (2)
{parts}ACTIONS
  NC Q 0.1;
END_ACTIONS
END_STEP
TRANSITION Back (2) FROM Run JUMP Idle
CONDITION Contact(I 0.1) END_CONDITION
END_TRANSITION
END_SEQUENCER
"""


def _check(
    go: str = "Contact(I 0.0)",
    parts: str = "INTERLOCK Contact(I 0.5) END_INTERLOCK\n",
    pre: str = "",
) -> list[Diagnostic]:
    body = pre + CHAIN.format(go=go, parts=parts)
    parsed = parse_graph(f"FUNCTION_BLOCK FB 1\nBEGIN\n{body}END_FUNCTION_BLOCK\n", "c.graph")
    assert parsed.diagnostics == []
    return check_block(parsed, 0)


def _found(found: list[Diagnostic]) -> list[tuple[str, str | None]]:
    return [(p.code, p.span.element if p.span else None) for p in found]


def test_contacts_branches_and_comparators_are_allowed_everywhere() -> None:
    go = (
        "Parallel BRANCH Contact(I 0.0) ContactNC(I 0.1) END_BRANCH "
        "BRANCH Box(CMP>=I, IN1 := MW 2, IN2 := 5) END_BRANCH END_PARALLEL "
        "Box(CMP<>R, IN1 := MD 4, IN2 := 1.5)"
    )
    parts = (
        "INTERLOCK ContactNC(I 0.5) END_INTERLOCK\n"
        "SUPERVISION Box(CMP>D, IN1 := Run.T, IN2 := T#10S) END_SUPERVISION\n"
    )
    assert _check(go, parts) == []


def test_not_is_refused_with_its_own_hint_on_its_element() -> None:
    found = _check("Contact(I 0.0) NOT")
    assert _found(found) == [("GRA261", "T1/e2")]
    assert found[0].span is not None
    assert found[0].span.line == 9


def test_other_elements_are_refused_where_they_stand() -> None:
    found = _check(
        "Contact(I 0.0) Midline(M 1.0)",
        "INTERLOCK Status(OV) END_INTERLOCK\n"
        "SUPERVISION Edge(P, M 0.0) Box(ADD_I, IN1 := 1, IN2 := 2, OUT => MW 0) END_SUPERVISION\n",
    )
    assert [
        (code, element, p.params) for p, (code, element) in zip(found, _found(found), strict=False)
    ] == [
        ("GRA260", "T1/e2", {"found": "Midline(M 1.0)"}),
        ("GRA260", "S2/C/e1", {"found": "Status(OV)"}),
        ("GRA260", "S2/V/e1", {"found": "Edge(P, M 0.0)"}),
        ("GRA260", "S2/V/e2", {"found": "Box(ADD_I)"}),
    ]


def test_32_elements_pass_33_do_not_and_branches_do_not_count() -> None:
    def contacts(count: int) -> str:
        return " ".join(f"Contact(I {k // 8}.{k % 8})" for k in range(count))

    assert _check(contacts(32)) == []
    found = _check(contacts(33))
    assert [(p.code, p.params) for p in found] == [("GRA262", {"count": 33, "limit": 32})]
    branched = (
        "Parallel BRANCH " + contacts(16) + " END_BRANCH BRANCH " + contacts(16) + " END_BRANCH "
        "END_PARALLEL"
    )
    assert _check(branched) == []
    assert [p.code for p in _check(branched + " Contact(I 9.0)")] == ["GRA262"]
    long_interlock = f"INTERLOCK {contacts(40)} END_INTERLOCK\n"
    assert _found(_check(parts=long_interlock)) == [("GRA262", "S2/C")]


def _permanent(*rungs: str) -> str:
    networks = "".join(f"NETWORK\n{rung}\n" for rung in rungs)
    return f"PERMANENT_PRE\n{networks}END_PERMANENT_PRE\n"


def test_permanent_networks_with_coils_and_block_calls_pass() -> None:
    pre = _permanent(
        "RUNG Contact(I 1.0) Contact(I 1.1) Coil(Q 1.0) END_RUNG",
        "RUNG Contact(I 1.2) SetCoil(M 5.0) END_RUNG",
        "RUNG Box(CMP>I, IN1 := MW 2, IN2 := 3) ResetCoil(M 5.0) END_RUNG",
        "RUNG Box(FC 3) END_RUNG",
        "RUNG Contact(I 1.3) OUTPUTS BRANCH Coil(Q 1.1) END_BRANCH "
        "BRANCH Contact(I 1.4) Coil(Q 1.2) END_BRANCH END_OUTPUTS END_RUNG",
    )
    assert _check(pre=pre) == []


def test_permanent_networks_refuse_other_ends_stl_and_missing_outputs() -> None:
    pre = _permanent(
        "RUNG Contact(I 1.0) SD(T 5, S5T#2S) END_RUNG",
        "RUNG Contact(I 1.1) Jump(M001) END_RUNG",
        "RUNG Contact(I 1.2) Box(MOVE, IN := 1, OUT => MW 4) END_RUNG",
        "RUNG Contact(I 1.3) NOT Coil(Q 2.0) END_RUNG",
        "RUNG Contact(I 1.4) END_RUNG",
        "STL\n  A I 1.5\n  = Q 2.1\nEND_STL",
    )
    found = _check(pre=pre)
    assert [(p.code, p.span.element if p.span else None, p.params) for p in found] == [
        ("GRA263", "PRE1/e2", {"found": "SD(T 5)"}),
        ("GRA263", "PRE2/e2", {"found": "Jump(M001)"}),
        ("GRA263", "PRE3/e2", {"found": "Box(MOVE)"}),
        ("GRA261", "PRE4/e2", {}),
        ("GRA265", "PRE5", {"network": "PRE5"}),
        ("GRA264", "PRE6", {"network": "PRE6"}),
    ]
    assert next(p for p in found if p.code == "GRA265").severity == "warning"


def test_permanent_network_counts_its_coils_towards_32() -> None:
    contacts = " ".join(f"Contact(I {k // 8}.{k % 8})" for k in range(32))
    found = _check(pre=_permanent(f"RUNG {contacts} Coil(Q 4.0) END_RUNG"))
    assert [(p.code, p.params) for p in found] == [("GRA262", {"count": 33, "limit": 32})]


def test_post_networks_are_keyed_post() -> None:
    text = CHAIN.format(go="Contact(I 0.0)", parts="INTERLOCK Contact(I 0.5) END_INTERLOCK\n")
    post = "PERMANENT_POST\nNETWORK\nRUNG Contact(I 1.4) END_RUNG\nEND_PERMANENT_POST\n"
    parsed = parse_graph(f"FUNCTION_BLOCK FB 1\nBEGIN\n{text}{post}END_FUNCTION_BLOCK\n", "c.graph")
    assert _found(check_block(parsed, 0)) == [("GRA265", "POST1")]


def test_elements_without_ids_point_at_their_part() -> None:
    """A model built by an editor before numbering: the problem names the part."""
    condition = Series(elements=[Contact(operand="I 0.0"), Invert()])
    step = Step(number=1, name="Idle", initial=True, supervision=condition)
    loop = Transition(number=1, name="Go", source=["Idle"], target=["Idle"], condition=condition)
    block = GraphBlock(
        name="FB 1", sequencers=[Sequencer(name="M", steps=[step], transitions=[loop])]
    )
    parsed = ParsedGraph(file="m.graph", blocks=[block], places=[{"BLOCK": 1}])
    found = [(p.code, p.span.element if p.span else None) for p in check_block(parsed, 0)]
    assert ("GRA261", "T1") in found
    assert ("GRA261", "S1/V") in found
