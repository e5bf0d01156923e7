"""The STL text generated for typical networks, exactly (the shapes of STL_PATTERNS.md), and the
complete source of a block."""

from __future__ import annotations

from lad_to_stl_run import c, coil, net, par, s, stl_of

from nasaq.lang.lad.model import (
    Box,
    Coil,
    EdgeContact,
    Invert,
    Jump,
    LadBlock,
    Midline,
    Network,
    Output,
    Return,
    StatusContact,
)
from nasaq.lang.lad.to_stl import LabelMaker, block_to_stl, network_to_stl, stl_line
from nasaq.lang.stl import SourceFile, compile_sources


def lines(text: str) -> list[str]:
    """Expected lines written as ``op operand`` (``_001: A BR`` for a label), in STL columns."""
    out = []
    for row in text.strip().splitlines():
        row = row.strip()
        label = None
        if ":" in row and not row.startswith(("L ", "T ")) and ":=" not in row:
            label, row = (part.strip() for part in row.split(":", 1))
        op, _, operand = row.partition(" ")
        out.append(stl_line(op, operand.strip(), label))
    return out


def test_series_and_normally_closed_contacts() -> None:
    assert stl_of(net(c("I 0.0"), c("I 0.1", True))) == lines("A I 0.0\nAN I 0.1\n= Q 4.0")


def test_or_of_single_contacts_at_the_rail() -> None:
    assert stl_of(net(par(c("I 0.0"), c("I 0.1", True)))) == lines("O I 0.0\nON I 0.1\n= Q 4.0")


def test_and_groups_or_ed_with_o_without_operand() -> None:
    assert stl_of(net(par(s(c("I 0.0"), c("I 0.1")), c("I 0.2")))) == lines(
        "A I 0.0\nA I 0.1\nO I 0.2\n= Q 4.0"
    )
    assert stl_of(net(par(c("I 0.0"), s(c("I 0.1"), c("I 0.2", True))))) == lines(
        "O I 0.0\nO\nA I 0.1\nAN I 0.2\n= Q 4.0"
    )


def test_parallel_inside_a_series_is_bracketed() -> None:
    network = net(c("I 0.0"), par(c("I 0.1"), c("I 0.2")), c("I 0.3"))
    assert stl_of(network) == lines("A I 0.0\nA(\nO I 0.1\nO I 0.2\n)\nA I 0.3\n= Q 4.0")


def test_nested_parallel_in_an_and_group() -> None:
    network = net(par(s(c("I 0.0"), par(c("I 0.1"), c("I 0.2"))), c("I 0.3")))
    assert stl_of(network) == lines("A I 0.0\nA(\nO I 0.1\nO I 0.2\n)\nO I 0.3\n= Q 4.0")


def test_status_not_edge_and_midline() -> None:
    network = net(
        StatusContact(bit="OV"),
        Invert(),
        EdgeContact(edge="N", memory="M 1.0"),
        Midline(operand="M 2.0"),
        StatusContact(bit="==0", negated=True),
    )
    assert stl_of(network) == lines("A OV\nNOT\nFN M 1.0\n= M 2.0\nA M 2.0\nAN ==0\n= Q 4.0")


def test_several_outputs_without_and_with_conditions() -> None:
    assert stl_of(net(c("I 0.0"), outputs=[coil("Q 4.0"), coil("Q 4.1", "S")])) == lines(
        "A I 0.0\n= Q 4.0\nS Q 4.1"
    )
    outputs = [
        coil("Q 4.0"),
        Output(conditions=s(c("I 0.1")), target=Coil(coil="R", operand="Q 4.1")),
    ]
    assert stl_of(net(c("I 0.0"), outputs=outputs)) == lines(
        """A I 0.0
        = #_lad_t0
        A #_lad_t0
        = Q 4.0
        A #_lad_t0
        A I 0.1
        R Q 4.1"""
    )


def test_compare_box_in_the_chain() -> None:
    compare = Box(name="CMP>=I", inputs={"IN1": "MW 0", "IN2": "MW 2"})
    assert stl_of(net(c("I 0.0"), compare)) == lines("A I 0.0\nA(\nL MW 0\nL MW 2\n>=I\n)\n= Q 4.0")
    assert stl_of(net(compare)) == lines("L MW 0\nL MW 2\n>=I\n= Q 4.0")


def test_math_box_with_eno_and_a_move_ending_the_rung() -> None:
    add = Box(name="ADD_I", inputs={"IN1": "MW 0", "IN2": "MW 2"}, outputs={"OUT": "MW 4"})
    assert stl_of(net(c("I 0.0"), add)) == lines(
        """A I 0.0
        JNB _001
        L MW 0
        L MW 2
        +I
        T MW 4
        AN OV
        SAVE
        CLR
        _001: A BR
        = Q 4.0"""
    )
    move = Box(name="MOVE", inputs={"IN": "MW 0"}, outputs={"OUT": "MW 4"})
    assert stl_of(net(c("I 0.0"), outputs=[Output(target=move)])) == lines(
        "A I 0.0\nJNB _001\nL MW 0\nT MW 4\n_001: NOP 0"
    )
    assert stl_of(net(move, c("I 0.1"))) == lines(
        "L MW 0\nT MW 4\nSET\nSAVE\nCLR\nA BR\nA I 0.1\n= Q 4.0"
    )


def test_timer_box_with_unconnected_pins_and_timer_coil() -> None:
    timer = Box(
        name="S_ODT",
        instance="T 5",
        inputs={"TV": "S5T#5S", "R": "I 0.1"},
        outputs={"BCD": "MW 2"},
    )
    assert stl_of(net(c("I 0.0"), timer)) == lines(
        """A I 0.0
        L S5T#5S
        SD T 5
        A I 0.1
        R T 5
        NOP 0
        LC T 5
        T MW 2
        A T 5
        = Q 4.0"""
    )
    on_delay = Coil(coil="SD", operand="T 5", value="S5T#2S")
    assert stl_of(net(c("I 0.0"), outputs=[Output(target=on_delay)])) == lines(
        "A I 0.0\nL S5T#2S\nSD T 5"
    )


def test_counter_box_and_flip_flop() -> None:
    counter = Box(
        name="S_CU", instance="C 1", inputs={"S": "I 0.1", "PV": "C#10"}, outputs={"CV": "MW 0"}
    )
    assert stl_of(net(c("I 0.0"), counter)) == lines(
        """A I 0.0
        CU C 1
        BLD 101
        A I 0.1
        L C#10
        S C 1
        NOP 0
        L C 1
        T MW 0
        NOP 0
        A C 1
        = Q 4.0"""
    )
    flip_flop = Box(name="RS", instance="M 0.0", inputs={"S1": "I 0.1"})
    assert stl_of(net(c("I 0.0"), flip_flop)) == lines(
        "A I 0.0\nR M 0.0\nA I 0.1\nS M 0.0\nA M 0.0\n= Q 4.0"
    )


def test_edge_box_after_a_contact() -> None:
    pos = Box(name="POS", instance="I 0.1", inputs={"M_BIT": "M 1.0"})
    assert stl_of(net(c("I 0.0"), pos)) == lines("A I 0.0\nA(\nA I 0.1\nFP M 1.0\n)\n= Q 4.0")


def test_calls_with_instance_and_from_the_rail() -> None:
    call = Box(name="FB 5", instance="DB 10", inputs={"IN1": "MW 0"}, outputs={"OUT1": "MW 2"})
    assert stl_of(net(c("I 0.0"), outputs=[Output(target=call)])) == [
        *lines("A I 0.0\nJNB _001"),
        "      CALL  FB 5 , DB 10 (",
        "                 IN1                      := MW 0,",
        "                 OUT1                     := MW 2);",
        *lines("_001: NOP 0"),
    ]
    bare = Box(name='"Init"')
    assert stl_of(net(outputs=[Output(target=bare)])) == lines('CALL "Init"')
    multi = Box(name="FB 5", instance="#motor")
    assert stl_of(net(outputs=[Output(target=multi)])) == lines("CALL #motor")


def test_jumps_and_return() -> None:
    assert stl_of(net(outputs=[Output(target=Jump(label="M001"))])) == lines("JU M001")
    assert stl_of(net(c("I 0.0"), outputs=[Output(target=Jump(label="M001", negated=True))])) == (
        lines("A I 0.0\nJCN M001")
    )
    assert stl_of(net(c("I 0.0"), outputs=[Output(target=Return())])) == lines("A I 0.0\nBEC")
    assert stl_of(net(outputs=[Output(target=Return())])) == lines("BEU")


def test_labels_skip_the_users_and_number_through_the_block() -> None:
    maker = LabelMaker(taken=["_001"])
    move = Box(name="MOVE", inputs={"IN": "1"}, outputs={"OUT": "MW 0"})
    network = Network(logic=s(c("I 0.0")), outputs=[Output(target=move)])
    assert "_002: NOP   0" in network_to_stl(network, maker)[0]
    assert "_003: NOP   0" in network_to_stl(network, maker)[0]


def test_a_complete_fc_source_compiles() -> None:
    block = LadBlock(
        kind="FC",
        name="FC 3",
        title="Motor",
        declarations="VAR_INPUT\n  start : BOOL;\n  _lad_t0 : BOOL;\nEND_VAR",
        networks=[
            Network(
                title="Run",
                comment="keeps running\nuntil stopped",
                label="RUN",
                logic=s(c("#start")),
                outputs=[
                    coil("Q 4.0"),
                    Output(conditions=s(c("I 0.1")), target=coil("Q 4.1").target),
                ],
            )
        ],
    )
    text, diagnostics = block_to_stl(block)
    assert diagnostics == []
    assert text.splitlines()[:12] == [
        "FUNCTION FC 3 : VOID",
        "TITLE = Motor",
        "VAR_INPUT",
        "  start : BOOL;",
        "  _lad_t0 : BOOL;",
        "END_VAR",
        "VAR_TEMP",
        "  _lad2_t0 : BOOL;",  # the user's _lad_t0 is not reused
        "END_VAR",
        "BEGIN",
        "NETWORK",
        "TITLE = Run",
    ]
    assert "//keeps running" in text
    assert "RUN:  A     #start" in text
    assert text.endswith("END_FUNCTION\n")
    result = compile_sources([SourceFile("fc3.awl", text)])
    assert [d.code for d in result.diagnostics if d.severity == "error"] == []
