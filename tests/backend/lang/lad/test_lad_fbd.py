"""LAD <-> FBD: the shapes STEP 7 draws, the normal forms, the refusals, and round trips."""

from __future__ import annotations

import itertools

import pytest
from lad_random import RandomNetworks

from nasaq.diagnostics import Span
from nasaq.diagnostics.catalogue import entry
from nasaq.lang.lad.fbd import (
    FbdAssign,
    FbdBox,
    FbdBranch,
    FbdEdge,
    FbdLogic,
    FbdMidline,
    FbdNetwork,
    FbdNode,
    FbdNot,
    FbdNotLad,
    FbdOperand,
    from_fbd,
    to_fbd,
)
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Invert,
    Midline,
    Network,
    Output,
    Parallel,
    Series,
)


def contact(ident: str, operand: str, negated: bool = False) -> Contact:
    return Contact(id=ident, operand=operand, negated=negated)


def rung(*elements: Contact | Invert | Parallel | Box | Midline | EdgeContact) -> Network:
    return Network(
        logic=Series(elements=list(elements)),
        outputs=[Output(target=Coil(id="q", coil="=", operand="Q 4.0"))],
    )


def op(operand: str, negated: bool = False, ident: str = "") -> FbdOperand:
    return FbdOperand(id=ident, operand=operand, negated=negated)


def fbd(logic: FbdNode, *inputs: FbdNode) -> FbdNetwork:
    """A network with one ``=`` per input given, or one fed straight by the common wire."""
    feeds = list(inputs) or [FbdBranch()]
    outputs = [
        FbdAssign(id=f"q{index}", coil="=", operand="Q 4.0", input=feed)
        for index, feed in enumerate(feeds)
    ]
    return FbdNetwork(logic=logic, outputs=outputs)


def test_series_with_normally_closed_contact_is_one_and_with_a_negated_pin() -> None:
    view = to_fbd(rung(contact("e1", "I 0.0"), contact("e2", "I 0.1", negated=True)))
    assert view.logic == FbdLogic(
        id="&1", op="AND", inputs=[op("I 0.0", ident="e1"), op("I 0.1", True, "e2")]
    )
    assert view.outputs == [FbdAssign(id="q", coil="=", operand="Q 4.0", input=FbdBranch())]


def test_one_contact_needs_no_and_box_and_the_rail_is_an_empty_and() -> None:
    assert to_fbd(rung(contact("e1", "I 0.0"))).logic == op("I 0.0", ident="e1")
    assert to_fbd(rung()).logic == FbdLogic(id="&1", op="AND", inputs=[])


def test_parallel_of_series_is_or_of_ands() -> None:
    network = rung(
        Parallel(
            id="p",
            branches=[
                Series(elements=[contact("a", "I 0.0"), contact("b", "I 0.1")]),
                Series(elements=[contact("c", "M 1.0")]),
            ],
        ),
        contact("d", "I 0.2"),
    )
    logic = to_fbd(network).logic
    assert isinstance(logic, FbdLogic)
    assert logic.op == "AND"
    either = logic.inputs[0]
    assert isinstance(either, FbdLogic)
    assert either.op == "OR"
    assert either.id == "p"
    assert [type(item) for item in either.inputs] == [FbdLogic, FbdOperand]
    assert logic.inputs[1] == op("I 0.2", ident="d")


def test_not_edge_midline_and_box_take_the_flow_so_far() -> None:
    timer = Box(
        id="t",
        name="S_ODT",
        instance="T 1",
        inputs={"TV": "S5T#5S", "R": Series(elements=[contact("r", "I 0.7")])},
        outputs={"Q": "M 3.0"},
    )
    network = rung(
        contact("a", "I 0.0"),
        contact("b", "I 0.1"),
        Invert(id="n"),
        EdgeContact(id="p", edge="P", memory="M 9.0"),
        Midline(id="m", operand="M 2.0"),
        timer,
        contact("c", "I 0.2"),
    )
    logic = to_fbd(network).logic
    assert isinstance(logic, FbdLogic)
    assert logic.op == "AND"
    box, after = logic.inputs
    assert after == op("I 0.2", ident="c")
    assert isinstance(box, FbdBox)
    assert box.inputs == {"TV": "S5T#5S", "R": op("I 0.7", ident="r")}
    midline = box.en
    assert isinstance(midline, FbdMidline)
    assert midline.operand == "M 2.0"
    edge = midline.input
    assert isinstance(edge, FbdEdge)
    assert edge.edge == "P"
    negation = edge.input
    assert isinstance(negation, FbdNot)
    assert negation.input == FbdLogic(
        id="&1", op="AND", inputs=[op("I 0.0", ident="a"), op("I 0.1", ident="b")]
    )
    assert from_fbd(to_fbd(network)) == network


def test_a_parallel_acting_on_the_flow_is_an_or_fed_by_the_flow_into_it() -> None:
    """``x`` then (``y`` MOVE | ``z``): each branch starts from ``x`` (the MOVE does not run
    while ``x`` is open), so the OR's ``flow`` is an AND box of ``x`` whose wire starts each
    branch; what follows the parallel is ANDed after the OR, nothing before it."""
    move = Box(id="mv", name="MOVE", inputs={"IN": "MW 0"}, outputs={"OUT": "MW 2"})
    branches = [
        Series(elements=[contact("y", "I 0.1"), move]),
        Series(elements=[contact("z", "I 0.2")]),
    ]
    network = rung(
        contact("x", "I 0.0"), Parallel(id="p", branches=branches), contact("w", "I 0.3")
    )
    logic = to_fbd(network).logic
    flow = FbdLogic(id="&1", op="AND", inputs=[op("I 0.0", ident="x")])
    tap = FbdBranch(source="&1")
    first = FbdBox(
        id="mv",
        name="MOVE",
        en=FbdLogic(id="&2", op="AND", inputs=[tap, op("I 0.1", ident="y")]),
        inputs={"IN": "MW 0"},
        outputs={"OUT": "MW 2"},
    )
    second = FbdLogic(id="&3", op="AND", inputs=[tap, op("I 0.2", ident="z")])
    either = FbdLogic(id="p", op="OR", inputs=[first, second], flow=flow)
    assert logic == FbdLogic(id="&4", op="AND", inputs=[either, op("I 0.3", ident="w")])
    assert from_fbd(to_fbd(network)) == network


def test_a_parallel_of_checks_keeps_the_plain_and_of_or() -> None:
    branches = [Series(elements=[contact("y", "I 0.1")]), Series(elements=[contact("z", "I 0.2")])]
    logic = to_fbd(rung(contact("x", "I 0.0"), Parallel(id="p", branches=branches))).logic
    assert isinstance(logic, FbdLogic)
    assert [item.kind for item in logic.inputs] == ["operand", "logic"]
    assert all(item.flow is None for item in logic.inputs if isinstance(item, FbdLogic))


def test_a_tapped_wire_only_where_lad_has_a_parallel_from_it() -> None:
    flow = FbdLogic(id="&9", op="AND", inputs=[op("a")])
    tap = FbdBranch(source="&9")
    # a tap outside the OR whose flow the box is
    stray = FbdLogic(op="AND", inputs=[flow, FbdNot(id="n", input=tap)])
    refusal(fbd(stray), "LAD407", "&9")
    # one branch starts from the wire, the other does not
    mixed = FbdLogic(
        id="o", op="OR", flow=flow, inputs=[FbdLogic(op="AND", inputs=[tap, op("b")]), op("c")]
    )
    refusal(fbd(mixed), "LAD407", "&9")
    # the flow is not an AND box with an id
    odd = FbdLogic(id="o", op="OR", flow=op("a", ident="a1"), inputs=[op("b"), op("c")])
    refusal(fbd(odd), "LAD407", "a1")
    # such an OR after other inputs of an AND: its branches would not see those
    good = FbdLogic(
        id="o", op="OR", flow=flow, inputs=[tap, FbdLogic(op="AND", inputs=[tap, op("b")])]
    )
    refusal(fbd(FbdLogic(id="and", op="AND", inputs=[op("c"), good])), "LAD405", "o")
    assert isinstance(from_fbd(fbd(good)), Network)


def test_a_comparator_is_one_input_of_the_and_as_step7_draws_it() -> None:
    compare = Box(id="c", name="CMP>=I", inputs={"IN1": "MW 0", "IN2": "MW 2"})
    network = rung(contact("a", "I 0.0"), compare, contact("b", "I 0.1"))
    logic = to_fbd(network).logic
    assert isinstance(logic, FbdLogic)
    assert [item.kind for item in logic.inputs] == ["operand", "box", "operand"]
    box = logic.inputs[1]
    assert isinstance(box, FbdBox)
    assert box.en is None
    assert from_fbd(to_fbd(network)) == network
    timer = Box(id="t", name="S_ODT", instance="T 1", inputs={"TV": "S5T#1S"})
    refusal(fbd(FbdLogic(op="AND", inputs=[op("a"), to_fbd(rung(timer)).logic])), "LAD405", "t")


def test_outputs_branch_off_the_common_wire() -> None:
    network = Network(
        logic=Series(elements=[contact("a", "I 0.0")]),
        outputs=[
            Output(target=Coil(id="q1", coil="=", operand="Q 4.0")),
            Output(
                conditions=Series(elements=[contact("b", "I 0.1", True)]),
                target=Coil(id="q2", coil="S", operand="Q 4.1"),
            ),
        ],
    )
    view = to_fbd(network)
    assert view.outputs[0].input == FbdBranch()
    second = view.outputs[1]
    assert isinstance(second, FbdAssign)
    assert second.coil == "S"
    assert second.input == FbdLogic(id="&1", op="AND", inputs=[FbdBranch(), op("I 0.1", True, "b")])
    assert from_fbd(view) == network


def test_nested_ands_are_one_series_and_one_input_boxes_vanish() -> None:
    nested = FbdLogic(
        op="AND",
        inputs=[
            FbdLogic(op="AND", inputs=[op("a"), op("b")]),
            FbdLogic(op="OR", inputs=[FbdLogic(op="AND", inputs=[op("c"), op("d")])]),
        ],
    )
    network = from_fbd(fbd(nested))
    assert isinstance(network, Network)
    assert [e.operand for e in network.logic.elements if isinstance(e, Contact)] == list("abcd")
    assert to_fbd(network).logic == FbdLogic(
        id="&1", op="AND", inputs=[op("a"), op("b"), op("c"), op("d")]
    )


def test_or_inside_or_stays_a_branch_holding_a_parallel() -> None:
    inner = FbdLogic(id="i", op="OR", inputs=[op("a"), op("b")])
    network = from_fbd(fbd(FbdLogic(id="o", op="OR", inputs=[inner, op("c")])))
    assert isinstance(network, Network)
    (outer,) = network.logic.elements
    assert isinstance(outer, Parallel)
    assert outer.id == "o"
    assert isinstance(outer.branches[0].elements[0], Parallel)


def test_outputs_apart_from_an_empty_common_logic_are_conditions() -> None:
    network = from_fbd(fbd(FbdLogic(op="AND"), op("a"), FbdNot(input=op("b"))))
    assert isinstance(network, Network)
    assert network.logic.elements == []
    assert [len(out.conditions.elements) for out in network.outputs] == [1, 2]


def refusal(view: FbdNetwork, code: str, element: str) -> None:
    found = from_fbd(view, network=3)
    assert isinstance(found, FbdNotLad), found
    assert found.diagnostic.code == code
    assert found.element == element
    assert found.diagnostic.span == Span(network=3)
    assert element in found.diagnostic.message


def test_xor_is_refused_with_its_reason() -> None:
    refusal(fbd(FbdLogic(id="x1", op="XOR", inputs=[op("a"), op("b")])), "LAD401", "x1")
    found = from_fbd(
        fbd(
            op("c"),
            FbdLogic(
                op="AND",
                inputs=[FbdBranch(), FbdLogic(id="x2", op="XOR", inputs=[op("a"), op("b")])],
            ),
        )
    )
    assert isinstance(found, FbdNotLad)
    assert found.diagnostic.key == "lad_fbd_xor"


def test_common_wire_only_at_the_start_of_an_output() -> None:
    late = FbdLogic(op="AND", inputs=[op("a"), FbdBranch()])
    refusal(fbd(op("c"), late), "LAD402", "q0")
    refusal(fbd(FbdLogic(id="L", op="AND", inputs=[FbdBranch(), op("a")])), "LAD402", "L")
    inside_or = FbdLogic(op="OR", inputs=[FbdBranch(), op("a")])
    refusal(fbd(op("c"), inside_or), "LAD402", "q0")


def test_an_output_apart_from_the_common_logic_is_refused() -> None:
    refusal(fbd(op("c"), FbdBranch(), op("a")), "LAD403", "q1")


def test_empty_or_is_refused() -> None:
    refusal(fbd(FbdLogic(id="o", op="OR")), "LAD404", "o")


def test_a_flow_box_in_a_later_and_input_is_refused() -> None:
    late = FbdLogic(id="and", op="AND", inputs=[op("a"), FbdNot(id="n", input=op("b"))])
    refusal(fbd(late), "LAD405", "n")
    deeper = FbdLogic(
        op="AND",
        inputs=[
            op("a"),
            FbdLogic(
                op="AND", inputs=[FbdEdge(id="p", edge="P", memory="M 9.0", input=op("b")), op("c")]
            ),
        ],
    )
    refusal(fbd(deeper), "LAD405", "p")


def test_a_duplicate_id_is_refused() -> None:
    refusal(
        fbd(FbdLogic(op="AND", inputs=[op("a", ident="e1"), op("b", ident="e1")])), "LAD406", "e1"
    )


def test_codes_are_catalogued_in_the_range() -> None:
    for number in range(401, 408):
        assert entry(f"LAD{number}").key.startswith("lad_fbd_")


@pytest.mark.parametrize("seed", range(300))
def test_lad_fbd_lad_round_trip(seed: int) -> None:
    network = RandomNetworks(seed).network()
    view = to_fbd(network)
    back = from_fbd(view)
    assert back == network
    assert to_fbd(back) == view
    assert from_fbd(FbdNetwork.model_validate_json(view.model_dump_json())) == network


# --- the two views compute the same power flow -----------------------------------------------


def lad_value(series: Series, values: dict[str, bool], flow: bool = True) -> bool:
    for element in series.elements:
        if isinstance(element, Contact):
            flow = flow and (values[element.operand] != element.negated)
        elif isinstance(element, Invert):
            flow = not flow
        else:
            assert isinstance(element, Parallel)
            flow = any(lad_value(branch, values, flow) for branch in element.branches)
    return flow


def fbd_value(
    node: FbdNode, values: dict[str, bool], common: bool, wires: dict[str, bool] | None = None
) -> bool:
    """The node's value; ``wires`` keeps the value of each AND box for the taps of its wire
    (an OR's ``flow`` is evaluated before its inputs, which tap it)."""
    wires = {} if wires is None else wires
    if isinstance(node, FbdOperand):
        return values[node.operand] != node.negated
    if isinstance(node, FbdBranch):
        return wires[node.source] if node.source else common
    if isinstance(node, FbdNot):
        return not fbd_value(node.input, values, common, wires)
    assert isinstance(node, FbdLogic)
    if node.flow is not None:
        fbd_value(node.flow, values, common, wires)
    results = [fbd_value(item, values, common, wires) for item in node.inputs]
    value = all(results) if node.op == "AND" else any(results)
    wires[node.id] = value
    return value


@pytest.mark.parametrize("seed", range(60))
def test_both_views_give_the_same_outputs(seed: int) -> None:
    network = RandomNetworks(seed, pure=True).network()
    view = to_fbd(network)
    names = ["I 0.0", "I 0.1", "I 0.2", "M 1.0", "#run", '"Stop"']
    for bits in itertools.product([False, True], repeat=len(names)):
        values = dict(zip(names, bits, strict=True))
        common = lad_value(network.logic, values)
        for output, final in zip(network.outputs, view.outputs, strict=True):
            assert isinstance(final, FbdAssign)
            expected = lad_value(output.conditions, values, common)
            assert fbd_value(final.input, values, fbd_value(view.logic, values, True)) == expected


def test_a_network_kept_as_stl_passes_through_the_fbd_view() -> None:
    kept = Network(title="moved", stl="      L     MW 10\n      T     MW 12", stl_reason="LAD305")
    fbd = to_fbd(kept)
    assert fbd.stl == kept.stl
    assert fbd.outputs == []
    assert from_fbd(fbd) == kept


# --- rungs being drawn -----------------------------------------------------------------------


def test_an_empty_rung_is_the_rail_alone_and_reads_back() -> None:
    empty = Network(label="M001")
    view = to_fbd(empty)
    assert view.logic == FbdLogic(id="&1", op="AND")
    assert view.outputs == []
    assert from_fbd(view) == empty


def test_logic_waiting_for_its_coil_is_its_logic_without_final_boxes() -> None:
    timer = Box(id="t", name="S_ODT", instance="T 1", inputs={"TV": "S5T#2S"})
    waiting = Network(logic=Series(elements=[contact("a", "I 0.0", True), timer]))
    view = to_fbd(waiting)
    assert view.logic == FbdBox(
        id="t", name="S_ODT", instance="T 1", en=op("I 0.0", True, "a"), inputs={"TV": "S5T#2S"}
    )
    assert view.outputs == []
    assert from_fbd(view) == waiting


@pytest.mark.parametrize("seed", range(100))
def test_random_logic_without_outputs_round_trips(seed: int) -> None:
    network = RandomNetworks(seed).network().model_copy(update={"outputs": []})
    view = to_fbd(network)
    assert view.outputs == []
    back = from_fbd(view)
    assert back == network
    assert isinstance(back, Network)
    assert to_fbd(back) == view
