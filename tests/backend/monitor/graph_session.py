"""A monitoring session driven scan by scan from a test, for the S7-Graph monitor tests: the
session runs in its own thread, paused, and each ``scans`` runs exactly that many scans."""

from __future__ import annotations

import time
from typing import Any

from nasaq.lang.stl import SourceFile
from nasaq.monitor import targets
from nasaq.monitor.protocol import CLIENT_MESSAGE, BlockStatus, GraphControl
from nasaq.monitor.session import ClientView, Session


class Cpu:
    """A session in its own thread, in RUN, driven scan by scan."""

    def __init__(self, sources: list[SourceFile]) -> None:
        self.session = Session("graph-sequencer", sources)
        self.session.clients[1] = ClientView()
        self.session.start()
        self.run(self.session.do_run)
        self.run(lambda: self.session.do_set_time("pause", None))

    def run(self, action: Any) -> Any:
        return self.session.submit(action).result(timeout=5)

    def scans(self, count: int = 1) -> None:
        session = self.session
        before = self.run(lambda: session.cpu.scans)
        self.run(lambda: session.do_run_scans(count))
        deadline = time.monotonic() + 5
        while session.cpu.scans < before + count:
            assert time.monotonic() < deadline, "the scans did not run"
            time.sleep(0.002)
        self.run(lambda: None)  # the scans' publishing is done

    def read(self, text: str) -> Any:
        session = self.session
        return self.run(lambda: targets.read(targets.resolve(text, session.program), session.cpu))

    def write(self, values: dict[str, Any]) -> None:
        session = self.session

        def write() -> None:
            for text, value in values.items():
                if text.startswith("I"):
                    session.do_set_input(text, value)
                else:
                    session.do_modify(text, value)

        self.run(write)

    def control(self, db: str, op: str, step: int | None = None) -> dict[str, Any]:
        message = CLIENT_MESSAGE.validate_python(
            {"type": "graph_control", "db": db, "op": op, "step": step}
        )
        assert isinstance(message, GraphControl)
        result: dict[str, Any] = self.run(
            lambda: self.session.do_graph_control(message.db, message.op, message.step)
        )
        return result

    def status(self, block: str = "FB1") -> BlockStatus:
        session = self.session
        key = self.run(lambda: session.do_open_block(1, block) and session.view(1).open_block)
        scans = self.run(lambda: session.cpu.scans)
        deadline = time.monotonic() + 5
        while True:
            self.scans(1)
            snapshot = session.snapshot
            status = snapshot.blocks.get(key) if snapshot else None
            if status is not None and status.scan > scans:
                return status
            assert time.monotonic() < deadline, "no sampled scan"
            time.sleep(0.04)  # block status is sampled at most every 1/30 s
