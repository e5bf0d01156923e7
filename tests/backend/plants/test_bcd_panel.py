"""P26 thumbwheels and BCD display: what the display shows for valid and invalid BCD, and the
course's binary -> BCD program showing a count."""

from __future__ import annotations

import pytest
from plant_driver import hold

from nasaq.plants.base import PlantError
from nasaq.plants.bcd_panel import BcdPanel, bcd_text


def test_the_display_shows_bcd_digits_and_flags_a_digit_above_nine() -> None:
    assert bcd_text(0x0123) == "0123"
    panel = BcdPanel()
    hold(panel, 10, display=0x0456)
    assert panel.state()["display_text"] == "0456"
    assert panel.state()["display_error"] is False
    hold(panel, 10, display=0x12A4)  # a binary 4772 written without conversion
    assert panel.state()["display_text"] == "12E4"
    assert panel.state()["display_error"] is True


def test_the_thumbwheels_drive_the_input_word() -> None:
    panel = BcdPanel()
    panel.operate("thumbwheel", 0x0456)
    assert panel.inputs() == {"thumbwheel": 0x0456}
    assert panel.state()["thumbwheel_text"] == "0456"
    panel.operate("thumbwheel", -1)  # an INT's pattern
    assert panel.inputs() == {"thumbwheel": 0xFFFF}
    with pytest.raises(PlantError) as raised:
        panel.operate("thumbwheel", 70000)
    assert raised.value.code == "PLT016"
