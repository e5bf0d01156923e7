"""The CPU family a program is compiled for: what the compilers accept depends on it.

``"S7-300"`` and ``"S7-400"`` are STEP 7 Classic's CPUs (and TIA Portal's for them); ``"S7-1500"``
stands for the S7-1200/1500 family, whose types (LREAL, LINT, WSTRING, DTL ...), VARIANT, DB_ANY
and optimized blocks the classic profiles refuse with a code that names the profile they need,
never with a syntax error. The CPU's figures per profile live in ``nasaq.cpu.profile``.
"""

from __future__ import annotations

from typing import Literal

ProfileName = Literal["S7-300", "S7-400", "S7-1500"]
PROFILES: tuple[ProfileName, ...] = ("S7-300", "S7-400", "S7-1500")
DEFAULT_PROFILE: ProfileName = "S7-300"


# The elementary types only the S7-1200/1500 family has (``nasaq.ir.types`` gives their sizes).
# Declared under a classic profile they are SCL500/STL500 at the declaration.
S7_1500_TYPES = frozenset(
    {
        "SINT",
        "USINT",
        "UINT",
        "UDINT",
        "LINT",
        "ULINT",
        "LREAL",
        "LWORD",
        "LTIME",
        "WCHAR",
        "WSTRING",
    }
)


def is_s7_1500(profile: str) -> bool:
    """True for the S7-1200/1500 family."""
    return profile == "S7-1500"


def needs_s7_1500(type_name: str, profile: str) -> bool:
    """Whether the elementary type ``type_name`` is refused under ``profile``."""
    return type_name.upper() in S7_1500_TYPES and not is_s7_1500(profile)
