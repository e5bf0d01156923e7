"""P26: thumbwheel switches on an input word and a BCD display on an output word.

The operator sets the thumbwheels (``thumbwheel``, one BCD digit per nibble, e.g. 16#0456 for
456); the program reads them as BCD. The display shows the output word as four BCD digits; a
nibble A..F is no decimal digit, so the display shows it as an error ("E"), as a real BCD
decoder shows a blank or a dash: ``display_error`` tells a check. The thumbwheel word may carry
any pattern a lesson needs (a sign nibble 16#F... for negative BCD).
"""

from __future__ import annotations

from typing import ClassVar

from nasaq.plants.base import Plant, Signal, StateValue


def bcd_text(word: int) -> str:
    """Four digits as a BCD display shows ``word``: ``0123``; a nibble above 9 is ``E``."""
    return "".join(
        str(n) if n <= 9 else "E"
        for n in ((word >> 12) & 15, (word >> 8) & 15, (word >> 4) & 15, word & 15)
    )


class BcdPanel(Plant):
    kind = "bcd_panel"
    title = "Thumbwheel switches and BCD display"
    signals = (
        Signal("thumbwheel", "control", "word", description="thumbwheel switches, BCD digits"),
        Signal("display", "actuator", "word", description="four-digit BCD display"),
    )
    defaults: ClassVar[dict[str, float]] = {}
    default_wiring: ClassVar[dict[str, str]] = {"thumbwheel": "IW2", "display": "QW4"}

    def step(self, dt_ms: int) -> None:
        """Nothing moves: the display follows the output word, the wheels the operator."""

    def sensors(self) -> dict[str, int]:
        return {}

    def state(self) -> dict[str, StateValue]:
        shown = self.actuators["display"] & 0xFFFF
        text = bcd_text(shown)
        return {
            "display_text": text,
            "display_error": "E" in text,
            "thumbwheel_text": bcd_text(self.controls["thumbwheel"]),
        }
