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
from nasaq.lang.profiles import is_s7_1500
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
# Lowered at every use: a CALL's parameters, the test ops' two operands.
NOT_KEPT = ASSERTS | {"CALL", "__FEATURE"}


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


# An instruction lowered before, by the key ``CodeLowerer.lower`` makes: its op and operand,
# and whether ``CodeLowerer.follow`` has something to do for it (a jump or a bracket).
Known = tuple[str, Operand | None, bool]
# The instructions that every block of a compilation lowers alike (those without a local
# variable), lowered once: shared by the blocks of one mnemonic language.
Shared = dict[object, Known]


class CodeLowerer:
    def __init__(
        self,
        scope: Scope,
        lines: list[str],
        auto: dict[int, AutoInstance],
        shared: Shared | None = None,
        elements: list[str | None] | None = None,
    ) -> None:
        self.scope = scope
        self.lines = lines
        # The LAD/FBD element of each source line (a LAD file's generated STL), else None.
        self.elements = elements
        self.resolver = Resolver(scope)
        self.calls = CallLowerer(scope, self.resolver, auto)
        self.out = LoweredCode()
        self.label_lines: dict[str, int] = {}
        self.last_call: tuple[Instruction, ast.InstrNode] | None = None
        self.open_brackets: list[tuple[str, ast.Loc]] = []  # "A(" ... in source order
        self.open_mcr: list[ast.Loc] = []
        # Generated code (SCL) gives many instructions one source position, and repeats the
        # same instructions: origins, ops and simple instructions are worked out once each.
        self._file = scope.file
        self._last_where: ast.Loc | None = None  # forgotten when a network starts
        self._last_origin = Origin("", 0, 0)
        self._ops: dict[str, str] = {}
        self._shared: Shared = {} if shared is None else shared
        self._simple: dict[object, Known] = {}

    # ---- items ------------------------------------------------------------------------------

    def lower(self, items: list[ast.CodeItem]) -> LoweredCode:
        """The code of a block. This loop is the hot path of a large compilation (the STL of
        generated SCL is 100,000s of instructions): an instruction with at most one operand,
        written as one before in the block (``_simple``) or in another (``_shared``), is that
        one again at its own origin, made right here. Both are keyed by the mnemonic and what
        ``cache_key`` of the operand would be (made here for the common operands)."""
        pending: ast.LabelNode | None = None  # a label waiting for its instruction
        simple = self._simple.get
        shared = self._shared.get
        append = self.out.code.append
        new = object.__new__
        elements = self.elements
        for item in items:
            if type(item) is not ast.InstrNode or item.param_line:
                if type(item) is ast.LabelNode and pending is None and self.last_call is None:
                    pending = item  # the label of the next instruction
                else:
                    pending = self.other_item(item, pending)
                continue
            if self.last_call is not None:
                self.finish_call()
            where = item.loc
            if where is not self._last_where:  # the instructions of an SCL statement share one
                network = len(self.out.networks) or 1
                element = None if elements is None else _element_of(elements, where.line)
                origin = Origin(self._file, where.line, where.column, network, element)
                self._last_origin = origin
                self._last_where = where
            origin = self._last_origin
            operands = item.operands
            key: object = None
            if item.args is None:
                if not operands:
                    key = item.mnemonic
                elif len(operands) == 1:
                    first = operands[0]
                    if type(first) is ast.SymbolNode and not first.path:
                        key = (
                            item.mnemonic,
                            ast.SymbolNode,
                            first.name,
                            first.local,
                            first.absolute_db,
                        )
                    elif type(first) is ast.LiteralNode:
                        key = (item.mnemonic, ast.LiteralNode, first.kind, first.text)
                    elif type(first) is ast.AddressNode:
                        key = (item.mnemonic, ast.AddressNode, first.text)
                    else:
                        key = cache_key(first, item.mnemonic)
            known = simple(key)
            if known is None:
                known = shared(key)  # lowered in another block
                if known is not None:
                    self._simple[key] = known
            if known is None:
                instruction, follow = self.instruction(item, key, origin), True
            else:  # Instruction(op, operand, origin) field by field: faster (a test pins them)
                instruction = new(Instruction)
                instruction.op = known[0]
                instruction.operand = known[1]
                instruction.origin = origin
                instruction.operand2 = instruction.label = instruction.call = None
                follow = known[2]
            if pending is not None:
                self.define_label(pending, instruction)
                pending = None
            append(instruction)
            if follow:
                self.follow(instruction, item)
        self.finish_call()
        self.flush_label(pending)
        self.unclosed_brackets()
        if self.out.code and not self.out.networks:
            self.out.networks.append(Network("", 0))
        return self.out

    def other_item(self, item: ast.CodeItem, pending: ast.LabelNode | None) -> ast.LabelNode | None:
        """A label, network, title or parameter line; the label waiting for its instruction
        after it."""
        if isinstance(item, ast.InstrNode):
            self.param_line(item)
            return pending
        if self.last_call is not None:
            self.finish_call()
        if isinstance(item, ast.LabelNode):
            self.flush_label(pending)
            return item
        if isinstance(item, ast.NetworkNode):
            self.out.networks.append(Network("", len(self.out.code), self.comment(item.loc)))
            self._last_where = None
            self.flush_label(pending)
            self.last_call = None
            return None
        if isinstance(item, ast.TitleNode):
            if not self.out.networks:
                self.out.networks.append(Network("", len(self.out.code)))
                self._last_where = None
            network = self.out.networks[-1]
            network.title = network.title or item.text
            network.comment = network.comment or self.comment(item.loc)
        return pending

    # ---- jumps and brackets -----------------------------------------------------------------

    def follow(self, instruction: Instruction, node: ast.InstrNode) -> None:
        """What an instruction leaves to check: a jump its label (once the block is lowered),
        a bracket its nesting, in source order, as STEP 7 checks it when it compiles a block:
        a ``)`` must close an open ``A(``..., at most 7 are open at once, all are closed at the
        end. MCR areas are checked the same way (at most 8)."""
        op = instruction.op
        if op == ")":
            if self.open_brackets:
                self.open_brackets.pop()
            else:
                self.scope.report("STL239", node.loc, op=op)
        elif op in BRACKET_OPENERS:
            if len(self.open_brackets) == MAX_BRACKET_NESTING:
                self.scope.report("STL240", node.loc, op=op, limit=MAX_BRACKET_NESTING)
            self.open_brackets.append((op, node.loc))
        elif type(instruction.operand) is LabelRef:
            self.out.jumps.append(Jump(instruction.operand.name, node.operands[0].loc))
        elif op == "MCR(":
            if len(self.open_mcr) == MAX_MCR_NESTING:
                self.scope.report("STL240", node.loc, op=op, limit=MAX_MCR_NESTING)
            self.open_mcr.append(node.loc)
        elif op == ")MCR":
            if self.open_mcr:
                self.open_mcr.pop()
            else:
                self.scope.report("STL239", node.loc, op=op)

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

    def flush_label(self, pending: ast.LabelNode | None) -> None:
        """A label that no instruction follows."""
        if pending is not None:
            self.scope.report("STL230", pending.loc, label=pending.name)

    def define_label(self, label: ast.LabelNode, instruction: Instruction) -> None:
        name = label.name.upper()
        if name in self.label_lines:
            self.scope.report("STL208", label.loc, label=label.name, line=self.label_lines[name])
            return
        if len(name) > MAX_LABEL and not is_s7_1500(self.scope.index.profile):
            self.scope.report("STL209", label.loc, label=label.name)  # TIA's S7-1500: longer
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

    def instruction(self, node: ast.InstrNode, key: object, origin: Origin) -> Instruction:
        """An instruction not lowered before in this block. It is kept by ``key`` (None: not
        kept) for the next ones written the same, unless lowering it reported something
        (reported again at each), and for the other blocks when it means the same in every
        block."""
        reported = len(self.scope.diagnostics)
        instruction = self.new_instruction(node, origin)
        op = instruction.op
        if key is not None and op not in NOT_KEPT and len(self.scope.diagnostics) == reported:
            operand = instruction.operand
            follow = type(operand) is LabelRef or op in BRACKET_OPS
            self._simple[key] = known = (op, operand, follow)
            if _same_in_every_block(node):
                self._shared[key] = known
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
        return LabelRef(name.upper())  # ``follow`` keeps the jump for ``resolve_jumps``

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


def _same_in_every_block(node: ast.InstrNode) -> bool:
    """Whether an instruction is lowered the same in every block (of one mnemonic language):
    not when its operand may name a local variable (``#x``, ``P##x``, ``DBW [#p]``)."""
    if not node.operands:
        return True
    operand = node.operands[0]
    if isinstance(operand, ast.SymbolNode):
        return not operand.local
    if isinstance(operand, ast.LiteralNode):
        return not operand.text[2:].startswith("#")
    return not isinstance(operand, ast.IndirectNode)


def _plain(operand: Operand | MultiInstance) -> Operand | None:
    return None if isinstance(operand, MultiInstance) else operand


def _text(node: ast.OperandNode) -> str:
    return operand_text(node)


def apply_code(block: Block, lowered: LoweredCode) -> None:
    block.code = lowered.code
    block.networks = lowered.networks
    block.labels = lowered.labels


def _element_of(elements: list[str | None], line: int) -> str | None:
    return elements[line - 1] if 0 < line <= len(elements) else None


__all__ = ["CodeLowerer", "ConstType", "Jump", "LoweredCode", "apply_code"]
