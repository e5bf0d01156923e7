"""Compiles the program's code blocks on first use and binds what their code refers to.

Generated code refers to memory, helpers and its block's error/call handlers as module globals
of its own namespace; everything is bound per CPU, so compiled functions run with no lookups
beyond local variables and these globals.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from nasaq.cpu import conversions, iec_library, realnum
from nasaq.cpu.calls import Calls
from nasaq.cpu.codegen.bit_logic import paren_close
from nasaq.cpu.codegen.compiler import Compiled, compile_block
from nasaq.cpu.counters import Counters
from nasaq.cpu.errors import CpuError, CpuStopError
from nasaq.cpu.machine import Machine
from nasaq.cpu.memory import Memory
from nasaq.cpu.profile import Profile
from nasaq.cpu.timers import Timers
from nasaq.ir import BlockKind, Program

CODE_KINDS = (BlockKind.OB, BlockKind.FC, BlockKind.FB)
EMPTY = bytearray()


def _assert_real(left: int, right: int) -> bool:
    a, b = realnum.to_float(left), realnum.to_float(right)
    if a != a or b != b:
        return a != a and b != b
    return math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-12)


class Loader:
    def __init__(
        self,
        program: Program,
        profile: Profile,
        machine: Machine,
        memory: Memory,
        timers: Timers,
        counters: Counters,
        calls: Calls,
        test_ops: bool,
        handle: Callable[[CpuError, Compiled, int], int],
        watchdog: Callable[[Compiled, int], None],
    ) -> None:
        self.program = program
        self.profile = profile
        self.handle = handle
        self.watchdog = watchdog
        self.calls = calls
        self.cache: dict[tuple[BlockKind, int], Compiled | None] = {}
        self.plain: dict[tuple[BlockKind, int], Compiled | None] = {}  # the fast compilations
        self.debug: dict[tuple[BlockKind, int], Compiled | None] = {}  # with per-instruction hooks
        self.by_filename: dict[str, Compiled] = {}
        dbs = memory.dbs

        def open_db(number: int) -> tuple[bytearray, int]:
            if number == 0:
                return EMPTY, 0
            found = dbs.get(number)
            if found is None:
                raise CpuError("SIM505", number=number)
            return found, number

        self.bind: dict[str, Any] = {
            "_I": memory.I,
            "_Q": memory.Q,
            "_M": memory.M,
            "_PI": memory.PI,
            "_PQ": memory.PQ,
            "_EMPTY": EMPTY,
            "_T": timers,
            "_C": counters,
            "_CE": CpuError,
            "_RARITH": realnum.arith,
            "_RFUNC": realnum.function,
            "_RCMP": realnum.compare,
            "_ROUND": realnum.rounded,
            "_DTR": realnum.from_dint,
            "_BTI": conversions.bti,
            "_BTD": conversions.btd,
            "_ITB": conversions.itb,
            "_DTB": conversions.dtb,
            "_SHIFT": conversions.shift,
            "_OPEN": open_db,
            "_MCR_PUSH": machine.mcr_push,
            "_MCR_POP": machine.mcr_pop,
            "_PAREN": paren_close,
            "_ASSERT_REAL": _assert_real,
            "_TEST_OPS": test_ops,
            **{f"_D{number}": buf for number, buf in dbs.items()},
        }

    def get(self, kind: BlockKind, number: int) -> Compiled | None:
        key = (kind, number)
        if key in self.cache:
            return self.cache[key]
        block = self.program.get(kind, number)
        compiled = None
        if block is not None and kind in CODE_KINDS:
            compiled = iec_library.compiled(block, self.calls.memory)  # a Python body
            if compiled is None:
                compiled = compile_block(block, self.program, self.profile, self.bind)
                self._link(compiled)
                self.by_filename[compiled.filename] = compiled
        self.cache[key] = compiled
        self.plain[key] = compiled
        return compiled

    def instrumented(
        self,
        kind: BlockKind,
        number: int,
        make_hooks: Callable[[Compiled], tuple[Callable[..., None], Callable[..., None]]],
    ) -> Compiled | None:
        """The debugger's compilation of a code block (None for data blocks, IEC library FCs
        and missing blocks); ``make_hooks(compiled)`` gives its ``_B`` and ``_H`` (see
        codegen.compiler)."""
        key = (kind, number)
        if key in self.debug:
            return self.debug[key]
        plain = self.get(kind, number)
        compiled = None
        if plain is not None and plain.line_map:  # library FCs (Python bodies) have no line map
            compiled = compile_block(
                plain.block, self.program, self.profile, self.bind, instrumented=True
            )
            self._link(compiled)
            compiled.namespace["_B"], compiled.namespace["_H"] = make_hooks(compiled)
            self.by_filename[compiled.filename] = compiled
        self.debug[key] = compiled
        return compiled

    def select(self, kind: BlockKind, number: int, debug: bool) -> None:
        """Calls from now on run the debug compilation (if there is one) or the fast one."""
        key = (kind, number)
        if key not in self.plain:
            self.get(kind, number)
        chosen = self.debug.get(key) if debug else None
        self.cache[key] = chosen if chosen is not None else self.plain[key]

    def _link(self, compiled: Compiled) -> None:
        ns = compiled.namespace
        handle, calls, watchdog = self.handle, self.calls, self.watchdog
        sites = compiled.call_sites

        def err(k: int, address: int | None = None) -> int:
            return handle(error_from_site(compiled, k, address), compiled, compiled.errors[k].index)

        def handle_here(error: CpuError, index: int) -> int:
            if isinstance(error, CpuStopError):
                raise error
            return handle(error, compiled, index)

        def call(
            k: int,
            frame: bytearray,
            vframe: bytearray,
            params: list[Any],
            target: int | None = None,
        ) -> None:
            calls.call(sites[k], compiled, frame, vframe, params, target)

        def wd(index: int) -> None:
            watchdog(compiled, index)

        ns["_ERR"] = err
        ns["_HANDLE"] = handle_here
        ns["_CALL"] = call
        ns["_WD"] = wd


def error_from_site(compiled: Compiled, k: int, address: int | None) -> CpuError:
    from nasaq.cpu.memory import address_text
    from nasaq.cpu.pointers import CODE_AREAS
    from nasaq.ir import Area

    site = compiled.errors[k]
    params = dict(site.params)
    if site.dynamic_area is not None and address is not None:
        if site.dynamic_area == "*":
            area = CODE_AREAS[(address >> 24) & 7]
        else:
            area = Area(site.dynamic_area)
        bits = address & 0x7FFFF if site.dynamic_area == "*" else address
        params["address"] = address_text(area, site.width or 8, bits >> 3, bits & 7)
    elif site.dynamic_area is not None:
        params["address"] = f"{site.dynamic_area} (computed address)"
    if site.code == "SIM503" or site.code == "SIM504":
        params.setdefault("address", "?")
    if site.code in ("SIM520", "SIM521"):
        params.setdefault("address", "?")
    return (CpuStopError if site.code == "SIM513" else CpuError)(site.code, **params)
