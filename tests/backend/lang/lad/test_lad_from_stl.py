"""Hand-typed STL networks of LAD shape lift to the exact model STEP 7 would show."""

from __future__ import annotations

import pytest
from lad_from_stl_build import (
    EdgeContact,
    Invert,
    Midline,
    box,
    c,
    coil,
    lift,
    nc,
    net,
    out,
    par,
    plain,
    s,
    st,
)

from nasaq.lang.lad.from_stl import NotConvertible, lift_block
from nasaq.lang.lad.model import Jump, Network, Return

SHAPES = {
    "series": ("A I 0.0; AN I 0.1; = Q 4.0", net(c("I 0.0"), nc("I 0.1"))),
    "or then series": (
        "A(; O I 0.0; O Q 4.0; ); AN I 0.1; = Q 4.0",
        net(par(c("I 0.0"), c("Q 4.0")), nc("I 0.1")),
    ),
    "latch without brackets": (
        'O "Start"; O "Motor"; A "Stop"; = "Motor"',
        net(par(c('"Start"'), c('"Motor"')), c('"Stop"'), outputs=[out(coil('"Motor"'))]),
    ),
    "nested brackets": (
        "A(; O I 0.0; O(; A I 0.1; A I 0.2; ); ); = Q 4.0",
        net(par(c("I 0.0"), s(c("I 0.1"), c("I 0.2")))),
    ),
    "status bits": ("A OV; AN ==0; = Q 4.0", net(st("OV"), st("==0", negated=True))),
    "not and edge": (
        "A I 0.0; NOT; FP M 1.0; = Q 4.0",
        net(c("I 0.0"), Invert(), EdgeContact(edge="P", memory="M 1.0")),
    ),
    "midline": (
        "A I 0.0; = M 2.0; A M 2.0; A I 0.1; = Q 4.0",
        net(c("I 0.0"), Midline(operand="M 2.0"), c("I 0.1")),
    ),
    "compare then coil": (
        "L MW 10; L 5; >I; = M 0.0",
        net(box("CMP>I", IN1="MW 10", IN2="5"), outputs=[out(coil("M 0.0"))]),
    ),
    "several coils": (
        "A I 0.0; = Q 4.0; S M 0.1; R M 0.2",
        net(
            c("I 0.0"),
            outputs=[out(coil("Q 4.0")), out(coil("M 0.1", "S")), out(coil("M 0.2", "R"))],
        ),
    ),
    "timer coil alone": (
        "A I 0.0; L S5T#5S; SD T 1",
        net(c("I 0.0"), outputs=[out(coil("T 1", "SD", "S5T#5S"))]),
    ),
    # STEP 7 shows a timer whose status is read right after it as the S_ODT box, Q -> coil
    "timer read back is a box": (
        "A I 0.0; L S5T#5S; SD T 1; A T 1; = Q 4.0",
        net(c("I 0.0"), box("S_ODT", "T 1", TV="S5T#5S")),
    ),
    "timer with reset": (
        "A I 0.0; L S5T#10S; SD T 1; A I 0.1; R T 1; A T 1; = Q 2.0",
        net(c("I 0.0"), box("S_ODT", "T 1", TV="S5T#10S", R="I 0.1"), outputs=[out(coil("Q 2.0"))]),
    ),
    "up/down counter": (
        "A I 0.0; CU C 1; A I 0.1; CD C 1; A I 0.2; L C#10; S C 1; A I 0.3; R C 1; A C 1; = Q 2.0",
        net(
            c("I 0.0"),
            box("S_CUD", "C 1", CD="I 0.1", S="I 0.2", PV="C#10", R="I 0.3"),
            outputs=[out(coil("Q 2.0"))],
        ),
    ),
    "set/reset latch": (
        "A I 0.0; S M 0.0; A I 0.1; R M 0.0",
        net(c("I 0.0"), outputs=[out(box("SR", "M 0.0", R1="I 0.1"))]),
    ),
    "move": ("L MW 0; T MW 2", net(outputs=[out(box("MOVE", IN="MW 0", OUT="MW 2"))])),
    "math": (
        "L MW 0; L 5; +I; T MW 2",
        net(outputs=[out(box("ADD_I", IN1="MW 0", IN2="5", OUT="MW 2"))]),
    ),
    "shift by a constant": (
        "L 200; SRW 3; T QW 2",
        net(outputs=[out(box("SHR_W", IN="200", N="3", OUT="QW 2"))]),
    ),
    "conditional jump": ("A I 0.0; JC M001", net(c("I 0.0"), outputs=[out(Jump(label="M001"))])),
    "jump from the rail": ("JU M001", net(outputs=[out(Jump(label="M001"))])),
    "conditional return": ("AN I 0.0; BEC", net(nc("I 0.0"), outputs=[out(Return())])),
    "label at the start": ("M001: A I 0.0; = Q 4.0", net(c("I 0.0"), label="M001")),
    "german mnemonics": (
        "U E 0.0; UN E 0.1; O; U M 0.0; = A 4.0",
        net(par(s(c("E 0.0"), nc("E 0.1")), c("M 0.0")), outputs=[out(coil("A 4.0"))]),
    ),
}


@pytest.mark.parametrize("name", list(SHAPES))
def test_a_network_of_lad_shape_lifts(name: str) -> None:
    code, expected = SHAPES[name]
    lifted = lift(code.replace("; ", "\n"))
    assert plain(lifted) == plain(expected), lifted


def test_title_comment_and_call_pins_come_from_the_source() -> None:
    text = """FUNCTION FC 10 : INT
VAR_INPUT
  Speed : INT;
END_VAR
VAR_OUTPUT
  Alarm : BOOL;
END_VAR
BEGIN
NETWORK
      L     #Speed;
      T     #RET_VAL;
END_FUNCTION

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = Call the scaling
//first line
//second line
      A     I 0.0;
      JNB   _001;
      CALL  FC 10 (
           Speed := MW 0,
           Alarm := M 1.0,
           RET_VAL := MW 2);
_001: A     BR;
      =     Q 4.0;
END_ORGANIZATION_BLOCK
"""
    result = lift_block(text, "call.awl")
    fc, ob = result.blocks
    assert (fc.kind, fc.name, ob.kind, ob.name) == ("FC", "FC 10", "OB", "OB 1")
    [network] = ob.networks
    assert isinstance(network, Network)
    assert (network.title, network.comment) == ("Call the scaling", "first line\nsecond line")
    called = box("FC 10", Speed="MW 0", Alarm="M 1.0", RET_VAL="MW 2")
    called = called.model_copy(update={"inputs": {"Speed": "MW 0"}})
    called = called.model_copy(update={"outputs": {"Alarm": "M 1.0", "RET_VAL": "MW 2"}})
    assert plain(network) == plain(net(c("I 0.0"), called))
    assert result.counts() == (2, 0)
    lad = ob.lad()
    assert lad is not None
    assert lad.networks == [network]


def test_code_outside_blocks_is_ob1_and_a_mixed_block_has_no_lad_form() -> None:
    result = lift_block("A I 0.0\n= Q 4.0\nNETWORK\nCLR\n", "loose.awl")
    [block] = result.blocks
    assert block.name == "OB 1"
    assert not block.converted()
    assert block.lad() is None
    assert isinstance(block.networks[1], NotConvertible)
    assert [d.code for d in result.diagnostics] == ["LAD310"]
    assert result.diagnostics[0].span is not None
    assert result.diagnostics[0].span.network == 2
