"""Runtime errors of the simulated CPU and how they are classified.

A real CPU sorts runtime errors into synchronous error classes: programming errors call OB121, I/O
access errors call OB122, and with the OB missing the CPU goes to STOP. Some conditions (watchdog,
nesting depth, STP) always stop. Every error carries a catalogue code (``SIM5xx``) and the
parameters of its message, so the UI can translate it.
"""

from __future__ import annotations

from enum import Enum
from typing import Any

from nasaq.diagnostics import render
from nasaq.ir import Block


class ErrorClass(Enum):
    PROGRAMMING = 121  # OB121 if loaded
    IO_ACCESS = 122  # OB122 if loaded
    FATAL = 0  # always STOP


# Fault identifiers written to OB121/OB122 start information (byte 1, "SW_FLT"), after STEP 7.
FAULT_IDS: dict[str, int] = {
    "SIM512": 0x21,  # BCD conversion error
    "SIM503": 0x22,  # area length error when reading
    "SIM504": 0x23,  # area length error when writing
    "SIM516": 0x26,  # timer number error
    "SIM517": 0x27,  # counter number error
    "SIM520": 0x28,  # alignment error when reading
    "SIM521": 0x29,  # alignment error when writing
    "SIM505": 0x3A,  # DB not loaded
    "SIM506": 0x3C,  # block (FC/FB/SFC) not loaded
    "SIM518": 0x42,  # I/O access error when reading
    "SIM519": 0x43,  # I/O access error when writing
}

_CLASSES: dict[str, ErrorClass] = dict.fromkeys(FAULT_IDS, ErrorClass.PROGRAMMING) | {
    "SIM510": ErrorClass.PROGRAMMING,
    "SIM511": ErrorClass.PROGRAMMING,
    "SIM514": ErrorClass.PROGRAMMING,
    "SIM515": ErrorClass.PROGRAMMING,
    "SIM518": ErrorClass.IO_ACCESS,
    "SIM519": ErrorClass.IO_ACCESS,
}


def error_class(code: str) -> ErrorClass:
    return _CLASSES.get(code, ErrorClass.FATAL)


class CpuError(Exception):
    """A runtime error raised inside a scan; ``where`` is filled in where the location is known."""

    def __init__(self, code: str, **params: object) -> None:
        self.code = code
        self.params = params
        self.where: tuple[str, int | None, int | None] | None = None  # block, network, line
        super().__init__(code)

    def located(self, where: tuple[str, int | None, int | None] | None) -> CpuError:
        self.where = where
        return self

    @property
    def message(self) -> str:
        return render(self.code, None, **self.params).message


class CpuStopError(CpuError):
    """Unwinds every block of the scan: the CPU goes to STOP (STP, watchdog, unhandled error)."""


def sentence_part(message: str) -> str:
    """``"Area length error reading MW 6."`` → ``"area length error reading MW 6"``."""
    text = message.rstrip(".")
    if len(text) > 1 and text[0].isupper() and text[1].islower():
        text = text[0].lower() + text[1:]
    return text


def location(compiled: Any, index: int) -> tuple[str, int | None, int | None]:
    """(block name, network, line) of instruction ``index`` of a compiled block."""
    block: Block = compiled.block
    name = f"{block.kind.value}{block.number}"
    network: int | None = None
    line: int | None = None
    if 0 <= index < len(block.code):
        origin = block.code[index].origin
        if origin is not None:
            network, line = origin.network, origin.line
    if network is None and block.networks:
        for k, net in enumerate(block.networks):
            if net.first <= index:
                network = k + 1
    return name, network, line
