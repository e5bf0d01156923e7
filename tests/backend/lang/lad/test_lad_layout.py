"""The deterministic layouts: every element placed, nothing overlapping, same input same output."""

from __future__ import annotations

import pytest
from lad_random import RandomNetworks, element_ids

from nasaq.lang.lad.fbd import FbdAssign, FbdBranch, FbdLogic, FbdNetwork, FbdOperand, to_fbd
from nasaq.lang.lad.layout import LadLayout, fbd_layout, lad_layout
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    Invert,
    Network,
    Output,
    Parallel,
    Series,
    StatusContact,
)


def contact(ident: str, operand: str = "I 0.0") -> Contact:
    return Contact(id=ident, operand=operand)


def cells_of(layout: LadLayout) -> dict[str, tuple[int, int, int, int]]:
    return {cell.id: (cell.column, cell.row, cell.width, cell.height) for cell in layout.cells}


def test_series_parallel_and_stacked_outputs() -> None:
    network = Network(
        logic=Series(
            elements=[
                contact("a"),
                Parallel(
                    id="p",
                    branches=[
                        Series(elements=[contact("b"), contact("c")]),
                        Series(elements=[contact("d")]),
                    ],
                ),
            ]
        ),
        outputs=[
            Output(target=Coil(id="q1", coil="=", operand="Q 4.0")),
            Output(
                conditions=Series(elements=[contact("e")]),
                target=Coil(id="q2", coil="S", operand="Q 4.1"),
            ),
        ],
    )
    layout = lad_layout(network)
    assert cells_of(layout) == {
        "a": (0, 0, 1, 1),
        "b": (1, 0, 1, 1),
        "c": (2, 0, 1, 1),
        "d": (1, 1, 1, 1),
        "q1": (4, 0, 1, 1),
        "e": (3, 1, 1, 1),
        "q2": (4, 1, 1, 1),
    }
    assert layout.columns == 5
    assert layout.rows == 2
    assert [(link.column, link.from_row, link.to_row) for link in layout.links] == [
        (1, 0, 1),
        (3, 0, 1),
        (3, 0, 1),
    ]
    assert [(w.row, w.from_column, w.to_column) for w in layout.wires] == [(1, 2, 3), (0, 3, 4)]
    (region,) = layout.parallels
    assert (region.id, region.column, region.row, region.width, region.height) == ("p", 1, 0, 2, 2)


def test_box_is_two_cells_wide_and_as_tall_as_its_pins() -> None:
    timer = Box(
        id="t",
        name="S_ODT",
        instance="T 1",
        inputs={"TV": "S5T#5S", "R": Series(elements=[contact("r"), contact("s")])},
        outputs={"BI": "MW 2", "BCD": "MW 4", "Q": "M 3.0"},
    )
    network = Network(
        logic=Series(elements=[contact("a"), timer]),
        outputs=[Output(target=Coil(id="q", coil="=", operand="Q 4.0"))],
    )
    layout = lad_layout(network)
    cells = cells_of(layout)
    assert cells["t"] == (3, 0, 2, 3)
    assert cells["r"] == (1, 2, 1, 1)
    assert cells["s"] == (2, 2, 1, 1)
    (box,) = [cell for cell in layout.cells if cell.id == "t"]
    assert [(p.name, p.side, p.row, p.operand) for p in box.pins] == [
        ("S", "left", 0, None),
        ("TV", "left", 1, "S5T#5S"),
        ("R", "left", 2, None),
        ("Q", "right", 0, "M 3.0"),
        ("BI", "right", 1, "MW 2"),
        ("BCD", "right", 2, "MW 4"),
    ]
    assert cells["q"] == (5, 0, 1, 1)
    assert layout.columns == 6
    assert layout.rows == 3


def test_comparator_and_move_pins() -> None:
    compare = Box(id="c", name="CMP>=I", inputs={"IN1": "MW 0", "IN2": "MW 2"})
    move = Box(id="m", name="MOVE", inputs={"IN": "MW 0"}, outputs={"OUT": "MW 4"})
    network = Network(logic=Series(elements=[compare]), outputs=[Output(target=move)])
    layout = lad_layout(network)
    pins = {cell.id: [(p.name, p.side, p.row) for p in cell.pins] for cell in layout.cells}
    assert pins == {
        "c": [("IN1", "left", 1), ("IN2", "left", 2)],
        "m": [("EN", "left", 0), ("IN", "left", 1), ("ENO", "right", 0), ("OUT", "right", 1)],
    }


def occupied(layout: LadLayout) -> list[tuple[str, int, int]]:
    taken = [
        (cell.id, cell.column + dx, cell.row + dy)
        for cell in layout.cells
        for dx in range(cell.width)
        for dy in range(cell.height)
    ]
    taken += [
        (f"wire{index}", column, wire.row)
        for index, wire in enumerate(layout.wires)
        for column in range(wire.from_column, wire.to_column)
    ]
    return taken


@pytest.mark.parametrize("seed", range(300))
def test_lad_layout_places_everything_once_without_overlap(seed: int) -> None:
    network = RandomNetworks(seed).network()
    layout = lad_layout(network)
    assert layout == lad_layout(Network.model_validate_json(network.model_dump_json()))
    placed = [cell.id for cell in layout.cells] + [region.id for region in layout.parallels]
    assert sorted(placed) == sorted(element_ids(network))
    taken = occupied(layout)
    spots = [(column, row) for _, column, row in taken]
    assert len(spots) == len(set(spots)), "two things share a cell"
    assert all(0 <= column < layout.columns and 0 <= row < layout.rows for column, row in spots)
    targets = {output.target.id for output in network.outputs}
    for cell in layout.cells:
        if cell.id in targets:
            assert cell.column + cell.width == layout.columns, "outputs touch the right rail"
    for region in layout.parallels:  # a parallel's rectangle holds whole cells or none of them
        area = {
            (region.column + dx, region.row + dy)
            for dx in range(region.width)
            for dy in range(region.height)
        }
        for ident in {ident for ident, _, _ in taken}:
            cell = {(column, row) for name, column, row in taken if name == ident}
            assert cell <= area or not cell & area, (region.id, ident)
    for link in layout.links:
        assert 0 <= link.from_row <= link.to_row < layout.rows
        assert 0 <= link.column <= layout.columns


@pytest.mark.parametrize("seed", range(200))
def test_fbd_layout_is_layered_and_complete(seed: int) -> None:
    network = RandomNetworks(seed).network()
    view = to_fbd(network)
    layout = fbd_layout(view)
    assert layout == fbd_layout(to_fbd(network))
    nodes = {node.id: node for node in layout.nodes}
    assert len(nodes) == len(layout.nodes)
    assert len({(node.layer, node.order) for node in layout.nodes}) == len(layout.nodes)
    for final in view.outputs:
        assert nodes[final.id].layer == layout.layers - 1
    ports = {port.id: (node.id, port) for node in layout.nodes for port in node.ports}
    for edge in layout.edges:
        source, out = ports[edge.source_port]
        target, into = ports[edge.target_port]
        assert (source, target) == (edge.source, edge.target)
        assert out.side == "EAST"
        assert into.side == "WEST"
        assert nodes[source].layer < nodes[target].layer
    for node in layout.nodes:
        west = [port.index for port in node.ports if port.side == "WEST"]
        east = [port.index for port in node.ports if port.side == "EAST"]
        assert west == list(range(len(west)))
        assert east == list(range(len(east)))
        assert node.height == max(1, len(west), len(east))
        assert node.width == 2
    fed = {edge.target_port for edge in layout.edges}
    for node in layout.nodes:
        for port in node.ports:
            if port.side == "WEST":
                # Every input is either wired, or shows its operand, or is an open pin.
                assert [port.id in fed, port.label is not None, port.open].count(True) == 1, port


def test_fbd_layout_of_a_typical_network() -> None:
    network = Network(
        logic=Series(
            elements=[
                Parallel(
                    id="p",
                    branches=[
                        Series(elements=[contact("a", "I 0.0")]),
                        Series(elements=[contact("b", "Q 4.0")]),
                    ],
                ),
                Contact(id="c", operand="I 0.1", negated=True),
            ]
        ),
        outputs=[
            Output(target=Coil(id="q", coil="=", operand="Q 4.0")),
            Output(target=Coil(id="m", coil="S", operand="M 0.0")),
        ],
    )
    layout = fbd_layout(to_fbd(network))
    summary = [(n.id, n.title, n.operand, n.layer, n.order, n.height) for n in layout.nodes]
    assert summary == [
        ("q", "=", "Q 4.0", 2, 0, 1),
        ("&1", "&", None, 1, 0, 2),
        ("p", ">=1", None, 0, 0, 2),
        ("m", "S", "M 0.0", 2, 1, 1),
    ]
    labels = [(p.name, p.label, p.negated) for p in layout.nodes[1].ports if p.side == "WEST"]
    assert labels == [("IN1", None, False), ("IN2", "I 0.1", True)]
    assert [(e.source, e.target) for e in layout.edges] == [("&1", "q"), ("p", "&1"), ("&1", "m")]


def test_fbd_layout_draws_the_flow_into_a_parallel_as_a_wire_to_every_branch() -> None:
    branches = [
        Series(elements=[contact("y", "I 0.1"), Invert(id="n")]),
        Series(elements=[contact("z", "I 0.2")]),
    ]
    network = Network(
        logic=Series(elements=[contact("x"), Parallel(id="p", branches=branches)]),
        outputs=[Output(target=Coil(id="q", coil="=", operand="Q 4.0"))],
    )
    layout = fbd_layout(to_fbd(network))
    assert [(n.id, n.title, n.layer) for n in layout.nodes] == [
        ("q", "=", 4),
        ("p", ">=1", 3),
        ("n", "NOT", 2),
        ("&2", "&", 1),
        ("&1", "&", 0),
        ("&3", "&", 2),
    ]
    assert [(e.source, e.target_port) for e in layout.edges] == [
        ("p", "q.W.0"),
        ("n", "p.W.0"),
        ("&3", "p.W.1"),
        ("&2", "n.W.0"),
        ("&1", "&2.W.0"),
        ("&1", "&3.W.0"),
    ]


def test_fbd_layout_of_a_box_tapping_its_own_wire_terminates() -> None:
    tap = FbdBranch(source="&9")
    looped = FbdLogic(id="&9", op="AND", inputs=[FbdOperand(operand="I 0.0"), tap])
    view = FbdNetwork(outputs=[FbdAssign(id="q", coil="=", operand="Q 4.0", input=looped)])
    layout = fbd_layout(view)
    assert [(node.id, node.layer) for node in layout.nodes] == [("q", 1), ("&9", 0)]
    assert [(e.source, e.target) for e in layout.edges] == [("&9", "q")]


def test_fbd_layout_of_a_shape_lad_refuses_still_terminates() -> None:
    looped = FbdLogic(id="L", op="AND", inputs=[FbdBranch(), FbdOperand(operand="I 0.0")])
    xor = FbdLogic(id="x", op="XOR", inputs=[FbdBranch(), FbdOperand(operand="I 0.1")])
    view = FbdNetwork(
        logic=looped, outputs=[FbdAssign(id="q", coil="=", operand="Q 4.0", input=xor)]
    )
    layout = fbd_layout(view)
    assert [(node.id, node.layer) for node in layout.nodes] == [("q", 2), ("x", 1), ("L", 0)]
    unlabelled = [p.id for n in layout.nodes for p in n.ports if p.side == "WEST" and not p.label]
    assert sorted(unlabelled) == ["L.W.0", "q.W.0", "x.W.0"]
    assert [(e.source, e.target) for e in layout.edges] == [("x", "q"), ("L", "x")]


def test_a_network_kept_as_stl_has_no_rung_to_lay_out() -> None:
    kept = Network(stl="      L     MW 10\n      T     MW 12", stl_reason="LAD305")
    assert lad_layout(kept).cells == []
    assert lad_layout(kept).columns == 0
    assert fbd_layout(to_fbd(kept)).nodes == []


# --- the power flow on each wire -------------------------------------------------------------


def coil(ident: str, operand: str = "Q 4.0") -> Coil:
    return Coil(id=ident, coil="=", operand=operand)


def test_every_wire_and_link_names_the_flow_it_carries() -> None:
    call = Box(
        id="f",
        name="FC 10",
        inputs={
            "A": Series(elements=[contact("x"), contact("y")]),
            "B": Series(elements=[contact("z")]),
            "N": "MW 2",
            "C": Series(),
        },
    )
    branches = [
        Series(elements=[contact("b"), contact("c")]),
        Series(),
        Series(elements=[contact("d")]),
    ]
    network = Network(
        logic=Series(elements=[contact("a"), Parallel(id="p", branches=branches), call]),
        outputs=[
            Output(target=coil("q1")),
            Output(conditions=Series(elements=[contact("e")]), target=coil("q2")),
            Output(conditions=Series(elements=[contact("h"), contact("i")]), target=coil("q3")),
        ],
    )
    layout = lad_layout(network)
    assert [(w.row, w.from_column, w.to_column, w.flow) for w in layout.wires] == [
        (1, 1, 3, "p:in"),  # the empty branch: the flow into the parallel
        (2, 2, 3, "d"),  # a shorter branch: the flow out of its last element
        (0, 3, 5, "f:in"),  # the box's flow passing over the logic of its pins
        (2, 4, 5, "z"),  # a pin's shorter logic: the flow out of its last element
        (4, 3, 5, "rail"),  # a pin's empty logic: the rail it starts from
        (0, 7, 9, "f"),  # an output without conditions: the common logic's flow
        (1, 8, 9, "e"),  # an output's conditions: the flow out of the last one
    ]
    assert [(k.column, k.from_row, k.to_row, k.flow) for k in layout.links] == [
        (1, 0, 2, "p:in"),  # a parallel's left edge: the flow into it
        (3, 0, 2, "p"),  # its right edge: the flow out of it
        (7, 0, 2, "f"),  # the outputs' join: the common logic's flow
    ]


def test_outputs_straight_from_the_rail_carry_the_rail() -> None:
    network = Network(
        outputs=[
            Output(target=coil("q1")),
            Output(conditions=Series(elements=[contact("a")]), target=coil("q2")),
        ]
    )
    layout = lad_layout(network)
    assert [(w.row, w.from_column, w.to_column, w.flow) for w in layout.wires] == [
        (0, 0, 1, "rail")
    ]
    assert [(k.column, k.from_row, k.to_row, k.flow) for k in layout.links] == [(0, 0, 1, "rail")]


def flow_points(network: Network) -> set[str]:
    """Every flow point of the network: the rail, and into and out of each element."""
    ids = element_ids(network)
    return {"rail", *ids, *(f"{ident}:in" for ident in ids)}


@pytest.mark.parametrize("seed", range(200))
def test_every_flow_is_a_point_of_the_network(seed: int) -> None:
    network = RandomNetworks(seed).network()
    for rung in (network, network.model_copy(update={"outputs": []})):
        layout = lad_layout(rung)
        flows = {wire.flow for wire in layout.wires} | {link.flow for link in layout.links}
        assert flows <= flow_points(rung)


# --- rungs being drawn -----------------------------------------------------------------------


def test_an_empty_rung_is_a_rung_of_no_width_and_one_row() -> None:
    layout = lad_layout(Network(label="M001"))
    assert (layout.columns, layout.rows) == (0, 1)
    assert layout.cells == layout.parallels == layout.links == layout.wires == []
    assert fbd_layout(to_fbd(Network())).nodes == []


def test_without_outputs_the_rail_stands_right_after_the_logic() -> None:
    parallel = Parallel(id="p", branches=[Series(elements=[contact("b")]), Series()])
    network = Network(logic=Series(elements=[contact("a"), parallel]))
    layout = lad_layout(network)
    assert (layout.columns, layout.rows) == (2, 2)
    assert cells_of(layout) == {"a": (0, 0, 1, 1), "b": (1, 0, 1, 1)}
    assert [(w.row, w.from_column, w.to_column, w.flow) for w in layout.wires] == [
        (1, 1, 2, "p:in")
    ]


@pytest.mark.parametrize("seed", range(100))
def test_random_logic_without_outputs_is_placed_up_to_the_rail(seed: int) -> None:
    network = RandomNetworks(seed).network().model_copy(update={"outputs": []})
    layout = lad_layout(network)
    placed = [cell.id for cell in layout.cells] + [region.id for region in layout.parallels]
    assert sorted(placed) == sorted(element_ids(network))
    spots = [(column, row) for _, column, row in occupied(layout)]
    assert len(spots) == len(set(spots))
    assert layout.columns == max((column + 1 for column, _ in spots), default=0)
    assert all(0 <= row < layout.rows for _, row in spots)


def test_without_outputs_the_common_logic_is_the_last_layer() -> None:
    timer = Box(id="t", name="S_ODT", instance="T 1", inputs={"TV": "S5T#2S"})
    network = Network(logic=Series(elements=[contact("a"), Invert(id="n"), timer]))
    layout = fbd_layout(to_fbd(network))
    assert [(node.id, node.title, node.layer) for node in layout.nodes] == [
        ("t", "T 1 S_ODT", 1),
        ("n", "NOT", 0),
    ]
    assert layout.layers == 2
    assert [(e.source, e.target_port) for e in layout.edges] == [("n", "t.W.0")]


def test_a_lone_operand_without_outputs_is_a_node_with_its_operand_at_its_output() -> None:
    for logic, text in ((contact("a", "I 0.3"), "I 0.3"), (StatusContact(id="a", bit="OV"), "OV")):
        negated = logic.model_copy(update={"negated": True})
        layout = fbd_layout(to_fbd(Network(logic=Series(elements=[negated]))))
        (node,) = layout.nodes
        assert (node.id, node.kind, node.title, node.operand, node.layer) == (
            "a",
            "operand" if isinstance(logic, Contact) else "status",
            "",
            None,
            0,
        )
        assert [(p.id, p.side, p.label, p.negated, p.element) for p in node.ports] == [
            ("a.E.0", "EAST", text, True, "a")
        ]


def test_a_port_names_the_element_whose_operand_it_shows() -> None:
    compare = Box(id="c", name="CMP>I", inputs={"IN1": "MW 0", "IN2": "MW 2"})
    network = Network(
        logic=Series(elements=[contact("a", "I 0.0"), StatusContact(id="s", bit="OV"), compare]),
        outputs=[Output(target=Coil(id="q", coil="=", operand="Q 4.0"))],
    )
    layout = fbd_layout(to_fbd(network))
    ports = {p.id: (p.label, p.element) for node in layout.nodes for p in node.ports}
    assert ports == {
        "q.W.0": (None, None),  # a wire
        "&1.W.0": ("I 0.0", "a"),
        "&1.W.1": ("OV", "s"),
        "&1.W.2": (None, None),
        "&1.E.0": (None, None),
        "c.W.0": ("MW 0", None),  # the box's own operands
        "c.W.1": ("MW 2", None),
        "c.E.0": (None, None),
    }
