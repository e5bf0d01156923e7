"""Every generated STL line names the LAD element it belongs to (``lower_block(...).elements``):
monitoring reads an element's status from its lines, and the STL compiler's problems land on
the element. One case per element kind and box family."""

from __future__ import annotations

import pytest

from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    LadBlock,
    Midline,
    Network,
    OpenDb,
    Output,
    Parallel,
    Return,
    Series,
    StatusContact,
)
from nasaq.lang.lad.text import number_network
from nasaq.lang.lad.to_stl import lower_block
from nasaq.lang.stl import SourceFile, compile_sources


def s(*elements: Element) -> Series:
    return Series(elements=list(elements))


def c(operand: str, negated: bool = False) -> Contact:
    return Contact(operand=operand, negated=negated)


def rung(*logic: Element, outputs: list[Final | Output]) -> Network:
    """A network numbered as a parsed file numbers it (e1, e2 ... in reading order)."""
    ends = [o if isinstance(o, Output) else Output(target=o) for o in outputs]
    return number_network(Network(logic=s(*logic), outputs=ends))


def owned(network: Network) -> list[tuple[str, str | None]]:
    """(the line with its blanks closed up, its element) of the network's instructions."""
    lowered = lower_block(LadBlock(kind="FC", name="FC 1", return_type="VOID", networks=[network]))
    assert lowered.diagnostics == []
    lines = lowered.text.rstrip("\n").split("\n")
    assert len(lines) == len(lowered.elements)
    start = lines.index("NETWORK") + 2  # after NETWORK and its TITLE
    return [(" ".join(line.split()), lowered.elements[k]) for k, line in enumerate(lines)][start:-1]


Q = Coil(coil="=", operand="Q 4.0")

CASES: dict[str, tuple[Network, list[tuple[str, str | None]]]] = {
    "contacts, status, NOT, edge, midline, coil": (
        rung(
            c("I 0.0"),
            c("I 0.1", negated=True),
            StatusContact(bit="OV"),
            Invert(),
            EdgeContact(edge="P", memory="M 0.0"),
            Midline(operand="M 0.1"),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("AN I 0.1", "e2"),
            ("A OV", "e3"),
            ("NOT", "e4"),
            ("FP M 0.0", "e5"),
            ("= M 0.1", "e6"),
            ("A M 0.1", "e6"),
            ("= Q 4.0", "e7"),
        ],
    ),
    "a parallel alone: its branches' contacts, its O": (
        rung(
            Parallel(branches=[s(c("I 0.0")), s(c("I 0.1"), c("I 0.2"))]),
            outputs=[Q],
        ),
        [("O I 0.0", "e2"), ("O", "e1"), ("A I 0.1", "e3"), ("A I 0.2", "e4"), ("= Q 4.0", "e5")],
    ),
    "a parallel after a contact: its brackets": (
        rung(
            c("I 0.0"),
            Parallel(
                branches=[s(c("I 0.1")), s(Parallel(branches=[s(c("M 0.0")), s(c("M 0.1"))]))]
            ),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("A(", "e2"),
            ("O I 0.1", "e3"),
            ("O(", "e2"),
            ("O M 0.0", "e5"),
            ("O M 0.1", "e6"),
            (")", "e2"),
            (")", "e2"),
            ("= Q 4.0", "e7"),
        ],
    ),
    "a parallel acting on the flow: its flow temporary": (
        rung(
            c("I 0.0"),
            Parallel(branches=[s(c("I 0.1"), Invert()), s(c("I 0.2"))]),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("= #_lad_t0", "e2"),
            ("A(", "e2"),
            ("O(", "e2"),
            ("A #_lad_t0", "e2"),
            ("A I 0.1", "e3"),
            ("NOT", "e4"),
            (")", "e2"),
            ("O", "e2"),
            ("A #_lad_t0", "e2"),
            ("A I 0.2", "e5"),
            (")", "e2"),
            ("= Q 4.0", "e6"),
        ],
    ),
    "several outputs: the common temporary is no element's": (
        rung(
            c("I 0.0"),
            outputs=[
                Output(conditions=s(c("I 0.1")), target=Q),
                Output(target=Coil(coil="S", operand="M 0.0")),
            ],
        ),
        [
            ("A I 0.0", "e1"),
            ("= #_lad_t0", None),
            ("A #_lad_t0", None),
            ("A I 0.1", "e2"),
            ("= Q 4.0", "e3"),
            ("A #_lad_t0", None),
            ("S M 0.0", "e4"),
        ],
    ),
    "several plain coils: one chain": (
        rung(c("I 0.0"), outputs=[Q, Coil(coil="R", operand="M 0.0"), Coil(coil="SAVE")]),
        [("A I 0.0", "e1"), ("= Q 4.0", "e2"), ("R M 0.0", "e3"), ("SAVE", "e4")],
    ),
    "timer and counter coils from the rail": (
        rung(
            outputs=[
                Coil(coil="SD", operand="T 1", value="S5T#1S"),
                Coil(coil="SC", operand="C 1", value="C#5"),
            ]
        ),
        [
            ("SET", "e1"),
            ("L S5T#1S", "e1"),
            ("SD T 1", "e1"),
            ("L C#5", "e2"),
            ("S C 1", "e2"),
        ],
    ),
    "jumps, RET and OPN": (
        rung(outputs=[OpenDb(block="DB 1")]),
        [("OPN DB 1", "e1")],
    ),
    "a conditional jump": (
        rung(c("I 0.0"), outputs=[Jump(label="M001")]),
        [("A I 0.0", "e1"), ("JC M001", "e2")],
    ),
    "JMPN from the rail": (
        rung(outputs=[Jump(label="M001", negated=True)]),
        [("SET", "e1"), ("JCN M001", "e1")],
    ),
    "RET": (rung(c("I 0.0"), outputs=[Return()]), [("A I 0.0", "e1"), ("BEC", "e2")]),
    "a compare box": (
        rung(c("I 0.0"), Box(name="CMP>=I", inputs={"IN1": "MW 0", "IN2": "5"}), outputs=[Q]),
        [
            ("A I 0.0", "e1"),
            ("A(", "e2"),
            ("L MW 0", "e2"),
            ("L 5", "e2"),
            (">=I", "e2"),
            (")", "e2"),
            ("= Q 4.0", "e3"),
        ],
    ),
    "an EN/ENO box in the chain, EN fed by logic on its pin": (
        rung(
            c("I 0.0"),
            Box(
                name="ADD_I",
                inputs={"EN": s(c("I 0.1")), "IN1": "MW 0", "IN2": "1"},
                outputs={"OUT": "MW 2", "ENO": "M 0.0"},
            ),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("A I 0.1", "e3"),
            ("JNB _001", "e2"),
            ("L MW 0", "e2"),
            ("L 1", "e2"),
            ("+I", "e2"),
            ("T MW 2", "e2"),
            ("AN OV", "e2"),
            ("SAVE", "e2"),
            ("CLR", "e2"),
            ("_001: A BR", "e2"),
            ("= M 0.0", "e2"),
            ("A M 0.0", "e2"),
            ("= Q 4.0", "e4"),
        ],
    ),
    "MOVE, conversion, word logic and shift boxes ending rungs": (
        rung(
            c("I 0.0"),
            outputs=[
                Output(target=Box(name="MOVE", inputs={"IN": "1"}, outputs={"OUT": "MW 0"})),
                Output(target=Box(name="I_DI", inputs={"IN": "MW 0"}, outputs={"OUT": "MD 4"})),
                Output(
                    target=Box(
                        name="WAND_W",
                        inputs={"IN1": "MW 0", "IN2": "W#16#F"},
                        outputs={"OUT": "MW 8"},
                    )
                ),
                Output(
                    target=Box(
                        name="SHL_W", inputs={"IN": "MW 0", "N": "2"}, outputs={"OUT": "MW 10"}
                    )
                ),
            ],
        ),
        [
            ("A I 0.0", "e1"),
            ("= #_lad_t0", None),
            ("A #_lad_t0", None),
            ("JNB _001", "e2"),
            ("L 1", "e2"),
            ("T MW 0", "e2"),
            ("_001: NOP 0", "e2"),
            ("A #_lad_t0", None),
            ("JNB _002", "e3"),
            ("L MW 0", "e3"),
            ("ITD", "e3"),
            ("T MD 4", "e3"),
            ("_002: NOP 0", "e3"),
            ("A #_lad_t0", None),
            ("JNB _003", "e4"),
            ("L MW 0", "e4"),
            ("L W#16#F", "e4"),
            ("AW", "e4"),
            ("T MW 8", "e4"),
            ("_003: NOP 0", "e4"),
            ("A #_lad_t0", None),
            ("JNB _004", "e5"),
            ("L 2", "e5"),
            ("L MW 0", "e5"),
            ("SLW", "e5"),
            ("T MW 10", "e5"),
            ("_004: NOP 0", "e5"),
        ],
    ),
    "a timer box with logic on R": (
        rung(
            c("I 0.0"),
            Box(
                name="S_ODT",
                instance="T 1",
                inputs={"TV": "S5T#1S", "R": s(c("I 0.1"))},
                outputs={"BI": "MW 0"},
            ),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("L S5T#1S", "e2"),
            ("SD T 1", "e2"),
            ("A I 0.1", "e3"),
            ("R T 1", "e2"),
            ("L T 1", "e2"),
            ("T MW 0", "e2"),
            ("NOP 0", "e2"),
            ("A T 1", "e2"),
            ("= Q 4.0", "e4"),
        ],
    ),
    "a counter box": (
        rung(
            c("I 0.0"),
            Box(name="S_CU", instance="C 1", inputs={"S": "I 0.1", "PV": "C#3"}),
            outputs=[Q],
        ),
        [
            ("A I 0.0", "e1"),
            ("CU C 1", "e2"),
            ("BLD 101", "e2"),
            ("A I 0.1", "e2"),
            ("L C#3", "e2"),
            ("S C 1", "e2"),
            ("NOP 0", "e2"),
            ("NOP 0", "e2"),
            ("NOP 0", "e2"),
            ("A C 1", "e2"),
            ("= Q 4.0", "e3"),
        ],
    ),
    "a flip-flop from the rail": (
        rung(Box(name="SR", instance="M 0.0", inputs={"R1": "I 0.1"}), outputs=[Q]),
        [
            ("SET", "e1"),
            ("S M 0.0", "e1"),
            ("A I 0.1", "e1"),
            ("R M 0.0", "e1"),
            ("A M 0.0", "e1"),
            ("= Q 4.0", "e2"),
        ],
    ),
    "a POS box": (
        rung(c("I 0.0"), Box(name="POS", instance="I 0.1", inputs={"M_BIT": "M 0.0"}), outputs=[Q]),
        [
            ("A I 0.0", "e1"),
            ("A(", "e2"),
            ("A I 0.1", "e2"),
            ("FP M 0.0", "e2"),
            (")", "e2"),
            ("= Q 4.0", "e3"),
        ],
    ),
    "a call with a Boolean pin fed by logic": (
        rung(
            c("I 0.0"),
            outputs=[
                Box(
                    name="FC 2", inputs={"go": s(c("I 0.1"), c("I 0.2"))}, outputs={"done": "M 0.0"}
                )
            ],
        ),
        [
            ("A I 0.0", "e1"),
            ("= #_lad_t0", "e2"),
            ("A I 0.1", "e3"),
            ("A I 0.2", "e4"),
            ("= #_lad_t1", "e2"),
            ("A #_lad_t0", "e2"),
            ("JNB _001", "e2"),
            ("CALL FC 2 (", "e2"),
            ("go := #_lad_t1,", "e2"),
            ("done := M 0.0);", "e2"),
            ("_001: NOP 0", "e2"),
        ],
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_each_line_names_its_element(case: str) -> None:
    network, expected = CASES[case]
    assert owned(network) == expected


def test_a_label_and_a_network_kept_as_stl() -> None:
    labelled = number_network(Network(label="M001"))
    kept = Network(stl="      L     MW 0\n      T     MW 2", stl_reason="LAD318")
    block = LadBlock(kind="OB", name="OB 1", networks=[labelled, kept])
    lowered = lower_block(block)
    pairs = list(zip(lowered.text.rstrip("\n").split("\n"), lowered.elements, strict=True))
    assert ("M001: NOP   0", None) in pairs
    assert ("      L     MW 0", None) in pairs
    assert all(element is None for _, element in pairs)


def test_the_compiled_instructions_carry_the_elements() -> None:
    """``ir.Origin.element`` of a LAD file's instructions; ``Origin.line`` stays the generated
    STL line."""
    text = (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG Contact(I 0.0) Not Coil(Q 4.0) END_RUNG\n"
        "NETWORK\nRUNG Contact(I 0.1) Box(MOVE, IN := 3, OUT => MW 2) @move END_RUNG\n"
        "END_ORGANIZATION_BLOCK\n"
    )
    result = compile_sources([SourceFile("main.lad", text)])
    assert result.ok, result.diagnostics
    block = result.program.get(*next(iter(result.program.blocks)))
    assert block is not None
    seen = [
        (ins.op, ins.origin.network, ins.origin.element)
        for ins in block.code
        if ins.origin is not None
    ]
    assert seen == [
        ("A", 1, "e1"),
        ("NOT", 1, "e2"),
        ("=", 1, "e3"),
        ("A", 2, "e1"),
        ("JNB", 2, "move"),
        ("L", 2, "move"),
        ("T", 2, "move"),
        ("NOP", 2, "move"),
    ]
    assert all(ins.origin is not None and ins.origin.line > 3 for ins in block.code)
    stl = compile_sources(
        [
            SourceFile(
                "main.awl",
                "ORGANIZATION_BLOCK OB 1\nBEGIN\nA I 0.0\n= Q 4.0\nEND_ORGANIZATION_BLOCK\n",
            )
        ]
    )
    stl_block = stl.program.get(*next(iter(stl.program.blocks)))
    assert stl_block is not None
    assert {ins.origin.element for ins in stl_block.code if ins.origin} == {None}


def test_a_wrong_operand_type_on_a_contact_is_placed_on_the_contact() -> None:
    text = (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG Contact(I 0.0) END_RUNG\nNETWORK\n"
        "RUNG\n  Contact(I 0.0)\n  Contact(MW 10)\n  Coil(Q 4.0)\nEND_RUNG\n"
        "END_ORGANIZATION_BLOCK\n"
    )
    result = compile_sources([SourceFile("main.lad", text)])
    placed = [
        (d.code, d.span.file, d.span.line, d.span.network, d.span.element)
        for d in result.diagnostics
        if d.span is not None
    ]
    assert placed == [
        ("LAD211", "main.lad", 3, 1, None),
        ("STL204", "main.lad", 5, 2, "e2"),
    ]


def test_a_syntax_error_is_the_one_message_of_its_network() -> None:
    """A coil the reader drops for a missing bracket does not also make the rung "without an
    output": the syntax error is the one message; the other networks are still checked."""
    text = (
        "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\nRUNG\n  Contact(I 0.0)\n  Coil(Q 4.0\n"
        "END_RUNG\nNETWORK\nRUNG Contact(I 0.1) END_RUNG\nEND_ORGANIZATION_BLOCK\n"
    )
    result = compile_sources([SourceFile("main.lad", text)])
    placed = [(d.code, d.span.line, d.span.network) for d in result.diagnostics if d.span]
    assert placed == [("LAD111", 7, 1), ("LAD211", 8, 2)]
