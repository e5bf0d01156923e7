"""Names: steps and transitions become members of the instance DB, and conditions and
arithmetic refer to them as step variables (GRA280–GRA291).

Decisions:

- A step or transition name is an identifier (letters, digits, ``_``, not starting with a
  digit), not one of the words the STL parser reserves (``BEGIN``, ``VAR`` …), unique among
  all steps and transitions of the FB without regard to case (each is a DB member), and
  different from the FB parameters of the chosen set (``INIT_SQ`` …), from the user's own
  declarations and from the sequencer's reserved ``G7_`` names (SEMANTICS.md §1).
- The user's declarations may not start with ``G7_`` nor repeat a parameter of the set.
- A step named ``S<k>`` while another step has the number k (or a transition ``T<k>`` and
  transition k) is a warning: ``S<k>.X`` and ``ON S<k>`` then mean the named one.
- Step variables (``Fill.X``, ``S3.T``, ``#Trans2.TT``, ``T2.TT``) in conditions, permanent
  networks and arithmetic must name an existing step (``.X .T .U``) or transition (``.TT``).
  A dotted name whose first part the user declared (a STRUCT, a multi-instance) or a data
  block (``DB5.X``) is not a step variable. A time (``.T``, ``.U``) in a contact and a bit
  (``.X``, ``.TT``) in a comparator are refused where the operand is just that variable.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check_conditions import is_comparator, leaves
from nasaq.lang.graph.check_context import BlockContext, step_key, transition_key
from nasaq.lang.graph.lower_chart import INPUTS, OUTPUTS
from nasaq.lang.graph.model import Step, Transition
from nasaq.lang.lad.model import Box, Contact, Network, Series

# The FB parameters of each set (SEMANTICS.md §1), as the lowering declares them.
PARAMETERS: dict[str, tuple[str, ...]] = {
    name: (*INPUTS[name], *OUTPUTS[name])
    for name in ("MINIMUM", "STANDARD", "MAXIMUM", "USER_DEFINED")
}
RESERVED_PREFIX = "G7_"
# Words the STL parser reads as keywords wherever they stand: no DB member can be named so.
RESERVED_WORDS = frozenset(
    {
        "ORGANIZATION_BLOCK",
        "FUNCTION_BLOCK",
        "FUNCTION",
        "DATA_BLOCK",
        "TYPE",
        "END_ORGANIZATION_BLOCK",
        "END_FUNCTION_BLOCK",
        "END_FUNCTION",
        "END_DATA_BLOCK",
        "END_TYPE",
        "BEGIN",
        "END_VAR",
        "END_STRUCT",
        "VAR",
        "VAR_INPUT",
        "VAR_OUTPUT",
        "VAR_IN_OUT",
        "VAR_TEMP",
    }
)
_IDENTIFIER = re.compile(r"[A-Za-z_]\w*", re.ASCII)
_NUMBERED = re.compile(r"([ST])(\d+)", re.IGNORECASE)
_QUOTED = re.compile(r"\"[^\"]*\"|'[^']*'")
_REFERENCE = re.compile(r"(?<![\w#.])#?([A-Za-z_]\w*)\.([A-Za-z_]\w*)(?![\w.\[])", re.ASCII)
_DATA_BLOCK = re.compile(r"D[BI]\d+", re.IGNORECASE)
STEP_MEMBERS = frozenset({"X", "T", "U"})
TRANSITION_MEMBERS = frozenset({"TT"})


def check_names(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    found += _declarations(ctx)
    found += _own_names(ctx)
    found += _references(ctx)
    return found


def _declarations(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    parameters = {name.upper() for name in PARAMETERS[ctx.block.settings.parameters]}
    for declared in ctx.declared:
        if declared.name.upper().startswith(RESERVED_PREFIX):
            found.append(ctx.problem("GRA283", "BLOCK", name=declared.name))
        elif declared.name.upper() in parameters:
            found.append(
                ctx.problem(
                    "GRA285", "BLOCK", name=declared.name, set=ctx.block.settings.parameters
                )
            )
    return found


def _own_names(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    parameters = {name.upper() for name in PARAMETERS[ctx.block.settings.parameters]}
    named: dict[str, tuple[int, str]] = {}  # upper name → (position, key) of its first owner
    owners = [(step_key(step), step.name) for _, step in ctx.steps]
    owners += [(transition_key(transition), transition.name) for _, transition in ctx.transitions]
    for position, (key, name) in enumerate(owners):
        upper = name.upper()
        if _IDENTIFIER.fullmatch(name) is None:
            found.append(ctx.problem("GRA280", key, name=name, owner=key))
            continue
        if upper in RESERVED_WORDS:
            found.append(ctx.problem("GRA286", key, name=name, owner=key))
        elif upper.startswith(RESERVED_PREFIX):
            found.append(ctx.problem("GRA283", key, name=name))
        elif upper in parameters:
            found.append(
                ctx.problem("GRA282", key, name=name, owner=key, set=ctx.block.settings.parameters)
            )
        elif upper in ctx.declared_names:
            found.append(ctx.problem("GRA284", key, name=name, owner=key))
        first, first_key = named.setdefault(upper, (position, key))
        if first != position:
            found.append(ctx.problem("GRA281", key, name=name, owner=key, other=first_key))
        found += _numbered_like_another(ctx, key, name)
    return found


def _numbered_like_another(ctx: BlockContext, key: str, name: str) -> list[Diagnostic]:
    numbered = _NUMBERED.fullmatch(name)
    if numbered is None:
        return []
    number = int(numbered.group(2))
    kind = numbered.group(1).upper()
    other: Step | Transition | None
    if kind == "S" and key.startswith("S"):
        other, other_key = ctx.step_by_number.get(number), f"S{number}"
    elif kind == "T" and key.startswith("T"):
        other, other_key = ctx.transition_by_number.get(number), f"T{number}"
    else:
        return []
    if other is None or other_key == key:
        return []
    return [
        ctx.problem("GRA287", key, name=name, owner=key, other=other_key, other_name=other.name)
    ]


# ---- step variables ---------------------------------------------------------------------------


def _operands(series: Series) -> Iterator[tuple[str, str, str]]:
    """(operand, where it is used: contact, compare or other, element id) in ``series``."""
    for element in leaves(series):
        if isinstance(element, Contact):
            yield element.operand, "contact", element.id
        elif isinstance(element, Box):
            use = "compare" if is_comparator(element) else "other"
            for pin in element.inputs.values():
                if isinstance(pin, str):
                    yield pin, use, element.id
            for out in element.outputs.values():
                yield out, "other", element.id
        else:
            operand = getattr(element, "operand", None)
            if isinstance(operand, str):
                yield operand, "other", element.id


def _network_series(network: Network) -> Iterator[Series]:
    yield network.logic
    for output in network.outputs:
        yield output.conditions


def _references(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    places: list[tuple[str, Series]] = []
    for _, transition in ctx.transitions:
        if transition.condition is not None:
            places.append((transition_key(transition), transition.condition))
    for _, step in ctx.steps:
        for series, part in ((step.interlock, "C"), (step.supervision, "V")):
            if series is not None:
                places.append((f"{step_key(step)}/{part}", series))
    for prefix, networks in (("PRE", ctx.block.pre), ("POST", ctx.block.post)):
        for number, network in enumerate(networks, start=1):
            places += [(f"{prefix}{number}", series) for series in _network_series(network)]
    for key, series in places:
        for operand, use, element in _operands(series):
            where = f"{key}/{element}" if element else key
            found += _operand(ctx, operand, use, key, where)
    for _, step in ctx.steps:
        for k, action in enumerate(step.actions, start=1):
            if ":=" in action.operand:
                found += _operand(ctx, action.operand, "other", f"{step_key(step)}/A{k}", None)
    return found


def _operand(
    ctx: BlockContext, operand: str, use: str, key: str, where: str | None
) -> list[Diagnostic]:
    if "." not in operand:
        return []
    found: list[Diagnostic] = []
    text = operand
    if '"' in text or "'" in text:
        text = _QUOTED.sub(lambda match: " " * len(match.group(0)), text)
    for match in _REFERENCE.finditer(text):
        name, member = match.group(1), match.group(2).upper()
        if name.upper() in ctx.declared_names or _DATA_BLOCK.fullmatch(name):
            continue
        reference = match.group(0)
        target: Step | Transition | None
        other: Step | Transition | None
        if member in STEP_MEMBERS:
            target = ctx.step_reference(name)
            other = None if target is not None else ctx.transition_reference(name)
        elif member in TRANSITION_MEMBERS:
            target = ctx.transition_reference(name)
            other = None if target is not None else ctx.step_reference(name)
        else:
            if ctx.step_reference(name) is not None or ctx.transition_reference(name) is not None:
                found.append(ctx.problem("GRA289", key, where, reference=reference))
            continue
        if target is None and other is None:
            found.append(ctx.problem("GRA288", key, where, reference=reference, name=name))
            continue
        if target is None:
            found.append(ctx.problem("GRA289", key, where, reference=reference))
            continue
        if reference != text.strip():
            continue
        if use == "contact" and member in ("T", "U"):
            found.append(ctx.problem("GRA290", key, where, reference=reference))
        elif use == "compare" and member in ("X", "TT"):
            found.append(ctx.problem("GRA291", key, where, reference=reference))
    return found
