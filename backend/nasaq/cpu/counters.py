"""S5 counters (CU CD S R FR L LC): 0..999, counting on rising edges of the RLO."""

from __future__ import annotations

from nasaq.cpu.bcd import bcd_to_int, int_to_bcd
from nasaq.cpu.errors import CpuError


class Counters:
    def __init__(self, count: int) -> None:
        self.count = count
        self.clear()

    def clear(self, keep: int = 0) -> None:
        """Reset counters ``keep`` and up (warm restart keeps the retentive ones)."""
        n = self.count
        if keep == 0:
            self.value = [0] * n
            self.cu_edge = [0] * n
            self.cd_edge = [0] * n
            self.s_edge = [0] * n
            self.fr_edge = [0] * n
            return
        for k in range(keep, n):
            self.value[k] = 0
            self.cu_edge[k] = self.cd_edge[k] = self.s_edge[k] = self.fr_edge[k] = 0

    def check(self, number: int) -> int:
        if not 0 <= number < self.count:
            raise CpuError("SIM517", number=number, last=self.count - 1)
        return number

    def status(self, n: int) -> int:
        self.check(n)
        return 1 if self.value[n] else 0

    def load(self, n: int) -> int:
        self.check(n)
        return self.value[n]

    def load_bcd(self, n: int) -> int:
        self.check(n)
        return int_to_bcd(self.value[n], 3)

    def up(self, n: int, rlo: int) -> None:
        self.check(n)
        if rlo and not self.cu_edge[n] and self.value[n] < 999:
            self.value[n] += 1
        self.cu_edge[n] = rlo

    def down(self, n: int, rlo: int) -> None:
        self.check(n)
        if rlo and not self.cd_edge[n] and self.value[n] > 0:
            self.value[n] -= 1
        self.cd_edge[n] = rlo

    def set(self, n: int, rlo: int, accu1: int) -> None:
        """``S C n``: on a rising RLO the counter takes ACCU1-L as 3 BCD digits (C#...)."""
        self.check(n)
        if rlo and not self.s_edge[n]:
            self.value[n] = bcd_to_int(accu1 & 0xFFF, 3, f"S C {n}")
        self.s_edge[n] = rlo

    def reset(self, n: int, rlo: int) -> None:
        self.check(n)
        if rlo:
            self.value[n] = 0

    def enable(self, n: int, rlo: int) -> None:
        self.check(n)
        if rlo and not self.fr_edge[n]:
            self.cu_edge[n] = self.cd_edge[n] = self.s_edge[n] = 0
        self.fr_edge[n] = rlo
