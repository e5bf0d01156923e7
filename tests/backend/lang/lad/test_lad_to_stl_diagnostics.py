"""Bad networks give a catalogued diagnostic with the network number and element id, never an
exception, and the rest of the block still lowers."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lad_to_stl_run import c, coil, net, ob1, par, s

from nasaq.lang.lad.boxes import CATALOGUE
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Invert,
    Midline,
    Network,
    OpenDb,
    Output,
    Series,
)
from nasaq.lang.lad.to_stl import block_to_stl
from nasaq.lang.stl import SourceFile, compile_sources


def problems(network: Network) -> list[tuple[str, int | None, str]]:
    text, diagnostics = block_to_stl(ob1(net(c("I 1.0"), outputs=[coil("Q 5.0")]), network))
    assert "A     I 1.0" in text  # the good network still lowers
    return [(d.code, d.span.network if d.span else None, d.params["element"]) for d in diagnostics]


def ends(target: Box | Coil | OpenDb) -> list[Output]:
    return [Output(target=target)]


@pytest.mark.parametrize(
    ("network", "code"),
    [
        (net(Box(id="b1", name="ADD_X")), "LAD201"),
        (
            net(Box(id="b1", name="MOVE", inputs={"IN": "1", "FOO": "2"}, outputs={"OUT": "MW 0"})),
            "LAD202",
        ),
        (
            net(
                Box(id="b1", name="MOVE", inputs={"IN": "1"}, outputs={"OUT": "MW 0", "IN": "MW 2"})
            ),
            "LAD202",
        ),
        (net(Box(id="b1", name="ADD_I", inputs={"IN1": "1"}, outputs={"OUT": "MW 0"})), "LAD203"),
        (net(Box(id="b1", name="S_ODT", instance="T 1")), "LAD203"),
        (
            net(
                Box(
                    id="b1",
                    name="ADD_I",
                    inputs={"IN1": s(c("I 0.0")), "IN2": "1"},
                    outputs={"OUT": "MW 0"},
                )
            ),
            "LAD204",
        ),
        (net(Invert(id="b1")), "LAD205"),
        (net(Midline(id="b1", operand="M 0.0")), "LAD205"),
        (net(par(s(EdgeContact(id="b1", edge="P", memory="M 0.0")), c("I 0.0"))), "LAD205"),
        (net(Box(id="b1", name="SR", inputs={"R1": "I 0.0"})), "LAD208"),
        (net(c("I 0.0"), outputs=ends(Box(id="b1", name="SFB 4"))), "LAD209"),
        (net(c("I 0.0"), outputs=ends(Coil(id="b1", coil="SD", operand="T 1"))), "LAD210"),
        (net(c("I 0.0"), outputs=ends(Coil(id="b1", coil="="))), "LAD210"),
        (net(c("I 0.0"), outputs=ends(OpenDb(id="b1", block="DB 1"))), "LAD207"),
    ],
)
def test_problem_has_code_network_and_element(network: Network, code: str) -> None:
    assert problems(network) == [(code, 2, "b1")]


LOCALES = Path(__file__).resolve().parents[4] / "frontend" / "src" / "i18n" / "locales"


@pytest.mark.parametrize("language", ["en", "ar", "fa", "vi"])
def test_every_word_a_problem_names_is_translated(language: str) -> None:
    """``what`` in LAD205/LAD208/LAD210 is a key of ``problemWords``, which the messages nest
    (``$t(problemWords.{{what}})``), so no English word shows in a translated message."""
    words = json.loads((LOCALES / f"{language}.json").read_text("utf-8"))["problemWords"]
    networks = [
        net(Invert(id="b1")),
        net(Midline(id="b1", operand="M 0.0")),
        net(par(s(EdgeContact(id="b1", edge="P", memory="M 0.0")), c("I 0.0"))),
        net(c("I 0.0"), outputs=ends(Coil(id="b1", coil="SD", operand="T 1"))),
        net(c("I 0.0"), outputs=ends(Coil(id="b1", coil="="))),
        *(
            net(Box(id="b1", name=name))
            for name, spec in sorted(CATALOGUE.items())
            if spec.address is not None
        ),
    ]
    said = set()
    for network in networks:
        _, diagnostics = block_to_stl(ob1(network))
        said |= {d.params["what"] for d in diagnostics if "what" in d.params}
    assert said == {"NOT", "midline", "edge", "value", "operand", "timer", "counter", "bit"}
    assert said <= set(words), said - set(words)


def test_empty_branch_is_a_short_circuit() -> None:
    network = net(c("I 0.0"), par(Series(), c("I 0.1")).model_copy(update={"id": "p1"}))
    assert problems(network) == [("LAD206", 2, "p1")]


def test_a_block_with_problems_still_yields_compilable_stl() -> None:
    block = ob1(
        net(Box(id="x", name="NOPE"), c("I 0.0")),
        net(c("I 0.1"), outputs=[coil("Q 4.1")]),
    )
    text, diagnostics = block_to_stl(block)
    assert [d.code for d in diagnostics] == ["LAD201"]
    assert "Network 1, element x" in diagnostics[0].message
    result = compile_sources([SourceFile("bad.awl", text)])
    assert [d.code for d in result.diagnostics if d.severity == "error"] == []


OPERANDS = {
    "BOOL": "M 0.1",
    "INT": "MW 10",
    "DINT": "MD 20",
    "REAL": "MD 30",
    "WORD": "MW 40",
    "DWORD": "MD 50",
    "S5TIME": "S5T#1S",
    "ANY": "MW 60",
}
ADDRESSES = {"timer": "T 1", "counter": "C 1", "bit": "M 1.0"}


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_every_box_with_all_pins_lowers_to_compilable_stl(name: str) -> None:
    spec = CATALOGUE[name]
    inputs: dict[str, str | Series] = {
        p.name: OPERANDS[p.type] for p in spec.inputs if p.name != "EN"
    }
    outputs = {p.name: OPERANDS[p.type].replace("0", "2") for p in spec.outputs}
    address = ADDRESSES[spec.address] if spec.address else None
    full = Box(id="b", name=name, instance=address, inputs=inputs, outputs=outputs)
    bare = Box(id="b", name=name, instance=address)
    block = ob1(net(c("I 0.0"), full), net(c("I 0.0"), outputs=ends(full)), net(bare))
    text, diagnostics = block_to_stl(block)
    assert all(d.code in ("LAD203",) for d in diagnostics), diagnostics
    result = compile_sources([SourceFile("all.awl", text)])
    assert [d.message for d in result.diagnostics if d.severity == "error"] == [], text


# ---- rungs being drawn ------------------------------------------------------------------------


def test_an_empty_rung_lowers_to_an_empty_network() -> None:
    text, diagnostics = block_to_stl(ob1(Network(), Network(label="M001")))
    assert diagnostics == []
    assert text.split("BEGIN\n")[1] == (
        "NETWORK\nTITLE =\nNETWORK\nTITLE =\nM001: NOP   0\nEND_ORGANIZATION_BLOCK\n"
    )


def test_logic_without_an_output_is_reported_on_its_network_and_lowers_to_nothing() -> None:
    unfinished = Network(logic=s(c("I 0.0"), par(c("I 0.1"), c("I 0.2"))), label="M002")
    text, diagnostics = block_to_stl(ob1(net(c("I 1.0")), unfinished))
    assert [(d.code, d.span.network if d.span else None) for d in diagnostics] == [("LAD211", 2)]
    assert diagnostics[0].message == (
        "Network 2: the rung has no output yet (a coil, a jump, RET, OPN or a box at its end)."
    )
    assert diagnostics[0].params == {"network": 2}
    assert "I 0.1" not in text
    assert "M002: NOP   0" in text  # the label stays a jump target
    result = compile_sources([SourceFile("draft.awl", text)])
    assert [d.code for d in result.diagnostics if d.severity == "error"] == []


BIT, ANY = "<??.?>", "<???>"
PLACEHOLDERS = [
    # (the network, [(element, what, pin)] reported in reading order)
    (net(Contact(id="x", operand=BIT)), [("x", "bit", None)]),
    (net(c("I 0.0"), Midline(id="x", operand=BIT)), [("x", "bit", None)]),
    (net(c("I 0.0"), EdgeContact(id="x", edge="N", memory=ANY)), [("x", "bit", None)]),
    (net(par(c("I 0.0"), Contact(id="x", operand=" <??.?> "))), [("x", "bit", None)]),
    (net(c("I 0.0"), outputs=[coil(BIT)]), [("", "bit", None)]),
    (
        net(outputs=ends(Coil(id="x", coil="SD", operand=ANY, value="S5T#1S"))),
        [("x", "timer", None)],
    ),
    (net(outputs=ends(Coil(id="x", coil="SD", operand="T 1", value=ANY))), [("x", "value", None)]),
    (net(outputs=ends(Coil(id="x", coil="CU", operand=ANY))), [("x", "counter", None)]),
    (net(outputs=ends(OpenDb(id="x", block=ANY))), [("x", "operand", None)]),
    (
        net(
            c("I 0.0"),
            Box(id="x", name="MOVE", inputs={"IN": ANY}, outputs={"OUT": ANY}),
        ),
        [("x", "operand", "IN"), ("x", "operand", "OUT")],
    ),
    (net(Box(id="x", name="S_ODT", instance=ANY, inputs={"TV": "S5T#1S"})), [("x", "timer", None)]),
    (net(Box(id="x", name="S_CU", instance=ANY)), [("x", "counter", None)]),
    (net(Box(id="x", name="SR", instance=BIT)), [("x", "bit", None)]),
    (net(c("I 0.0"), Box(id="x", name="FB 5", instance=ANY)), [("x", "operand", None)]),
    (
        net(
            Box(
                id="x",
                name="SR",
                instance="M 0.0",
                inputs={"R1": s(Contact(id="y", operand=BIT))},
            )
        ),
        [("y", "bit", None)],
    ),
]


@pytest.mark.parametrize(("network", "expected"), PLACEHOLDERS)
def test_an_operand_not_filled_in_is_reported_and_its_element_left_out(
    network: Network, expected: list[tuple[str, str, str | None]]
) -> None:
    """``<??.?>`` and ``<???>`` (as an editor writes a new element's operands) are LAD212 on
    their element; the element is left out, so the STL never holds a placeholder and the rest
    still compiles."""
    text, diagnostics = block_to_stl(ob1(net(c("I 1.0")), network))
    found = [
        (d.params["element"], d.params["what"], d.params.get("pin"))
        for d in diagnostics
        if d.code == "LAD212"
    ]
    assert found == [(e or "?", what, pin) for e, what, pin in expected]
    assert all(d.span is not None and d.span.network == 2 for d in diagnostics)
    assert "<" not in text.split("BEGIN")[1]
    result = compile_sources([SourceFile("draft.awl", text)])
    assert [d.message for d in result.diagnostics if d.severity == "error"] == [], text


def test_a_placeholder_in_a_parallel_leaves_the_other_branches() -> None:
    network = net(c("I 0.0"), par(c("I 0.1"), Contact(id="x", operand=BIT), c("I 0.2")))
    text, diagnostics = block_to_stl(ob1(network))
    assert [d.code for d in diagnostics] == ["LAD212"]
    body = [line.split() for line in text.split("BEGIN\n")[1].splitlines()[2:-1]]
    assert body == [
        ["A", "I", "0.0"],
        ["A("],
        ["O", "I", "0.1"],
        ["O", "I", "0.2"],
        [")"],
        ["=", "Q", "4.0"],
    ]
