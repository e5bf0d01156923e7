"""The LAD/FBD text format: printing and reading back give the same model, the printed text is
stable, broken input gives one positioned diagnostic and reading goes on."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from lad_random import RandomNetworks
from lark import Lark, Tree
from lark.exceptions import LarkError

from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
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
from nasaq.lang.lad.text import number_network, parse_lad, print_lad

GRAMMAR = Path(__file__).resolve().parents[4] / "grammars" / "lad.lark"

MOTOR = """\
FUNCTION FC 10 : VOID
TITLE = Motor start/stop
VAR_INPUT
  Start : BOOL;   // BEGIN in a comment does not end the declarations
  Stop : BOOL;
END_VAR
BEGIN
NETWORK
TITLE = Self-holding
COMMENT = The motor holds itself
COMMENT = until Stop opens.
LABEL M001
RUNG
  PARALLEL
    BRANCH Contact(#Start) END_BRANCH
    BRANCH Contact("Motor") END_BRANCH
  END_PARALLEL
  Contact(#Stop)
  ContactNC("Overload")     (* a normally closed contact *)
  Coil("Motor")
END_RUNG
NETWORK
RUNG
  Contact(I0.1)
  Box(CMP>=I, IN1 := MW 10, IN2 := 100)
  Box(S_ODT, T_NO := T 5, TV := S5T#5S, R := RUNG Contact(I 0.2) Not END_RUNG,
      BI => MW 20, Q => DB1.DBX 0.0)
  OUTPUTS
    BRANCH Coil("Lamp") END_BRANCH
    BRANCH Contact(M 0.1) SetCoil(M 0.2) END_BRANCH
  END_OUTPUTS
END_RUNG
END_FUNCTION
"""


def numbered(block: LadBlock) -> LadBlock:
    return block.model_copy(update={"networks": [number_network(n) for n in block.networks]})


def round_trip(blocks: list[LadBlock], file: str = "test.lad") -> list[LadBlock]:
    parsed, problems = parse_lad(print_lad(blocks), file)
    assert problems == []
    return parsed


def every_element_block() -> LadBlock:
    """Every element kind, every final element, nesting of parallels and boxes, given ids."""
    nested = Parallel(
        branches=[
            Series(elements=[Contact(operand="I 1.0"), Invert()]),
            Series(),
            Series(
                elements=[
                    Parallel(
                        id="inner",
                        branches=[
                            Series(elements=[StatusContact(bit="OV")]),
                            Series(elements=[StatusContact(bit="<>0", negated=True)]),
                        ],
                    )
                ]
            ),
        ]
    )
    call = Box(
        name="FB 5",
        instance="DB 5",
        inputs={"EN_RUN": Series(elements=[nested, Contact(operand="M 1.1")]), "SPEED": "MW 4"},
        outputs={"DONE": "#done", "ERR": '"Data".err[2]'},
    )
    logic = Series(
        elements=[
            Contact(operand='"Start"'),
            Contact(operand="DB1.DBX 0.0", negated=True),
            EdgeContact(edge="P", memory="M 1.0"),
            EdgeContact(edge="N", memory="#edge"),
            Midline(operand="M 2.0"),
            call,
            Box(name="MOVE", inputs={"IN": "B#(1,2)"}, outputs={"OUT": "MW 12"}),
        ]
    )
    coils = [
        Coil(coil=kind, operand="T 1", value="S5T#2S") for kind in ("SP", "SE", "SD", "SS", "SF")
    ]
    coils += [
        Coil(coil="=", operand="Q 4.0"),
        Coil(coil="S", operand="Q 4.1"),
        Coil(coil="R", operand="#q"),
        Coil(coil="SD", operand="T 2"),
        Coil(coil="CU", operand="C 1"),
        Coil(coil="CD", operand="C 1"),
        Coil(coil="SC", operand="C 1", value="C#10"),
        Coil(coil="SAVE"),
    ]
    finals = [
        *coils,
        Jump(label="M001"),
        Jump(label="NEXT", negated=True, id="skip"),
        Return(),
        OpenDb(block="DB 10"),
        Box(name="SR", inputs={"S": "I 0.0", "R": Series(elements=[Contact(operand="I 0.1")])}),
    ]
    outputs = [
        Output(conditions=Series(elements=[Contact(operand=f"M 3.{n % 8}")]), target=final)
        if n % 2
        else Output(target=final)
        for n, final in enumerate(finals)
    ]
    networks = [
        Network(
            title="All", comment="line one\nline two", label="M001", logic=logic, outputs=outputs
        ),
        Network(logic=Series(elements=[Contact(operand="I 0.0")]), outputs=[outputs[1]]),
        Network(
            outputs=[Output(target=Box(name="MOVE", inputs={"IN": "0"}, outputs={"OUT": "MW 2"}))]
        ),
        Network(outputs=[Output(target=Jump(label="END"))]),
    ]
    block = LadBlock(
        kind="FB",
        name="FB 20",
        title="Everything",
        declarations="VAR_INPUT\n  x : BOOL;\nEND_VAR\nVAR\n  inst : FB 5;\nEND_VAR",
        networks=networks,
    )
    return numbered(block)


# ---- round trips ---------------------------------------------------------------------------


def test_every_element_kind_survives_print_and_parse() -> None:
    block = every_element_block()
    assert round_trip([block]) == [block]


def test_the_printer_leaves_out_generated_ids_and_keeps_given_ones() -> None:
    text = print_lad([every_element_block()])
    assert "@e" not in text
    assert "PARALLEL @inner" in text
    assert "JumpN(NEXT) @skip" in text


@pytest.mark.parametrize("seed", range(150))
def test_random_networks_survive_print_and_parse(seed: int) -> None:
    networks = RandomNetworks(seed)
    block = LadBlock(kind="OB", name="OB 1", networks=[networks.network() for _ in range(3)])
    assert round_trip([numbered(block)]) == [numbered(block)]


def test_fbd_blocks_and_headers_survive() -> None:
    blocks = [
        numbered(
            LadBlock(
                language="FBD",
                kind="FC",
                name='"Mixer"',
                return_type="INT",
                networks=[Network(outputs=[Output(target=Return())])],
            )
        ),
        LadBlock(kind="OB", name="OB 35", networks=[]),
    ]
    text = print_lad(blocks)
    assert "LANGUAGE FBD" in text
    assert round_trip(blocks) == blocks


def test_print_of_parse_is_stable() -> None:
    blocks, problems = parse_lad(MOTOR, "motor.lad")
    assert problems == []
    once = print_lad(blocks)
    again, problems = parse_lad(once, "motor.lad")
    assert problems == []
    assert again == blocks
    assert print_lad(again) == once


def test_the_example_reads_as_its_model() -> None:
    [block], problems = parse_lad(MOTOR, "motor.lad")
    assert problems == []
    assert (block.kind, block.name, block.return_type, block.language) == (
        "FC",
        "FC 10",
        "VOID",
        "LAD",
    )
    assert block.title == "Motor start/stop"
    assert block.declarations.startswith("VAR_INPUT\n  Start : BOOL;   // BEGIN in a comment")
    assert block.declarations.endswith("END_VAR")
    first, second = block.networks
    assert (first.title, first.label) == ("Self-holding", "M001")
    assert first.comment == "The motor holds itself\nuntil Stop opens."
    parallel = first.logic.elements[0]
    assert isinstance(parallel, Parallel)
    assert parallel.id == "e1"
    assert [b.elements[0].id for b in parallel.branches] == ["e2", "e3"]
    assert first.logic.elements[2] == Contact(id="e5", operand='"Overload"', negated=True)
    assert first.outputs == [Output(target=Coil(id="e6", coil="=", operand='"Motor"'))]
    timer = second.logic.elements[2]
    assert isinstance(timer, Box)
    assert timer.inputs["R"] == Series(
        elements=[Contact(id="e4", operand="I 0.2"), Invert(id="e5")]
    )
    assert timer.outputs == {"BI": "MW 20", "Q": "DB1.DBX 0.0"}
    assert second.logic.elements[0] == Contact(id="e1", operand="I0.1")
    assert second.outputs[1].conditions.elements[0].id == "e7"
    assert second.outputs[1].target == Coil(id="e8", coil="S", operand="M 0.2")


def test_language_follows_the_suffix_unless_the_block_says() -> None:
    text = "FUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\n"
    assert parse_lad(text, "a.fbd")[0][0].language == "FBD"
    assert parse_lad(text, "a.lad")[0][0].language == "LAD"
    said = "FUNCTION FC 1 : VOID\nLANGUAGE lad\nBEGIN\nEND_FUNCTION\n"
    assert parse_lad(said, "a.fbd")[0][0].language == "LAD"


def test_a_file_with_two_blocks() -> None:
    text = (
        MOTOR
        + "\nORGANIZATION_BLOCK OB 1\nTITLE = Main\nBEGIN\nNETWORK\nRUNG\n  CALL_FC\nEND_RUNG\n"
    )
    text += "NETWORK\nRUNG Box(FC 10) END_RUNG\nEND_ORGANIZATION_BLOCK\n"
    blocks, problems = parse_lad(text, "two.lad")
    assert [(b.kind, b.name) for b in blocks] == [("FC", "FC 10"), ("OB", "OB 1")]
    assert [p.code for p in problems] == ["LAD110"]
    # The unknown element is dropped; its rung stays, empty.
    assert blocks[1].networks == [
        Network(),
        Network(outputs=[Output(target=Box(id="e1", name="FC 10"))]),
    ]
    again, problems = parse_lad(print_lad(blocks), "two.lad")
    assert problems == []
    assert again == blocks


def test_explicit_ids_are_kept_and_clashes_reported() -> None:
    rung = "RUNG Contact(I 0.0) @start Not Coil(Q 0.0) @e2\nEND_RUNG\n"
    text = f"FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\n{rung}END_FUNCTION\n"
    [block], problems = parse_lad(text, "ids.lad")
    network = block.networks[0]
    assert [e.id for e in network.logic.elements] == ["start", "e2"]
    assert [(p.code, p.span.line, p.span.column) for p in problems if p.span] == [("LAD123", 4, 44)]
    assert problems[0].params == {"id": "e2"}


# ---- rungs being drawn ------------------------------------------------------------------------

UNFINISHED = """\
ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
TITLE = New
RUNG
END_RUNG
NETWORK
LABEL M001
RUNG
END_RUNG
NETWORK
RUNG
  Contact(I 0.0)
  PARALLEL
    BRANCH Contact(<??.?>) END_BRANCH
    BRANCH ContactNC(M 0.1) END_BRANCH
  END_PARALLEL
END_RUNG
NETWORK
RUNG
  Contact(I 0.0)
  Box(MOVE, IN := <???>, OUT => MW 2)
  OUTPUTS
  END_OUTPUTS
END_RUNG
NETWORK
RUNG
  Box(ADD_I, IN1 := MW 0, IN2 := 1, OUT => MW 0)
END_RUNG
END_ORGANIZATION_BLOCK
"""


def test_empty_and_unfinished_rungs_read_and_print_back_the_same() -> None:
    """A new network is an empty rung; contacts placed before their coil are logic without
    outputs. Both read without a problem and print back as they were, so an editor can save
    a network in any state (a rung ending in a box keeps its empty OUTPUTS, else the box
    would read back as the rung's final element)."""
    [block], problems = parse_lad(UNFINISHED, "draft.lad")
    assert problems == []
    empty, labelled, contacts, box_logic, box_final = block.networks
    assert empty == Network(title="New")
    assert labelled == Network(label="M001")
    assert contacts.outputs == []
    assert [e.kind for e in contacts.logic.elements] == ["contact", "parallel"]
    placeholder = contacts.logic.elements[1]
    assert isinstance(placeholder, Parallel)
    assert placeholder.branches[0].elements == [Contact(id="e3", operand="<??.?>")]
    assert box_logic.outputs == []
    assert [e.kind for e in box_logic.logic.elements] == ["contact", "box"]
    assert box_final.logic.elements == []
    assert [o.target.kind for o in box_final.outputs] == ["box"]
    assert print_lad([block]) == UNFINISHED
    assert reference().parse(UNFINISHED)


def test_an_empty_outputs_section_is_a_rung_without_outputs() -> None:
    text = "FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nRUNG Contact(I 0.0) OUTPUTS END_OUTPUTS "
    text += "END_RUNG\nEND_FUNCTION\n"
    [block], problems = parse_lad(text, "draft.lad")
    assert problems == []
    [network] = block.networks
    assert network.outputs == []
    assert network.logic.elements == [Contact(id="e1", operand="I 0.0")]


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 10_000))
def test_random_rungs_without_their_outputs_survive_print_and_parse(seed: int) -> None:
    network = RandomNetworks(seed).network().model_copy(update={"outputs": []})
    block = numbered(LadBlock(kind="FC", name="FC 3", return_type="VOID", networks=[network]))
    assert round_trip([block]) == [block]


# ---- errors --------------------------------------------------------------------------------

HEAD = "FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\n"
TAIL = "NETWORK\nRUNG Contact(I 9.9) Coil(Q 9.9) END_RUNG\nEND_FUNCTION\n"

BROKEN = [
    # (rung line(s) of network 1, code, line, column)
    ("RUNG Contakt(I 0.0) Coil(Q 0.0) END_RUNG", "LAD110", 4, 6),
    ("RUNG Contact I 0.0 Coil(Q 0.0) END_RUNG", "LAD111", 4, 14),
    ("RUNG Contact(I 0.0 Coil(Q 0.0) END_RUNG", "LAD111", 4, 20),
    ("RUNG Contact(I 0.0, I 0.1) Coil(Q 0.0) END_RUNG", "LAD112", 4, 6),
    ("RUNG Contact() Coil(Q 0.0) END_RUNG", "LAD112", 4, 6),
    ("RUNG Midline(M 0.0, ) Coil(Q 0.0) END_RUNG", "LAD112", 4, 6),
    ("RUNG Box(MOVE, IN := , OUT => MW 2) END_RUNG", "LAD113", 4, 22),
    ("RUNG Status(XY) Coil(Q 0.0) END_RUNG", "LAD114", 4, 13),
    ("RUNG Edge(Q, M 0.0) Coil(Q 0.0) END_RUNG", "LAD115", 4, 11),
    (
        "RUNG PARALLEL BRANCH Contact(I 0.0) END_BRANCH END_PARALLEL Coil(Q 0.0) END_RUNG",
        "LAD116",
        4,
        6,
    ),
    ("RUNG PARALLEL Contact(I 0.0) END_PARALLEL Coil(Q 0.0) END_RUNG", "LAD117", 4, 15),
    ("RUNG Coil(Q 0.0) Contact(I 0.0) Coil(Q 0.1) END_RUNG", "LAD118", 4, 6),
    (
        "RUNG PARALLEL BRANCH Coil(Q 0.0) END_BRANCH BRANCH END_BRANCH END_PARALLEL Save END_RUNG",
        "LAD119",
        4,
        22,
    ),
    (
        "RUNG Contact(I 0.0) OUTPUTS BRANCH Contact(I 0.1) END_BRANCH END_OUTPUTS END_RUNG",
        "LAD121",
        4,
        29,
    ),
    ("RUNG Box(SR, S := I 0.0, S := I 0.1) END_RUNG", "LAD122", 4, 26),
    ("RUNG Box(SR S := I 0.0) Coil(Q 0.0) END_RUNG", "LAD111", 4, 15),
    ("RUNG Box(SR, S := RUNG Contact(I 0.0), Q => M 0.0) Coil(Q 0.0) END_RUNG", "LAD109", 4, 38),
    ("RUNG Contact(I 0.0) Coil(Q 0.0) @ END_RUNG", "LAD128", 4, 33),
    ("RUNG Jump(12) END_RUNG", "LAD124", 4, 11),
    ('RUNG Contact("Start) Coil(Q 0.0) END_RUNG', "LAD127", 4, 14),
    ("TITLE = a\nTITLE = b\nRUNG Return END_RUNG", "LAD125", 5, 1),
    ("Contact(I 0.0) Coil(Q 0.0) END_RUNG", "LAD108", 4, 1),
    ("RUNG Contact(I 0.0) Coil(Q 0.0)", "LAD109", 5, 1),
    ("RUNG Save(M 0.0) Coil(Q 0.0) END_RUNG", "LAD112", 4, 6),
    ("RUNG Return (* never closed END_RUNG", "LAD126", 4, 13),
]


@pytest.mark.parametrize(("rung", "code", "line", "column"), BROKEN)
def test_a_broken_element_or_network_gives_one_diagnostic(
    rung: str, code: str, line: int, column: int
) -> None:
    blocks, problems = parse_lad(HEAD + rung + "\n" + TAIL, "bad.lad")
    assert [(p.code, p.span.line, p.span.column) for p in problems if p.span] == [
        (code, line, column)
    ]
    assert problems[0].span is not None
    assert problems[0].span.file == "bad.lad"
    assert problems[0].span.network == 1
    if code != "LAD126":  # an unclosed comment swallows the rest of the file
        [block] = blocks
        last = block.networks[-1]
        assert last.logic.elements[0] == Contact(id="e1", operand="I 9.9")


@pytest.mark.parametrize(
    ("text", "codes"),
    [
        ("FUNCTION FC 1\nBEGIN\nEND_FUNCTION\n", ["LAD103"]),
        ("FUNCTION FB 1 : VOID\nBEGIN\nEND_FUNCTION\n", ["LAD102"]),
        ("FUNCTION FC 1 : VOID\nLANGUAGE STL\nBEGIN\nEND_FUNCTION\n", ["LAD104"]),
        (
            "FUNCTION FC 1 : VOID\nVAR_TEMP x : INT; END_VAR\n"
            "NETWORK\nRUNG Return END_RUNG\nEND_FUNCTION\n",
            ["LAD105"],
        ),
        ("FUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION_BLOCK\n", ["LAD106"]),
        ("FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nRUNG Return END_RUNG\n", ["LAD106"]),
        ("FUNCTION FC 1 : VOID\nBEGIN\nRUNG Return END_RUNG\nEND_FUNCTION\n", ["LAD107"]),
        ("hello\nFUNCTION FC 1 : VOID\nBEGIN\nEND_FUNCTION\n", ["LAD101"]),
        (
            "FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nLABEL 12\nRUNG Return END_RUNG\nEND_FUNCTION\n",
            ["LAD124"],
        ),
        ("FUNCTION FC 1 : VOID\nBEGIN\nNETWORK\nRUNG Contact(I 0.0", ["LAD111"]),
    ],
)
def test_broken_blocks(text: str, codes: list[str]) -> None:
    _, problems = parse_lad(text, "bad.lad")
    assert [p.code for p in problems] == codes
    assert all(p.span is not None and p.span.line is not None for p in problems)


def test_reading_goes_on_after_a_broken_block() -> None:
    text = "FUNCTION FC : VOID\nBEGIN\nNETWORK\nRUNG Contact(I 0.0)\n" + MOTOR
    blocks, problems = parse_lad(text, "bad.lad")
    assert [p.code for p in problems] == ["LAD102", "LAD109", "LAD106"]
    assert [b.name for b in blocks] == ["FC 10"]


@settings(max_examples=300, deadline=None)
@given(st.data())
def test_mangled_text_never_raises(data: st.DataObject) -> None:
    """Cutting, doubling and replacing pieces of a valid file gives diagnostics, never an
    exception, and every diagnostic has a position."""
    text = MOTOR
    for _ in range(data.draw(st.integers(1, 4))):
        start = data.draw(st.integers(0, len(text)))
        end = data.draw(st.integers(start, min(len(text), start + 12)))
        piece = data.draw(
            st.sampled_from(
                ["", "(", ")", ",", "@", '"', "(*", "END_RUNG", "RUNG", text[start:end]]
            )
        )
        text = text[:start] + piece + text[end:]
    blocks, problems = parse_lad(text, "fuzz.lad")
    assert all(p.span is not None and p.span.line and p.span.column for p in problems)
    assert print_lad(blocks).count("END_RUNG") >= sum(len(b.networks) for b in blocks)


# ---- networks that stay STL ----------------------------------------------------------------

STL_NETWORK = """FUNCTION FC 1 : VOID
BEGIN
NETWORK
TITLE = A value moved: no LAD shape here
STL REASON LAD305
      L     MW 10
M001: T     MW 12
END_STL
NETWORK
RUNG
  Contact(I 0.0)
  Coil(Q 0.0)
END_RUNG
END_FUNCTION
"""


def test_a_network_without_lad_shape_keeps_its_stl_lines_and_reason() -> None:
    blocks, problems = parse_lad(STL_NETWORK, "kept.lad")
    assert problems == []
    kept, rung = blocks[0].networks
    assert kept.stl == "      L     MW 10\nM001: T     MW 12"
    assert kept.stl_reason == "LAD305"
    assert not kept.outputs
    assert rung.outputs
    assert print_lad(blocks) == STL_NETWORK


def test_an_stl_network_without_its_end_is_reported() -> None:
    text = STL_NETWORK.replace("END_STL\n", "")
    _blocks, problems = parse_lad(text, "open.lad")
    assert [p.code for p in problems] == ["LAD129"]


# ---- the grammar is the reference -----------------------------------------------------------


def reference() -> Lark:
    return Lark(GRAMMAR.read_text("utf-8"), parser="lalr", lexer="contextual")


def test_the_grammar_reads_every_valid_text_the_parser_reads() -> None:
    texts = [
        MOTOR,
        print_lad([every_element_block()]),
        "FUNCTION FC 1 : INT\nLANGUAGE FBD BEGIN END_FUNCTION",
        STL_NETWORK,
    ]
    texts += [
        print_lad(
            [numbered(LadBlock(kind="OB", name="OB 1", networks=[RandomNetworks(s).network()]))]
        )
        for s in range(40)
    ]
    used: set[str] = set()
    for text in texts:
        tree = reference().parse(text)
        used |= {str(sub.data) for sub in tree.iter_subtrees() if isinstance(sub, Tree)}
    rules = {str(rule.alias or rule.origin.name) for rule in reference().rules}
    rules = {name for name in rules if not name.startswith("_")}
    assert rules - {"start"} <= used


def test_the_grammar_names_every_element_kind_of_the_model() -> None:
    """Each kind of the model (its ``kind`` literal) has its rule in the grammar."""
    rules = {str(rule.origin.name) for rule in reference().rules}
    kinds = {
        "contact": {"contact", "contact_nc"},
        "status": {"status", "status_nc"},
        "not": {"invert"},
        "edge": {"edge"},
        "midline": {"midline"},
        "box": {"box", "in_pin", "logic_pin", "out_pin"},
        "parallel": {"parallel", "branch"},
        "coil": {"coil", "set_coil", "reset_coil", "timer_coil", "counter_coil", "save"},
        "jump": {"jump", "jump_n"},
        "ret": {"ret"},
        "opn": {"open_db"},
    }
    model_kinds = {
        cls.model_fields["kind"].default
        for cls in (
            Contact,
            StatusContact,
            Invert,
            EdgeContact,
            Midline,
            Box,
            Parallel,
            Coil,
            Jump,
            Return,
            OpenDb,
        )
    }
    assert model_kinds == set(kinds)
    for names in kinds.values():
        assert names <= rules


def test_the_grammar_rejects_what_the_parser_rejects() -> None:
    checks = {"LAD114", "LAD115", "LAD122", "LAD125"}  # the reader's checks, not syntax
    for rung, code, *_ in BROKEN:
        if code in checks:
            continue
        with pytest.raises(LarkError):
            reference().parse(HEAD + rung + "\n" + TAIL)


PIECES = [
    "FUNCTION FC 1 : VOID\n", "FUNCTION_BLOCK FB 2\n", "BEGIN\n", "END_FUNCTION\n", "NETWORK\n",
    "TITLE = t\n", "LABEL L1\n", "COMMENT = c\n", "LANGUAGE FBD\n", "RUNG ", "END_RUNG\n",
    "OUTPUTS ", "END_OUTPUTS ", "PARALLEL ", "END_PARALLEL ", "BRANCH ", "END_BRANCH ",
    "Contact(I 0.0) ", "ContactNC(", "Status(OV) ", "Edge(P, M 1.0) ", "Not ", "Midline(M 2.0) ",
    "Box(SR, S := ", "Box(MOVE, IN := 1, OUT => MW 2) ", "INSTANCE DB 1", "Coil(Q 0.0) ",
    "SD(T 1, ",
    "Save ", "Jump(L1) ", "Return ", "Open(DB 1) ", "(", ")", ",", ":=", "=>", "@x ", "@", '"',
    "'", "(*", "*)", "//", "\n", "VAR x : INT; END_VAR\n",
]  # fmt: skip


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(PIECES), max_size=40))
def test_any_sequence_of_pieces_reads_without_exception(pieces: list[str]) -> None:
    """Whatever the order of the format's pieces, reading ends with blocks and positioned
    diagnostics, and what was read prints and reads back the same."""
    blocks, problems = parse_lad("".join(pieces), "pieces.fbd")
    assert all(p.span is not None and p.span.line and p.span.column for p in problems)
    if not problems:
        assert parse_lad(print_lad(blocks), "pieces.fbd") == (blocks, [])


def test_header_attributes_and_declarations_are_kept_verbatim() -> None:
    declarations = (
        "{ S7_language := 'LAD' }\nAUTHOR : Student\nFAMILY : Lab\nNAME : Motor\nVERSION : 0.1\n"
        "KNOW_HOW_PROTECT\nVAR_INPUT\n  text : STRING[8] := 'BEGIN';  (* BEGIN here is text *)\n"
        '  "BEGIN" : BOOL;\nEND_VAR'
    )
    text = f'FUNCTION_BLOCK "Motor"\nTITLE = Drive\n{declarations}\n  BEGIN\nEND_FUNCTION_BLOCK\n'
    [block], problems = parse_lad(text, "motor.lad")
    assert problems == []
    assert (block.kind, block.name, block.title) == ("FB", '"Motor"', "Drive")
    assert block.declarations == declarations
    assert parse_lad(print_lad([block]), "motor.lad") == ([block], [])
