"""Every network of the course's STL examples and of the example projects either lifts to LAD
or gives a catalogued reason; none raises. The counts are pinned so a change shows."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from nasaq.lang.lad.from_stl import REASONS, NotConvertible, lift_block
from nasaq.lang.lad.model import LadBlock, Network
from nasaq.lang.lad.to_stl import block_to_stl

ROOT = Path(__file__).resolve().parents[4]
SOURCES = sorted(
    [
        *(ROOT / "tests" / "scenarios" / "course").rglob("*.awl"),
        *(ROOT / "examples" / "projects").glob("*/*.awl"),
    ]
)


def test_every_course_network_lifts_or_says_why() -> None:
    assert len(SOURCES) > 100
    lifted = 0
    reasons: Counter[str] = Counter()
    for path in SOURCES:
        result = lift_block(path.read_text("utf-8"), path.name)
        for block in result.blocks:
            for network in block.networks:
                if isinstance(network, Network):
                    lifted += 1
                    continue
                assert isinstance(network, NotConvertible)
                assert network.code in REASONS
                assert network.line >= 1
                reasons[network.code] += 1
    total = lifted + sum(reasons.values())
    # a large share of the course is LAD-shaped bit logic, timers and counters
    assert lifted >= 200, (lifted, reasons)
    assert total >= 340, (lifted, reasons)
    assert reasons["LAD305"] >= 1  # the exclusive ORs of the course stay STL


def test_every_lifted_course_network_survives_lowering_and_lifting_again() -> None:
    """LAD → STL → LAD on the course's own networks: ``to_stl`` writes them in its shapes and
    the lifter reads the same network back (the source is put first so that calls find the
    interfaces of the blocks they call)."""
    checked = 0
    for path in SOURCES:
        text = path.read_text("utf-8")
        for block in lift_block(text, path.name).blocks:
            for network in block.networks:
                if not isinstance(network, Network):
                    continue
                lowered, problems = block_to_stl(
                    LadBlock(kind="OB", name="OB 1", networks=[network])
                )
                assert not problems, (path.name, network.title)
                again = lift_block(text + "\n" + lowered, path.name).blocks[-1].networks[0]
                assert again == network, (path.name, network.title, lowered)
                checked += 1
    assert checked >= 200
