"""LAD → STL → LAD gives the same network back: every shape ``to_stl`` writes
(``STL_PATTERNS.md``) is read back by the lifter into the model it came from."""

from __future__ import annotations

import pytest
from lad_from_stl_build import (
    EdgeContact,
    Invert,
    Midline,
    box,
    c,
    coil,
    nc,
    net,
    ob1,
    out,
    par,
    plain,
    s,
    st,
)

from nasaq.lang.lad.from_stl import lift_block
from nasaq.lang.lad.model import Jump, Network, OpenDb, Return
from nasaq.lang.lad.to_stl import block_to_stl

NETWORKS: dict[str, Network] = {
    "series": net(c("I 0.0"), nc("I 0.1")),
    "status": net(st("OV"), st("==0", negated=True), c('"Start"')),
    "or of contacts": net(par(c("I 0.0"), c("Q 4.0"))),
    "or of groups": net(par(s(c("a"), c("b")), s(c("c"), c("d")))),
    "or: one then group": net(par(c("a"), s(c("b"), c("c")))),
    "or: group then one": net(par(s(c("a"), c("b")), c("c"))),
    "series around or": net(c("x"), par(c("a"), c("b")), c("y")),
    "nested or": net(par(par(c("a"), c("b")), c("c"))),
    "or inside branch": net(par(s(c("a"), par(c("b"), c("c"))), c("d"))),
    "not": net(c("a"), Invert(), c("b")),
    "not in branch": net(c("x"), par(s(c("a"), Invert()), c("b"))),
    "edge": net(c("a"), EdgeContact(edge="P", memory="M 1.0")),
    "edge in branch after logic": net(
        c("x"), par(s(EdgeContact(edge="N", memory="M 1.1")), c("b"))
    ),
    "midline": net(c("a"), Midline(operand="M 2.0"), c("b")),
    "several coils": net(
        c("a"), outputs=[out(coil("Q 4.0")), out(coil("M 0.1", "S")), out(coil("M 0.2", "R"))]
    ),
    "output branches": net(
        c("a"), outputs=[out(coil("Q 4.0"), c("b")), out(coil("Q 4.1"), nc("c"))]
    ),
    "rail coil": net(),
    "timer coil": net(c("a"), outputs=[out(coil("T 1", "SD", "S5T#5S"))]),
    "counter coils": net(c("a"), outputs=[out(coil("C 1", "CU"))]),
    "set counter": net(c("a"), outputs=[out(coil("C 2", "SC", "C#10"))]),
    "save": net(c("a"), outputs=[out(coil("", "SAVE"))]),
    "jump": net(c("a"), outputs=[out(Jump(label="M001"))]),
    "jump not": net(c("a"), outputs=[out(Jump(label="M001", negated=True))]),
    "rail jump": net(outputs=[out(Jump(label="M001"))]),
    "return": net(c("a"), outputs=[out(Return())]),
    "rail return": net(outputs=[out(Return())]),
    "open db": net(outputs=[out(OpenDb(block="DB 5"))]),
    "label": net(c("a"), label="M001"),
    "compare": net(box("CMP>=I", IN1="MW 10", IN2="5")),
    "compare in series": net(c("a"), box("CMP==R", IN1="MD 0", IN2="1.0")),
    "compare in branch": net(par(box("CMP<I", IN1="MW 0", IN2="MW 2"), c("b"))),
    "move from rail": net(outputs=[out(box("MOVE", IN="MW 0", OUT="MW 2"))]),
    "move with en": net(c("a"), outputs=[out(box("MOVE", IN="MW 0", OUT="MW 2"))]),
    "add in chain": net(c("a"), box("ADD_I", IN1="MW 0", IN2="5", OUT="MW 2"), c("b")),
    "shift": net(c("a"), outputs=[out(box("SHL_W", IN="MW 0", N="3", OUT="MW 2"))]),
    "round": net(box("ROUND", IN="MD 0", OUT="MD 4")),
    "timer box": net(c("a"), box("S_ODT", "T 5", TV="S5T#2S", R="I 0.1", BI="MW 10", BCD="MW 12")),
    "timer box, q unused": net(c("a"), outputs=[out(box("S_PULSE", "T 2", TV="S5T#1S"))]),
    "timer box, reset logic": net(c("a"), box("S_OFFDT", "T 3", TV="MW 4", R=s(c("b"), nc("c")))),
    "counter box": net(
        c("a"), box("S_CUD", "C 1", CD="I 0.1", S="I 0.2", PV="C#10", R="I 0.3", CV="MW 0")
    ),
    "counter box, q unused": net(c("a"), outputs=[out(box("S_CU", "C 3", R="I 0.3"))]),
    "sr": net(c("a"), box("SR", "M 0.0", R1="I 0.1")),
    "rs": net(c("a"), box("RS", "M 0.1", S1=s(c("x"), c("y")))),
    "pos": net(c("a"), box("POS", "I 0.3", M_BIT="M 1.0")),
    "call": net(outputs=[out(box("FC 10", IN1="MW 0", RET_VAL="MW 2"))]),
    "call with en": net(c("a"), outputs=[out(box("FB 5", "DB 10", IN1="5"))]),
    "call in chain": net(c("a"), box("FC 10", IN1="MW 0"), c("b")),
    "call with boolean pin": net(c("a"), outputs=[out(box("FC 10", IN1=s(c("x"), nc("y"))))]),
    "call pin from the rail": net(outputs=[out(box("FC 10", IN1=s()))]),
    "call pins after logic": net(
        c("a"), outputs=[out(box("FC 10", IN1=s(), IN2=s(c("x"), c("y"))))]
    ),
    "call pin, then more logic": net(c("a"), box("FC 10", IN1=s(c("x"), nc("y"))), c("z")),
    "two calls in series": net(c("a"), box("FC 10", IN1="MW 0"), box("FC 10", IN1="MW 2")),
    "call in an output branch": net(
        c("a"),
        outputs=[
            out(coil("Q 1.0"), c("b")),
            out(box("FC 10", IN1=s(c("x"), c("y"))), c("c")),
        ],
    ),
    "box after a parallel": net(par(c("a"), c("b")), box("MOVE", IN="1", OUT="MW 2")),
    "and group holding a parallel": net(par(s(c("a"), par(c("b"), c("c"))), c("d"))),
    "later and group holding a parallel": net(par(c("d"), s(c("a"), par(c("b"), c("c"))))),
    "midline in a branch": net(c("x"), par(s(c("a"), Midline(operand="M 1.0")), c("b"))),
    "midline branch, then more": net(
        c("x"), par(s(c("a"), Midline(operand="M 1.0")), c("b")), c("y")
    ),
    "branches: jump and coil": net(
        c("a"), outputs=[out(Jump(label="L1"), c("b")), out(coil("Q 1.0"))]
    ),
    "branches: box first": net(
        c("a"), outputs=[out(box("MOVE", IN="1", OUT="MW 2")), out(coil("Q 1.0"))]
    ),
    "branches: timer coil": net(
        c("a"),
        outputs=[out(coil("T 1", "SP", "S5T#1S"), c("b")), out(coil("Q 1.0"), c("c"))],
    ),
    "jump not from the rail": net(outputs=[out(Jump(label="L1", negated=True))]),
    "timer box from the rail": net(box("S_ODT", "T 1", TV="S5T#1S")),
    "counter box from the rail": net(box("S_CU", "C 1", PV="C#5", S="I 0.1")),
    "sr from the rail": net(box("SR", "M 0.0", R1="I 0.1")),
    "compare, then or": net(par(s(box("CMP>I", IN1="MW 0", IN2="1"), c("a")), c("b"))),
    # An output branch whose conditions start with an element acting on the common flow.
    "branches: timer box before a coil": net(
        par(c("a"), c("q")),
        nc("b"),
        outputs=[out(coil("Q 4.0")), out(coil("Q 4.1"), box("S_ODT", "T 1", TV="S5T#2S"))],
    ),
    "branches: counter box before a coil": net(
        c("a"),
        outputs=[out(coil("Q 4.0")), out(coil("Q 4.1"), box("S_CU", "C 1", PV="C#5", S="I 0.1"))],
    ),
    "branches: move in chain before a coil": net(
        c("a"),
        outputs=[out(coil("Q 4.0")), out(coil("Q 4.1"), box("MOVE", IN="1", OUT="MW 2"))],
    ),
    "branches: edge before a coil": net(
        c("a"),
        outputs=[out(coil("Q 4.0")), out(coil("Q 4.1"), EdgeContact(edge="P", memory="M 3.0"))],
    ),
    "branches: not before a coil": net(
        c("a"), outputs=[out(coil("Q 4.0")), out(coil("Q 4.1"), Invert())]
    ),
}

# Shapes whose STL is also the STL of a simpler drawing: the lifter gives the drawing STEP 7
# shows (an operand on ENO or EN is a coil or contact beside the box; POS in a branch is its
# contact and edge).
NORMAL_FORMS: dict[str, tuple[Network, Network]] = {
    "eno operand": (
        net(c("a"), outputs=[out(box("MOVE", IN="1", OUT="MW 2", ENO="M 0.0"))]),
        net(c("a"), box("MOVE", IN="1", OUT="MW 2"), outputs=[out(coil("M 0.0"))]),
    ),
    "en operand": (
        net(c("a"), outputs=[out(box("MOVE", EN="I 0.5", IN="1", OUT="MW 2"))]),
        net(c("a"), c("I 0.5"), outputs=[out(box("MOVE", IN="1", OUT="MW 2"))]),
    ),
    "pos in a branch": (
        net(par(box("POS", "I 0.0", M_BIT="M 1.0"), c("b"))),
        net(par(s(c("I 0.0"), EdgeContact(edge="P", memory="M 1.0")), c("b"))),
    ),
}

INTERFACE = """FUNCTION FC 10 : VOID
VAR_INPUT
  IN1 : INT;
END_VAR
VAR_OUTPUT
  Result : INT;
END_VAR
BEGIN
NETWORK
      NOP   0;
END_FUNCTION
"""


@pytest.mark.parametrize("name", list(NETWORKS))
def test_lad_to_stl_to_lad_gives_the_same_network(name: str) -> None:
    network = NETWORKS[name]
    text, problems = block_to_stl(ob1(network))
    assert not problems
    result = lift_block(INTERFACE + text, "round.awl")
    lifted = result.blocks[-1].networks[0]
    assert plain(lifted) == plain(network), text


@pytest.mark.parametrize("name", list(NORMAL_FORMS))
def test_an_ambiguous_shape_lifts_to_its_normal_form(name: str) -> None:
    drawn, normal = NORMAL_FORMS[name]
    text, problems = block_to_stl(ob1(drawn))
    assert not problems
    assert block_to_stl(ob1(normal))[0] == text
    lifted = lift_block(text, "normal.awl").blocks[0].networks[0]
    assert plain(lifted) == plain(normal), text
