"""Errors of the monitoring protocol and the session API, each a code of the diagnostics catalogue
(``diagnostics/monitor.csv``) so the IDE shows them in the user's language."""

from __future__ import annotations

from typing import Any

from nasaq.diagnostics.catalogue import render


class MonitorError(Exception):
    """A request the session cannot carry out; ``str()`` is the English message."""

    def __init__(self, code: str, **params: Any) -> None:
        self.code = code
        self.params = params
        self.diagnostic = render(code, **params)
        super().__init__(self.diagnostic.message)

    @property
    def key(self) -> str:
        return self.diagnostic.key
