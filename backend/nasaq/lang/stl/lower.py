"""A block's statements → ``ir.Instruction``s with origins, networks and labels.

Mnemonics become international IR ops (``mnemonics``), operands IR operands (``resolve``),
checked per op (``check``); CALLs go through ``calls``. Labels are block-local (STEP 7):
jumps are collected here and resolved once every block is lowered, so a jump to a label of
another block gets its own message.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nasaq.diagnostics import Severity, entry
from nasaq.ir import (
    Block,
    Constant,
    ConstType,
    Instruction,
    LabelRef,
    MultiInstance,
    Network,
    Operand,
    Origin,
)
from nasaq.lang.stl import ast
from nasaq.lang.stl.calls import AutoInstance, CallLowerer
from nasaq.lang.stl.check import JUMPS, RULES, check_operand, expected_text
from nasaq.lang.stl.constants import NOT_LOADABLE
from nasaq.lang.stl.mnemonics import NAMES, TEST_OPS, other_language, to_international
from nasaq.lang.stl.resolve import Resolver, Scope, cache_key, operand_text

KEYWORDS = frozenset(
    [
        "BEGIN",
        "END_ORGANIZATION_BLOCK",
        "END_FUNCTION_BLOCK",
        "END_FUNCTION",
        "END_DATA_BLOCK",
        "END_TYPE",
        "END_VAR",
        "END_STRUCT",
        "VAR",
        "VAR_INPUT",
        "VAR_OUTPUT",
        "VAR_IN_OUT",
        "VAR_TEMP",
        "STRUCT",
        "ARRAY",
        "AUTHOR",
        "FAMILY",
        "NAME",
        "VERSION",
        "KNOW_HOW_PROTECT",
        "ORGANIZATION_BLOCK",
        "FUNCTION_BLOCK",
        "FUNCTION",
        "DATA_BLOCK",
        "TYPE",
    ]
)
ASSERTS = frozenset(op for op in TEST_OPS if op.startswith("__ASSERT"))
MAX_LABEL = 4
BRACKET_OPENERS = frozenset({"A(", "AN(", "O(", "ON(", "X(", "XN("})
BRACKET_OPS = BRACKET_OPENERS | {")", "MCR(", ")MCR"}
MAX_BRACKET_NESTING = 7  # the S7-300/400 nesting stack
MAX_MCR_NESTING = 8  # the MCR stack


@dataclass(slots=True)
class Jump:
    label: str
    loc: ast.Loc


@dataclass(slots=True)
class LoweredCode:
    code: list[Instruction] = field(default_factory=list)
    networks: list[Network] = field(default_factory=list)
    labels: dict[str, int] = field(default_factory=dict)
    jumps: list[Jump] = field(default_factory=list)


class CodeLowerer:
    def __init__(self, scope: Scope, lines: list[str], auto: dict[int, AutoInstance]) -> None:
        self.scope = scope
        self.lines = lines
        self.resolver = Resolver(scope)
        self.calls = CallLowerer(scope, self.resolver, auto)
        self.out = LoweredCode()
        self.label_lines: dict[str, int] = {}
        self.last_call: tuple[Instruction, ast.InstrNode] | None = None
        self.open_brackets: list[tuple[str, ast.Loc]] = []  # "A(" ... in source order
        self.open_mcr: list[ast.Loc] = []
        # Generated code (SCL) gives many instructions one source position, and repeats the
        # same instructions: origins, ops and simple instructions are worked out once each.
        self._origins: dict[int, Origin] = {}  # by id of the source position
        self._last_where: ast.Loc | None = None
        self._last_origin = Origin("", 0, 0)
        self._ops: dict[str, str] = {}
        self._simple: dict[tuple[object, ...], tuple[str, Operand | None]] = {}
        self._labels: dict[str, LabelRef] = {}

    # ---- items ------------------------------------------------------------------------------

    def lower(self, items: list[ast.CodeItem]) -> LoweredCode:
        pending: list[ast.LabelNode] = []
        for item in items:
            if isinstance(item, ast.InstrNode):
                if item.param_line:
                    self.param_line(item)
                    continue
                if self.last_call is not None:
                    self.finish_call()
                instruction = self.instruction(item)
                if pending:
                    self.define_label(pending.pop(), instruction)
                self.out.code.append(instruction)
                if instruction.op in BRACKET_OPS:
                    self.track_brackets(instruction.op, item.loc)
                continue
            self.finish_call()
            if isinstance(item, ast.NetworkNode):
                self.out.networks.append(Network("", len(self.out.code), self.comment(item.loc)))
                self._last_where = None
                self.flush_labels(pending)
                self.last_call = None
            elif isinstance(item, ast.TitleNode):
                if not self.out.networks:
                    self.out.networks.append(Network("", len(self.out.code)))
                    self._last_where = None
                network = self.out.networks[-1]
                network.title = network.title or item.text
                network.comment = network.comment or self.comment(item.loc)
            elif isinstance(item, ast.LabelNode):
                self.flush_labels(pending)
                pending.append(item)
        self.finish_call()
        self.flush_labels(pending)
        self.unclosed_brackets()
        if self.out.code and not self.out.networks:
            self.out.networks.append(Network("", 0))
        return self.out

    # ---- brackets ---------------------------------------------------------------------------

    def track_brackets(self, op: str, where: ast.Loc) -> None:
        """Bracket nesting in source order, as STEP 7 checks it when it compiles a block: a
        ``)`` must close an open ``A(``..., at most 7 are open at once, all are closed at the end.
        MCR areas are checked the same way (at most 8)."""
        if op == "MCR(":
            if len(self.open_mcr) == MAX_MCR_NESTING:
                self.scope.report("STL240", where, op=op, limit=MAX_MCR_NESTING)
            self.open_mcr.append(where)
        elif op == ")MCR":
            if not self.open_mcr:
                self.scope.report("STL239", where, op=op)
            else:
                self.open_mcr.pop()
        elif op.endswith("(") and op in BRACKET_OPENERS:
            if len(self.open_brackets) == MAX_BRACKET_NESTING:
                self.scope.report("STL240", where, op=op, limit=MAX_BRACKET_NESTING)
            self.open_brackets.append((op, where))
        elif op == ")":
            if not self.open_brackets:
                self.scope.report("STL239", where, op=op)
            else:
                self.open_brackets.pop()

    def unclosed_brackets(self) -> None:
        for op, where in self.open_brackets:
            self.scope.report("STL238", where, op=op, line=where.line)
        for where in self.open_mcr:
            self.scope.report("STL238", where, op="MCR(", line=where.line)

    def comment(self, where: ast.Loc) -> str:
        """The whole-line ``//`` comments right below a NETWORK or TITLE line."""
        found: list[str] = []
        number = where.line  # the next line, 0-based
        while number < len(self.lines):
            text = self.lines[number].strip()
            if not text.startswith("//"):
                break
            found.append(text[2:].strip())
            number += 1
        return "\n".join(found)

    def flush_labels(self, pending: list[ast.LabelNode]) -> None:
        for label in pending:
            self.scope.report("STL230", label.loc, label=label.name)
        pending.clear()

    def define_label(self, label: ast.LabelNode, instruction: Instruction) -> None:
        name = label.name.upper()
        if name in self.label_lines:
            self.scope.report("STL208", label.loc, label=label.name, line=self.label_lines[name])
            return
        if len(name) > MAX_LABEL:
            self.scope.report("STL209", label.loc, label=label.name)
        self.label_lines[name] = label.loc.line
        self.out.labels[name] = len(self.out.code)
        instruction.label = name

    def param_line(self, item: ast.InstrNode) -> None:
        """``NAME := value`` under a ``CALL`` without parentheses (the STEP 7 editor's form)."""
        if self.last_call is None:
            self.scope.report("STL227", item.loc, name=item.mnemonic)
            return
        _, node = self.last_call
        value = item.operands[0] if item.operands else None
        node.args = [*(node.args or []), ast.CallArgNode(item.mnemonic, value, item.loc)]

    def finish_call(self) -> None:
        """Lowers a CALL once its parameter lines (if any) have been collected."""
        if self.last_call is None:
            return
        instruction, node = self.last_call
        self.last_call = None
        instruction.call = self.calls.call(node)
        if instruction.call is not None:
            instruction.operand = instruction.call.block

    # ---- one instruction --------------------------------------------------------------------

    def origin(self, where: ast.Loc) -> Origin:
        """Where an instruction comes from. The instructions of one SCL statement follow each
        other: ``instruction`` takes the last origin again when ``where`` is the same (``lower``
        forgets it when a network starts)."""
        network = len(self.out.networks) or 1
        found = self._origins.get(id(where))  # the syntax tree keeps each ``where`` alive
        if found is None or found.network != network:
            found = Origin(self.scope.file, where.line, where.column, network)
            self._origins[id(where)] = found
        self._last_where, self._last_origin = where, found
        return found

    def op_of(self, node: ast.InstrNode) -> str | None:
        """The international op of an instruction (None: reported); known mnemonics once."""
        found = self._ops.get(node.mnemonic)
        if found is None:
            found = self._op_of(node)
            if found is not None:
                self._ops[node.mnemonic] = found
        return found

    def _op_of(self, node: ast.InstrNode) -> str | None:
        mnemonic = node.mnemonic.upper()
        if mnemonic in KEYWORDS:
            self.scope.report("STL108", node.loc, keyword=node.mnemonic)
            return None
        op = to_international(mnemonic, self.scope.language)
        if op is not None:
            return op
        if mnemonic in TEST_OPS:
            if self.scope.test_ops:
                return mnemonic
            self.scope.report("STL218", node.loc, mnemonic=node.mnemonic)
            return None
        other = other_language(mnemonic, self.scope.language)
        hint = ""
        if other is not None:
            hint = (
                f" (it is {NAMES[other]}; this file uses the "
                f"{NAMES[self.scope.language]} mnemonics)"
            )
        self.scope.report("STL201", node.loc, mnemonic=node.mnemonic, hint=hint)
        return None

    def instruction(self, node: ast.InstrNode) -> Instruction:
        """The IR instruction of a statement. A jump or an instruction with at most one operand,
        written as one before, is that one again (at its own origin), unless that one reported
        something."""
        where = node.loc
        origin = self._last_origin if where is self._last_where else self.origin(where)
        key = _simple_key(node)
        known = self._simple.get(key) if key is not None else None
        if known is not None:
            op, operand = known
            if isinstance(operand, LabelRef):  # a jump: its label is resolved at the end
                self.out.jumps.append(Jump(operand.name, node.operands[0].loc))
            return Instruction(op, operand, origin)
        reported = len(self.scope.diagnostics)
        instruction = self.new_instruction(node, origin)
        op = instruction.op
        repeatable = op != "CALL" and op not in ASSERTS and op != "__FEATURE"
        if key is not None and repeatable and len(self.scope.diagnostics) == reported:
            self._simple[key] = (op, instruction.operand)
        return instruction

    def new_instruction(self, node: ast.InstrNode, origin: Origin) -> Instruction:
        op = self.op_of(node)
        if op is None:
            return Instruction(node.mnemonic.upper(), None, origin)
        instruction = Instruction(op, None, origin)
        if node.args is not None and op != "CALL":
            self.scope.report("STL203", node.loc, mnemonic=node.mnemonic)
        if op == "CALL":
            if node.args is None:
                self.last_call = (instruction, node)  # parameter lines may follow
            else:
                instruction.call = self.calls.call(node)
                if instruction.call is not None:
                    instruction.operand = instruction.call.block
        elif op in JUMPS:
            instruction.operand = self.jump(node)
        elif op in ASSERTS or op == "__FEATURE":
            self.two_operands(node, op, instruction)
        else:
            instruction.operand = self.single(node, op)
        return instruction

    def jump(self, node: ast.InstrNode) -> LabelRef | None:
        if len(node.operands) != 1:
            self.scope.report("STL202", node.loc, mnemonic=node.mnemonic, expected="a label")
            return None
        target = node.operands[0]
        name: str | None = None
        if (
            isinstance(target, ast.AddressNode)
            and " " not in target.text
            and "\t" not in (target.text)
        ):
            name = target.text
        elif isinstance(target, ast.BareNode) and target.arg is None:
            name = target.name
        if name is None:
            self.scope.report(
                "STL204",
                target.loc,
                mnemonic=node.mnemonic,
                operand=_text(target),
                expected="a label",
            )
            return None
        label = name.upper()
        self.out.jumps.append(Jump(label, target.loc))
        found = self._labels.get(label)
        if found is None:
            found = self._labels[label] = LabelRef(label)
        return found

    def two_operands(self, node: ast.InstrNode, op: str, instruction: Instruction) -> None:
        count = len(node.operands)
        if count != 2 and not (op == "__FEATURE" and count == 1):
            self.scope.report("STL202", node.loc, mnemonic=node.mnemonic, expected="two operands")
            return
        found = [self.resolver.operand(operand) for operand in node.operands]
        if any(item is None for item in found):
            return
        operands = [item.operand for item in found if item is not None]
        for operand, source in zip(operands, node.operands, strict=True):
            if isinstance(operand, Constant) and operand.type in NOT_LOADABLE:
                reason = NOT_LOADABLE[operand.type]
                self.scope.report("STL107", source.loc, text=operand.text, reason=reason)
                return
        if op == "__FEATURE" and not all(isinstance(item, Constant) for item in operands):
            self.scope.report(
                "STL204",
                node.loc,
                mnemonic=node.mnemonic,
                operand=_text(node.operands[0]),
                expected="a constant",
            )
            return
        instruction.operand = _plain(operands[0])
        instruction.operand2 = _plain(operands[1]) if len(operands) > 1 else None

    def single(self, node: ast.InstrNode, op: str) -> Operand | None:
        rule = RULES.get(op)
        if not node.operands:
            if rule is not None and not rule.optional:
                self.scope.report(
                    "STL202", node.loc, mnemonic=node.mnemonic, expected=expected_text(rule.kinds)
                )
            return None
        if rule is None:
            self.scope.report("STL203", node.operands[0].loc, mnemonic=node.mnemonic)
            return None
        if len(node.operands) > 1:
            extra = node.operands[1]
            self.scope.report(
                "STL204",
                extra.loc,
                mnemonic=node.mnemonic,
                operand=_text(extra),
                expected=expected_text(rule.kinds),
            )
            return None
        resolved = self.resolver.operand(node.operands[0])
        if resolved is None:
            return None
        problem_found = check_operand(op, resolved)
        if problem_found is not None:
            code, params = problem_found
            if code == "STL204" or code == "STL203" or code == "STL214":
                params = {**params, "mnemonic": node.mnemonic} if "mnemonic" in params else params
            self.scope.report(code, node.operands[0].loc, **params)
            if entry(code).severity is not Severity.WARNING:
                return None  # a warning (e.g. STL237) keeps the operand as written
        return _plain(resolved.operand)


def _simple_key(node: ast.InstrNode) -> tuple[object, ...] | None:
    """What an instruction with at most one operand is lowered from (None for others): its
    mnemonic and ``resolve.cache_key`` of the operand."""
    if node.args is not None or len(node.operands) > 1:
        return None
    if not node.operands:
        return (node.mnemonic,)
    return cache_key(node.operands[0], node.mnemonic)


def _plain(operand: Operand | MultiInstance) -> Operand | None:
    return None if isinstance(operand, MultiInstance) else operand


def _text(node: ast.OperandNode) -> str:
    return operand_text(node)


def apply_code(block: Block, lowered: LoweredCode) -> None:
    block.code = lowered.code
    block.networks = lowered.networks
    block.labels = lowered.labels


__all__ = ["CodeLowerer", "ConstType", "Jump", "LoweredCode", "apply_code"]
