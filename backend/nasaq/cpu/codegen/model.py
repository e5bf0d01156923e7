"""What instruction emitters produce: statements of Python source with their data flow.

Every emitted statement says which local variables it defines and uses. The compiler uses that to
drop statements whose results nobody reads (a status bit overwritten before the next reader),
which is what makes full status-word semantics affordable. Statements with effects beyond their
locals (memory writes, calls, errors) are marked ``keep``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from nasaq.cpu.profile import Profile
from nasaq.ir import Block, Instruction, Program

# Registers kept in locals inside a compiled block and synchronised with the machine at calls,
# block end and block start. a3/a4 exist only on 4-accumulator profiles.
STATUS = ("fc", "rlo", "sta", "orb", "os", "ov", "cc0", "cc1", "br")
REGISTERS = ("a1", "a2", "a3", "a4", "ar1", "ar2", *STATUS, "db", "dbno", "di", "dino")
ALL = frozenset(REGISTERS)


@dataclass(slots=True)
class Stmt:
    lines: list[str]
    defs: frozenset[str]
    uses: frozenset[str]
    keep: bool
    index: int  # instruction index in Block.code


@dataclass(slots=True)
class Term:
    """How a basic block ends. Targets are instruction indices until the compiler maps them."""

    kind: str  # "fall" | "jump" | "cond" | "ret" | "cret" | "jl"
    cond: str = ""
    uses: frozenset[str] = frozenset()
    target: int = -1
    targets: list[int] = field(default_factory=list)


@dataclass(slots=True)
class ErrorSite:
    """A place where generated code may report a runtime error: ``_ERR(k, address_bits)``."""

    index: int  # instruction
    code: str
    params: dict[str, Any]
    dynamic_area: str | None = None  # address text built at run time from this area prefix
    width: int = 0


class Ctx:
    """Emission state for one block: the statements of the current basic block, facts known
    about status bits at this point, and what the block needs bound at run time."""

    def __init__(
        self, block: Block, program: Program, profile: Profile, instrumented: bool
    ) -> None:
        self.block = block
        self.program = program
        self.profile = profile
        self.instrumented = instrumented
        self.index = 0
        self.stmts: list[Stmt] = []
        self.known: dict[str, int] = {}
        self.term: Term | None = None
        self.globals: dict[str, Any] = {}
        self.errors: list[ErrorSite] = []
        self._error_keys: dict[tuple[Any, ...], int] = {}
        self._tmp = 0
        self.frame_size = max(block.temp_bytes, 0)
        self.uses_mcr = any(ins.op == "MCRA" for ins in block.code)
        self.nest_static = True
        self.nest_depth: list[int] = []  # static nesting depth before each instruction
        self.nest_kinds: list[str] = []  # static mode: the open brackets' kinds
        self.params: dict[str, int] = {}  # FC parameter name -> slot in P
        self.param_slots: list[str] = []
        self.call_sites: list[Any] = []
        self.scratch: list[tuple[int, int]] = []  # (offset, size) reserved in the frame
        self.locals_needed: set[str] = set()
        self.param_pointers = False  # the FC loads P##param: calls must build m.vptrs
        self.v_base: int | None = None  # start of the V area its FC calls use in the frame

    # -- emission ----------------------------------------------------------------------------
    def emit(
        self,
        code: str | list[str],
        defs: Iterable[str] = (),
        uses: Iterable[str] = (),
        keep: bool = False,
        known: dict[str, int] | None = None,
    ) -> None:
        lines = [code] if isinstance(code, str) else code
        defs_set = frozenset(defs)
        self.stmts.append(Stmt(lines, defs_set, frozenset(uses), keep, self.index))
        for name in defs_set:
            self.known.pop(name, None)
        if known:
            self.known.update(known)

    def tmp(self, hint: str = "t") -> str:
        self._tmp += 1
        return f"_{hint}{self._tmp}"

    def const(self, value: Any, hint: str = "K") -> str:
        """Bind ``value`` as a global of the generated module and return its name."""
        name = f"_{hint}{len(self.globals)}"
        self.globals[name] = value
        return name

    def error_site(
        self,
        code: str,
        dynamic_area: str | None = None,
        width: int = 0,
        **params: Any,
    ) -> int:
        key = (self.index, code, dynamic_area, width, tuple(sorted(params.items())))
        found = self._error_keys.get(key)
        if found is None:
            found = len(self.errors)
            self.errors.append(ErrorSite(self.index, code, params, dynamic_area, width))
            self._error_keys[key] = found
        return found

    def error(self, code: str, **params: Any) -> None:
        """Report a runtime error here (OB121/OB122 or STOP) and continue."""
        k = self.error_site(code, **params)
        self.emit(f"_ERR({k})", keep=True)

    def guarded(self, body: list[str], fallback: list[str], exc: str = "IndexError") -> list[str]:
        return [
            "try:",
            *("    " + b for b in body),
            f"except {exc}:",
            *("    " + f for f in fallback),
        ]

    def guarded_call(self, body: list[str], on_error: str = "") -> list[str]:
        """``body`` may raise a recoverable CpuError: report it here and continue."""
        fallback = [f"_HANDLE(_e, {self.index})"]
        if on_error:
            fallback.append(on_error)
        return [
            "try:",
            *("    " + b for b in body),
            "except _CE as _e:",
            *("    " + f for f in fallback),
        ]

    def set_term(self, term: Term) -> None:
        self.term = term

    @property
    def ins(self) -> Instruction:
        return self.block.code[self.index]

    def reserve(self, size: int) -> int:
        """Reserve ``size`` bytes of the frame beyond the block's temporaries (call scratch)."""
        offset = self.frame_size
        offset += offset & 1
        self.frame_size = offset + size
        return offset

    def cover(self, end: int) -> None:
        """Make the frame at least ``end`` bytes (direct L accesses beyond the declared temps)."""
        self.frame_size = max(self.frame_size, end)


Emitter = Callable[[Ctx, Instruction], None]
