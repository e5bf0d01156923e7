"""The S7-300/400 CPU simulator: compiles STL IR blocks to Python and runs them in virtual time.

Public API: :class:`Cpu` and :class:`Profile` (see ``api.py``); COMPATIBILITY.md lists the known
differences from a real CPU.
"""

from nasaq.cpu.api import Cpu
from nasaq.cpu.cycle import DiagnosticEntry, Retentive
from nasaq.cpu.profile import Profile

__all__ = ["Cpu", "DiagnosticEntry", "Profile", "Retentive"]
