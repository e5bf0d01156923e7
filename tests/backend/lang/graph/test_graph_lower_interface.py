"""The compiled FB's interface is the instance DB of SEMANTICS.md §1: the parameter set, the
user's declarations after the set's parameters of the same section, the G7_ state, one STRUCT
per step and per transition, with these names, types, order and initial values."""

from __future__ import annotations

import pytest
from graph_lower_support import Plant, compiled, errors

from nasaq.ir import BlockKind, Variable

SOURCE = """FUNCTION_BLOCK FB 1
SETTINGS
  PARAMETERS := {parameters};
  ACKNOWLEDGE := FALSE;
END_SETTINGS
VERSION : 0.3
VAR_INPUT
  speed : INT;
END_VAR
VAR
  count : INT;
END_VAR
BEGIN
SEQUENCER Main
INITIAL_STEP Idle (1)
END_STEP
TRANSITION Go (4) FROM Idle TO Fill
CONDITION Contact(I 0.0) END_CONDITION
END_TRANSITION
STEP Fill (7)
ACTIONS
  N Q 0.0;
END_ACTIONS
END_STEP
TRANSITION Back (5) FROM Fill TO Idle
END_TRANSITION
END_SEQUENCER
END_FUNCTION_BLOCK
"""

STEP_MEMBERS = [
    *(("X", "S1", "S0", "V1", "V0", "L1", "L0", "A1", "R1", "LA", "VA", "PS1", "PS0")),
    "SNO",
    "T",
    "U",
]


def words(text: str) -> list[str]:
    return text.split()


def interface(parameters: str) -> list[Variable]:
    result = compiled(SOURCE.format(parameters=parameters))
    assert not errors(result), errors(result)
    block = result.program.get(BlockKind.FB, 1)
    assert block is not None
    assert block.attributes.get("VERSION") == "0.3"
    return block.interface


def names(variables: list[Variable], section: str) -> list[str]:
    return [v.name for v in variables if v.section == section]


def test_standard_set_then_the_users_declarations_then_the_state() -> None:
    found = interface("STANDARD")
    assert names(found, "IN") == [
        *words("OFF_SQ INIT_SQ ACK_EF S_PREV S_NEXT SW_AUTO SW_TAP SW_MAN S_SEL S_ON S_OFF"),
        "T_PUSH",
        "speed",
    ]
    assert names(found, "OUT") == words("S_NO S_MORE S_ACTIVE ERR_FLT AUTO_ON TAP_ON MAN_ON")
    edges = [f"G7_M_{p}" for p in words("SW_AUTO SW_MAN SW_TAP ACK_EF T_PUSH S_ON S_OFF")]
    assert names(found, "STAT") == [
        "count",
        "G7_MODE",
        "G7_STARTED",
        "G7_TICK",
        *edges,
        "G7_M_S_NEXT",
        "G7_M_S_PREV",
        "G7_DISP",
        "G7_IL_OFF",
        "G7_SV_OFF",
        "G7_CMD",
        "G7_CMD_STEP",
        "Idle",
        "Fill",
        "Go",
        "Back",
    ]
    by_name = {v.name: v for v in found}
    assert by_name["S_SEL"].type == "INT"
    assert by_name["S_NO"].type == "INT"
    assert by_name["G7_TICK"].type == "DINT"
    fill = by_name["Fill"]
    assert [m.name for m in fill.members] == STEP_MEMBERS
    types = {m.name: m.type for m in fill.members}
    assert types["SNO"] == "INT"
    assert types["T"] == "TIME"
    assert types["U"] == "TIME"
    assert [(m.name, m.type) for m in by_name["Back"].members] == [
        ("TT", "BOOL"),
        ("TNO", "INT"),
    ]
    # initial values, as the instance DB holds them before the first call
    plant = Plant(SOURCE.format(parameters="STANDARD"))
    assert plant.db("G7_MODE") == 1
    assert plant.db("Fill.SNO") == 7
    assert plant.db("Back.TNO") == 5
    assert plant.db("Idle.X") is False
    assert plant.db("Idle.SNO") == 1


def test_minimum_set_has_init_sq_only() -> None:
    found = interface("MINIMUM")
    assert names(found, "IN") == ["INIT_SQ", "speed"]
    assert names(found, "OUT") == []
    assert not any(v.name.startswith("G7_M_") for v in found)


@pytest.mark.parametrize("parameters", ["MAXIMUM", "USER_DEFINED"])
def test_maximum_and_user_defined_sets(parameters: str) -> None:
    found = interface(parameters)
    inputs = names(found, "IN")
    assert inputs[:8] == words("OFF_SQ INIT_SQ ACK_EF HALT_SQ HALT_TM ZERO_OP EN_IL EN_SV")
    by_name = {v.name: v for v in found}
    plant = Plant(SOURCE.format(parameters=parameters))
    assert plant.db("EN_IL") is True
    assert plant.db("EN_SV") is True
    outputs = names(found, "OUT")
    assert "IL_ENABLED" in outputs
    assert "SV_ENABLED" in outputs
    if parameters == "USER_DEFINED":
        assert inputs[-4:] == ["EN_ACKREQ", "EN_SSKIP", "SW_TOP", "speed"]
        assert outputs[-4:] == ["ERROR", "FAULT", "SQ_ISOFF", "TOP_ON"]
        assert plant.db("EN_ACKREQ") is False  # ACKNOWLEDGE := FALSE
        assert "G7_M_SW_TOP" in names(found, "STAT")
    else:
        assert "EN_ACKREQ" not in by_name
        assert "G7_M_SW_TOP" not in by_name
