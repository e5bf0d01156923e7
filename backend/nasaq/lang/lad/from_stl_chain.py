"""The running state of one RLO chain while the lifter reads it (``Chain``).

It mirrors the status word: ``current`` is the AND series since the last first check, ``groups``
the AND groups a bare ``O`` parked (the OR bit), ``done`` what came before a restart (a midline
``= x; A x`` or a box whose output is reloaded: ``A BR``, ``A T 1``, ``A m``). ``elements``
turns it into the model's series, dropping the reload and checking that the restarted chain
really continues the flow in series.
"""

from __future__ import annotations

import re

from nasaq.lang.lad.from_stl_reasons import RefusalError, not_convertible
from nasaq.lang.lad.from_stl_steps import Step
from nasaq.lang.lad.model import (
    Contact,
    Element,
    Midline,
    Parallel,
    Series,
)

TEMP = re.compile(r"#_lad\d*_t\d+")


def is_temp(operand: str | None) -> bool:
    return operand is not None and TEMP.fullmatch(operand) is not None


class Chain:
    """The running state of one chain: ``done`` (elements before the last restart, i.e. a
    midline or a box whose output is reloaded), the AND groups parked by a bare ``O``, the
    current series, and the reload element the restarted chain begins with."""

    def __init__(self) -> None:
        self.done: list[Element] = []
        self.groups: list[list[Element]] = []
        self.current: list[Element] = []
        self.reload: Element | None = None
        self.open: list[Parallel] = []  # parallels built by O here (O x extends them)
        self.unloaded: Step | None = None  # ``= #t`` whose flow each branch reloads
        self.rail = False  # ``SET`` started the chain: the flow is the rail itself
        self.reload_step: Step | None = None
        self.bare_o: Step | None = None  # the last ``O`` without operand

    def empty(self) -> bool:
        return not self.groups and not self.current

    def parallel(self, branches: list[list[Element]]) -> Element:
        flat: list[Series] = []
        for branch in branches:
            inner = branch[0] if len(branch) == 1 else None
            if isinstance(inner, Parallel) and any(inner is made for made in self.open):
                flat.extend(inner.branches)
            else:
                flat.append(Series(elements=branch))
        made = Parallel(branches=flat)
        self.open.append(made)
        return made

    def segment(self) -> list[Element]:
        if not self.groups:
            return list(self.current)
        if not self.current:  # ``O`` with nothing after it
            step = self.bare_o
            assert step is not None
            raise RefusalError(not_convertible("LAD310", step.line, step.text))
        return [self.parallel([*self.groups, self.current])]

    def restart(self, element: Element, reload: Element, at: Step, reloaded: bool = True) -> None:
        """A midline or a box with its output reloaded (``at``): what came so far is done."""
        self.done = [*self.elements(), element]
        self.groups, self.current, self.reload = [], [reload] if reloaded else [], reload
        self.reload_step = at

    def elements(self) -> list[Element]:
        segment = self.segment()
        reload = self.reload
        if reload is not None and segment and segment[0] == reload:
            segment = segment[1:]
        elif (
            reload is not None
            and _all_branches_start(segment, reload)
            and self.done
            and self.done[-1] == Midline(operand=getattr(reload, "operand", ""))
        ):
            # the flow past a parallel with side effects (``= #t`` then ``A #t`` per branch)
            assert isinstance(segment[0], Parallel)
            branches = [Series(elements=b.elements[1:]) for b in segment[0].branches]
            self.done = self.done[:-1]
            segment = [Parallel(branches=branches), *segment[1:]]
            self.unloaded = None
        elif reload is not None and segment and self.unloaded is None:
            # the reloaded value is ORed or grouped: a chain of its own, not a flow in series
            step = self.reload_step
            assert step is not None
            raise RefusalError(not_convertible("LAD306", step.line, step.text))
        if self.unloaded is not None:
            step = self.unloaded
            raise RefusalError(not_convertible("LAD306", step.line, step.text))
        return self.done + segment


def _all_branches_start(segment: list[Element], reload: Element) -> bool:
    if not segment or not isinstance(segment[0], Parallel) or not isinstance(reload, Contact):
        return False
    return is_temp(reload.operand) and all(
        branch.elements and branch.elements[0] == reload for branch in segment[0].branches
    )
