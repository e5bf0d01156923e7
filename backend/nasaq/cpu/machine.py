"""The register file and run-time state that generated code reads and writes as ``m``.

Compiled blocks keep registers in locals and synchronise with this object at block entry and
exit and around calls, so these attributes are the truth only between blocks.
"""

from __future__ import annotations

import operator

from nasaq.cpu.errors import CpuError

MCR_LEVELS = 8


class Machine:
    __slots__ = (
        "a1",
        "a2",
        "a3",
        "a4",
        "ar1",
        "ar2",
        "br",
        "cc0",
        "cc1",
        "db",
        "dbno",
        "depth",
        "di",
        "dino",
        "fc",
        "lim",
        "lstack",
        "mcr",
        "mcr_stack",
        "n",
        "now",
        "orb",
        "os",
        "ov",
        "priority",
        "rlo",
        "sta",
        "vptrs",
    )

    def __init__(self) -> None:
        self.now = 0
        self.n = 0
        self.lim = 1 << 62
        self.vptrs: list[int] = []  # ``L P##param`` of the running FC, by parameter slot
        self.reset_registers()

    def reset_registers(self) -> None:
        self.a1 = self.a2 = self.a3 = self.a4 = 0
        self.ar1 = self.ar2 = 0
        self.fc = self.rlo = self.sta = self.orb = 0
        self.os = self.ov = self.cc0 = self.cc1 = self.br = 0
        self.db = self.di = bytearray()
        self.dbno = self.dino = 0
        self.mcr = 1
        self.mcr_stack: list[int] = []
        self.depth = 0
        self.lstack = 0
        self.priority = 1

    def sleep(self, ms: int) -> None:
        """``__SLEEP ms``: the virtual clock moves on in the middle of the scan."""
        self.now += max(0, ms)

    def mcr_push(self, rlo: int) -> None:
        if len(self.mcr_stack) >= MCR_LEVELS:
            raise CpuError("SIM510")
        self.mcr_stack.append(self.mcr)
        self.mcr = self.mcr & rlo

    def mcr_pop(self) -> None:
        if not self.mcr_stack:
            raise CpuError("SIM511")
        self.mcr = self.mcr_stack.pop()

    def save(self) -> tuple[object, ...]:
        saved: tuple[object, ...] = _SAVE(self)
        return saved

    def restore(self, saved: tuple[object, ...]) -> None:
        for name, value in zip(_SAVED, saved, strict=True):
            setattr(self, name, value)


_SAVED = (
    "a1",
    "a2",
    "a3",
    "a4",
    "ar1",
    "ar2",
    "fc",
    "rlo",
    "sta",
    "orb",
    "os",
    "ov",
    "cc0",
    "cc1",
    "br",
    "db",
    "dbno",
    "di",
    "dino",
    "mcr",
    "depth",
    "lstack",
    "priority",
)
_SAVE = operator.attrgetter(*_SAVED)  # one C call instead of 23 getattr (once per OB run)
