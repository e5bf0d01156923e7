"""The system blocks several modules bring (``nasaq.lang.system_blocks`` merges their tables):
a number taken twice would silently replace a block, so every number has one owner, and every
block has an interface and a body the CPU runs."""

from __future__ import annotations

import re
from pathlib import Path

from nasaq.cpu import iec_blocks
from nasaq.lang import system_blocks, tia_comm, tia_control, tia_filters, tia_iec

_CLASSIC_SFBS = {0, 1, 2, 3, 4, 5, system_blocks.R_TRIG_SFB, system_blocks.F_TRIG_SFB}


def test_no_two_modules_claim_the_same_system_block_number() -> None:
    owners: dict[int, str] = dict.fromkeys(_CLASSIC_SFBS, "system_blocks")
    for module in (tia_control, tia_comm, tia_iec, tia_filters):
        for number in module.NAMES:
            assert number not in owners, (number, module.__name__, owners.get(number))
            owners[number] = module.__name__
    assert set(system_blocks.SFB_NAMES) == set(owners)


def test_no_two_modules_claim_the_same_system_function_number() -> None:
    source = Path(system_blocks.__file__).read_text(encoding="utf-8")
    base = re.search(r"^SFC_NAMES: dict\[int, str\] = \{(.*?)\}", source, re.M)
    assert base is not None
    owners = {int(number): "system_blocks" for number in re.findall(r"(\d+):", base.group(1))}
    for module in (tia_control, tia_comm):
        for number in module.SFC_NAMES:
            assert number not in owners, (number, module.__name__, owners.get(number))
            owners[number] = module.__name__
    assert set(system_blocks.SFC_NAMES) == set(owners)


def test_every_system_block_has_an_interface_and_a_name() -> None:
    assert set(system_blocks.SFB_INTERFACES) == set(system_blocks.SFB_NAMES)
    assert set(system_blocks.SFC_INTERFACES) >= set(system_blocks.SFC_NAMES) - {43, 46}
    # the instance layouts the CPU builds cover every block with a Python body
    assert set(iec_blocks.BODIES) <= set(system_blocks.SFB_NAMES)
