"""Writes Graph blocks in the ``.graph`` text format that ``text_parse`` reads.

The layout is canonical, so a chart saved twice gives the same text and a change gives a small
diff: per sequencer, the steps in their order, each followed by the transitions that leave it
(whose first source it is), in ``Sequencer.transitions`` order. The reader keeps steps and
transitions in the order of the file, so to read back the same model the printer never reorders
transitions: a transition whose first source step comes later than the next transition's is
written after the step its predecessor followed (any interleaving keeps both orders). Conditions
and permanent networks are written by the LAD printer, one element a line; ids equal to their
reading-order number (``e<n>`` per condition, ``a<n>`` per step) are left out.
"""

from __future__ import annotations

from nasaq.lang.graph.model import Action, GraphBlock, Sequencer, Settings, Step, Transition
from nasaq.lang.lad.model import Network, Series
from nasaq.lang.lad.text_print import network_lines, series_lines

INDENT = "  "


def _one_line(text: str) -> str:
    return " ".join(text.split("\n")).strip()


def _comment_lines(text: str) -> list[str]:
    return [f"COMMENT = {line}".rstrip() for line in text.split("\n")] if text else []


def _names(names: list[str]) -> str:
    return names[0] if len(names) == 1 else f"({', '.join(names)})"


def action_line(action: Action, number: int) -> str:
    """One action row (without indentation); ``number`` is its 1-based place in the step."""
    parts: list[str] = [action.event] if action.event else []
    parts.append(action.qualifier + ("C" if action.interlock else ""))
    parts.append(action.operand)
    line = " ".join(parts)
    if action.time is not None:
        line += f", {action.time}"
    if action.id and action.id != f"a{number}":
        line += f" @{action.id}"
    line += ";"
    if action.comment:
        line += f"  // {_one_line(action.comment)}"
    return line


def _condition(opener: str, series: Series | None) -> list[str]:
    if series is None:
        return []
    if not series.elements:
        return [f"{opener} END_{opener}"]
    return [opener, *series_lines(series, 1), f"END_{opener}"]


def step_lines(step: Step) -> list[str]:
    keyword = "INITIAL_STEP" if step.initial else "STEP"
    lines = [f"{keyword} {step.name} ({step.number})", *_comment_lines(step.comment)]
    lines += _condition("INTERLOCK", step.interlock)
    lines += _condition("SUPERVISION", step.supervision)
    if step.actions:
        lines.append("ACTIONS")
        lines += [INDENT + action_line(a, n) for n, a in enumerate(step.actions, start=1)]
        lines.append("END_ACTIONS")
    lines.append("END_STEP")
    return lines


def transition_lines(transition: Transition) -> list[str]:
    head = f"TRANSITION {transition.name} ({transition.number}) FROM {_names(transition.source)}"
    if not transition.target:
        head += " STOP"
    else:
        head += f" {'JUMP' if transition.jump else 'TO'} {_names(transition.target)}"
    lines = [head, *_comment_lines(transition.comment)]
    lines += _condition("CONDITION", transition.condition)
    lines.append("END_TRANSITION")
    return lines


def chart_order(sequencer: Sequencer) -> list[Step | Transition]:
    """Steps and transitions interleaved: after each step, the transitions that follow in
    ``transitions`` order as long as their first source is a step already written (or no step
    of the sequencer); whatever is left comes last."""
    names = {step.name for step in sequencer.steps}
    written: set[str] = set()
    pending = list(sequencer.transitions)
    order: list[Step | Transition] = []
    index = 0
    for step in sequencer.steps:
        order.append(step)
        written.add(step.name)
        while index < len(pending) and (
            pending[index].source[0] in written or pending[index].source[0] not in names
        ):
            order.append(pending[index])
            index += 1
    order += pending[index:]
    return order


def sequencer_lines(sequencer: Sequencer) -> list[str]:
    lines = [f"SEQUENCER {sequencer.name}", *_comment_lines(sequencer.comment)]
    for item in chart_order(sequencer):
        lines.append("")
        lines += step_lines(item) if isinstance(item, Step) else transition_lines(item)
    lines += ["", "END_SEQUENCER"]
    return lines


def _settings_lines(settings: Settings) -> list[str]:
    if settings == Settings():
        return []

    def flag(value: bool) -> str:
        return "TRUE" if value else "FALSE"

    return [
        "SETTINGS",
        f"{INDENT}PARAMETERS := {settings.parameters};",
        f"{INDENT}SKIP_STEPS := {flag(settings.skip_steps)};",
        f"{INDENT}ACKNOWLEDGE := {flag(settings.acknowledge_required)};",
        f"{INDENT}INTERLOCK_BLOCKS := {flag(settings.interlock_blocks)};",
        "END_SETTINGS",
    ]


def _permanent(kind: str, networks: list[Network]) -> list[str]:
    if not networks:
        return []
    lines = [f"PERMANENT_{kind}"]
    for network in networks:
        lines += network_lines(network)
    lines.append(f"END_PERMANENT_{kind}")
    return lines


def block_lines(block: GraphBlock) -> list[str]:
    lines = [f"FUNCTION_BLOCK {block.name}"]
    if block.title:
        lines.append(f"TITLE = {_one_line(block.title)}")
    lines += _comment_lines(block.comment)
    lines += _settings_lines(block.settings)
    if block.declarations.strip():
        lines.append(block.declarations.rstrip())
    lines.append("BEGIN")
    lines += _permanent("PRE", block.pre)
    for sequencer in block.sequencers:
        lines += ["", *sequencer_lines(sequencer)]
    if block.post:
        lines += ["", *_permanent("POST", block.post)]
    lines.append("END_FUNCTION_BLOCK")
    return lines


def print_blocks(blocks: list[GraphBlock]) -> str:
    """The text of ``blocks``, one blank line between blocks, ending with a newline."""
    return "\n".join("\n".join(block_lines(block)) + "\n" for block in blocks)
