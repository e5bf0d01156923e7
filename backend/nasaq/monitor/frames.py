"""Frames: what one client has not seen yet, and how unsent frames combine.

A client's frame carries only the changes since its previous frame (``FrameState``, one per
client, kept where the session runs). When a socket cannot take frames as fast as they come, the
server does not send them one by one: ``merge`` folds the waiting frames into one, so the client
gets one frame with the newest state, the diagnostic entries and the newest trend samples.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from nasaq.monitor import protocol as p
from nasaq.monitor.status import narrowed

if TYPE_CHECKING:
    from nasaq.monitor.session import ClientView, Session, Snapshot

MAX_MERGED_SAMPLES = 5_000  # trend samples a waiting frame keeps (the newest)


class FrameState:
    """What this client was last sent, to send only changes."""

    def __init__(self) -> None:
        self.seq = 0
        self.cpu: p.CpuState | None = None
        self.values: dict[str, p.WatchValue] = {}
        self.block_scan: int | None = None
        self.block_name: str | None = None
        self.block_sent: p.BlockStatus | None = None
        self.hold: p.HoldState | None = None
        self.diagnostics = -1
        self.plant: p.PlantFrame | None = None

    def frame(self, snap: Snapshot, view: ClientView, session: Session) -> p.Frame | None:
        """The changes ``snap`` brings this client; None when there are none."""
        frame = p.Frame(seq=snap.seq)
        changed = False
        if view.cpu and snap.cpu != self.cpu:
            frame.cpu = self.cpu = snap.cpu
            changed = True
        if view.watch:
            delta = {}
            for text in view.watch:
                value = snap.values.get(text)
                if value is not None and self.values.get(text) != value:
                    delta[text] = value
                    self.values[text] = value
            if delta:
                frame.watch = delta
                changed = True
        if view.open_block is not None:
            status = snap.blocks.get(view.open_block)
            # A new status of the same scan (the values at a hold, after a modify) is sent too.
            if status is not None and (
                status is not self.block_sent
                or (status.scan, status.block) != (self.block_scan, self.block_name)
            ):
                self.block_sent = status
                if view.open_networks is not None:  # another client may record more of it
                    status = narrowed(status, view.open_networks, session.info(view.open_block))
                frame.block = status
                self.block_scan, self.block_name = status.scan, status.block
                changed = True
        if snap.hold is not self.hold:
            if snap.hold is None:
                frame.released = True
            frame.hold = snap.hold
            self.hold = snap.hold
            changed = True
        samples = [view.samples.popleft() for _ in range(len(view.samples))]
        if samples:
            frame.trend = samples
            changed = True
        if snap.diagnostics != self.diagnostics:
            buffer = session.engine.diagnostic_buffer
            new = snap.diagnostics - max(self.diagnostics, 0)
            if self.diagnostics >= 0 and new > 0:
                frame.diagnostics = [
                    p.DiagnosticEntry.of(e) for e in buffer[-min(new, len(buffer)) :]
                ]
                changed = True
            self.diagnostics = snap.diagnostics
        if snap.plant is not self.plant:
            if snap.plant is None:
                frame.plant_removed = True
            frame.plant = self.plant = snap.plant
            changed = True
        self.seq = snap.seq
        return frame if changed else None


def merge(texts: list[str]) -> str:
    """One frame (JSON text) with the effect of ``texts`` applied in order; each is parsed once,
    so folding many waiting frames costs what reading them once does."""
    if len(texts) == 1:
        return texts[0]
    merged: dict[str, Any] = json.loads(texts[0])
    for text in texts[1:]:
        b: dict[str, Any] = json.loads(text)
        merged["seq"] = b["seq"]
        for key in ("cpu", "block"):
            if b.get(key) is not None:
                merged[key] = b[key]
        if b.get("plant_removed"):
            merged["plant_removed"], merged["plant"] = True, None
        elif b.get("plant") is not None:
            merged["plant_removed"], merged["plant"] = False, b["plant"]
        if b.get("watch"):
            merged["watch"] = {**(merged.get("watch") or {}), **b["watch"]}
        for key in ("trend", "diagnostics"):
            if b.get(key):
                merged[key] = ((merged.get(key) or []) + b[key])[-MAX_MERGED_SAMPLES:]
        if b.get("released"):
            merged["released"] = True
            merged["hold"] = b.get("hold")
        elif b.get("hold") is not None:
            merged["hold"] = b["hold"]
    return json.dumps(merged, separators=(",", ":"))
