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
