"""The VAR sections of a compiled Graph FB (``SEMANTICS.md`` §1): the parameter set, the user's
declarations, the sequencer state and one STRUCT per step and per transition.

Our parameter sections come first and the user's sections after them; the STL compiler lays an
instance out section by section (IN, OUT, IN_OUT, STAT, as STEP 7 does), so the user's inputs
follow the set's inputs and the user's statics come before the ``G7_`` state.
"""

from __future__ import annotations

import re

from nasaq.lang.graph.lower_chart import EDGE_INPUTS, INT_PARAMETERS, STEP_EVENTS, Chart

_SECTION = re.compile(r"^\s*VAR(_INPUT|_OUTPUT|_IN_OUT|_TEMP)?\b", re.IGNORECASE | re.MULTILINE)
_DECLARATION = re.compile(r"^\s*([A-Za-z_]\w*)\s*:\s*([A-Za-z_][\w ]*?)\s*(?::=|;|\{|//|$)")

# The call's working values (VAR_TEMP): the time, the edges and commands of this call.
TEMPS: tuple[tuple[str, str], ...] = (
    ("G7_NOW", "DINT"),
    ("G7_DT", "DINT"),
    ("G7_SEL", "INT"),
    ("G7_N", "INT"),
    ("G7_SNO", "INT"),
    ("G7_D1", "INT"),
    ("G7_AUTO", "BOOL"),
    ("G7_MAN", "BOOL"),
    ("G7_TAP", "BOOL"),
    ("G7_TOP", "BOOL"),
    ("G7_INIT", "BOOL"),
    ("G7_OFF", "BOOL"),
    ("G7_NOSW", "BOOL"),
    ("G7_SW", "BOOL"),
    ("G7_P1", "BOOL"),
    ("G7_P2", "BOOL"),
    ("G7_ILEN", "BOOL"),
    ("G7_SVEN", "BOOL"),
    ("G7_OK", "BOOL"),
    ("G7_ERR", "BOOL"),
    ("G7_SKIP", "BOOL"),
    *((f"G7_E_{name}", "BOOL") for name in EDGE_INPUTS),
)


def split_declarations(text: str) -> tuple[str, str]:
    """The user's header lines (``VERSION``, ``AUTHOR`` …, before the first VAR section) and the
    VAR sections."""
    match = _SECTION.search(text)
    if match is None:
        return text.strip("\n"), ""
    return text[: match.start()].strip("\n"), text[match.start() :].strip("\n")


def declared_types(text: str) -> dict[str, tuple[str, str]]:
    """The user's top-level variables: upper-case name → (name, type); for typing arithmetic
    actions and for writing ``name`` as ``#name``."""
    found: dict[str, tuple[str, str]] = {}
    depth = 0
    for line in text.split("\n"):
        stripped = line.split("//", 1)[0].strip()
        upper = stripped.upper()
        if upper.startswith("END_STRUCT"):
            depth -= 1
            continue
        match = _DECLARATION.match(stripped)
        if match is not None and depth == 0 and not upper.startswith("VAR"):
            name, type_text = match.group(1), match.group(2).strip().upper()
            found.setdefault(name.upper(), (name, type_text))
        if re.search(r"\bSTRUCT\b", upper) and not upper.startswith("END_STRUCT"):
            depth += 1
    return found


def _initial(parameter: str, chart: Chart) -> str:
    settings = chart.block.settings
    if parameter in ("EN_IL", "EN_SV"):
        return " := TRUE"
    if parameter == "EN_ACKREQ":
        return " := TRUE" if settings.acknowledge_required else ""
    if parameter == "EN_SSKIP":
        return " := TRUE" if settings.skip_steps else ""
    return ""


def interface_lines(chart: Chart, lad_temps: list[str]) -> list[str]:
    """The declaration part of the FB, between its header and BEGIN."""
    head, sections = split_declarations(chart.block.declarations)
    lines = [head] if head else []
    for kind, names in (("VAR_INPUT", chart.inputs), ("VAR_OUTPUT", chart.outputs)):
        if not names:
            continue
        lines.append(kind)
        for name in names:
            kind_of = "INT" if name in INT_PARAMETERS else "BOOL"
            lines.append(f"  {name} : {kind_of}{_initial(name, chart)};")
        lines.append("END_VAR")
    if sections:
        lines.append(sections)
    lines.append("VAR")
    lines += ["  G7_MODE : INT := 1;", "  G7_STARTED : BOOL;", "  G7_TICK : DINT;"]
    lines += [f"  G7_M_{name} : BOOL;" for name in EDGE_INPUTS if name in chart.inputs]
    lines += ["  G7_DISP : INT;", "  G7_IL_OFF : BOOL;", "  G7_SV_OFF : BOOL;"]
    lines += ["  G7_CMD : INT;", "  G7_CMD_STEP : INT;"]
    for step in chart.steps:
        lines.append(f"  {step.name} : STRUCT")
        bits = ("X", *STEP_EVENTS, "LA", "VA", "PS1", "PS0")
        lines += [f"    {bit} : BOOL;" for bit in bits]
        lines.append(f"    SNO : INT := {step.number};")
        lines += ["    T : TIME;", "    U : TIME;", "  END_STRUCT;"]
    for transition in chart.transitions:
        lines.append(f"  {transition.name} : STRUCT")
        lines += ["    TT : BOOL;", f"    TNO : INT := {transition.number};", "  END_STRUCT;"]
    lines.append("END_VAR")
    lines.append("VAR_TEMP")
    lines += [f"  {name} : {kind_of};" for name, kind_of in TEMPS]
    lines += [f"  {name} : BOOL;" for name in lad_temps]
    lines.append("END_VAR")
    return lines
