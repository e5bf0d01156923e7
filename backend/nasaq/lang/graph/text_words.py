"""The keywords of the ``.graph`` format, grouped by what they end (for recovery)."""

from __future__ import annotations

from typing import get_args

from nasaq.lang.graph.model import Event, ParameterSet, Qualifier

EVENTS: frozenset[str] = frozenset(get_args(Event))
QUALIFIERS: frozenset[str] = frozenset(get_args(Qualifier))
PARAMETER_SETS: frozenset[str] = frozenset(get_args(ParameterSet))
SETTING_NAMES = ("PARAMETERS", "SKIP_STEPS", "ACKNOWLEDGE", "INTERLOCK_BLOCKS")

# What ends a block's parts, a sequencer, a permanent section.
OUTER = frozenset(
    {
        "FUNCTION_BLOCK",
        "END_FUNCTION_BLOCK",
        "SEQUENCER",
        "END_SEQUENCER",
        "PERMANENT_PRE",
        "END_PERMANENT_PRE",
        "PERMANENT_POST",
        "END_PERMANENT_POST",
    }
)
BODY = OUTER - {"END_SEQUENCER", "END_PERMANENT_PRE", "END_PERMANENT_POST"}
ITEMS = frozenset({"STEP", "INITIAL_STEP", "TRANSITION"})
STEP_PARTS = frozenset({"COMMENT", "INTERLOCK", "SUPERVISION", "ACTIONS"})
TRANSITION_PARTS = frozenset({"COMMENT", "CONDITION"})
ENDS = frozenset(
    {"END_STEP", "END_TRANSITION", "END_CONDITION", "END_INTERLOCK", "END_SUPERVISION"}
)
KEYWORDS = (
    OUTER
    | ITEMS
    | STEP_PARTS
    | TRANSITION_PARTS
    | ENDS
    | {"END_ACTIONS", "SETTINGS", "END_SETTINGS", "BEGIN", "FROM", "TO", "JUMP", "STOP"}
)
# Words refused as a name (a step, transition or sequencer): they more likely mean that the name
# is missing. FROM, TO, JUMP and STOP stand only where no name can, so a step may be called Stop.
NOT_NAMES = KEYWORDS - {"FROM", "TO", "JUMP", "STOP"}
# What ends any LAD text inside a Graph file (``Scanner.host_words``).
HOST_WORDS = OUTER | ITEMS | ENDS | {"INTERLOCK", "SUPERVISION", "CONDITION", "ACTIONS"}
# What ends an action row whose ';' is missing.
ROW_STOPS = HOST_WORDS | {"END_ACTIONS", "COMMENT"}
SEQUENCER_SYNC = ITEMS | OUTER
STEP_SYNC = ITEMS | OUTER | {"END_STEP"}
TRANSITION_SYNC = ITEMS | OUTER | {"END_TRANSITION"}
CONDITION_SYNC = STEP_SYNC | TRANSITION_SYNC | STEP_PARTS | TRANSITION_PARTS
