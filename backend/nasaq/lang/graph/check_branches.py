"""Do simultaneous branches open and close consistently? (GRA220, GRA221; part of the
structure rules.)

S7-Graph's editor only lets a simultaneous convergence join the branches a simultaneous
divergence opened; a text file can join anything. Two mistakes make a sequence hang or run
twice, and both are found from where each step's *path* starts:

- GRA220 (warning): a simultaneous convergence ``FROM (A, B)`` whose steps are never active
  together: they lie one after the other on one path (B's path may branch off A itself), or
  on two alternative branches of the same step. The transition can never fire (unless ON
  actions switch the steps on).
- GRA221 (warning): branches of one simultaneous divergence end in the same step through
  separate transitions (an alternative convergence): each branch activates the step on its
  own and the other branch stays active. They need one transition ``FROM (A, B)``.

The origin of a step is found by walking back while the step has exactly one incoming
transition leading from one step that no other transition leaves: the walk stops at the first
step of a simultaneous branch (origin: that divergence and branch), of an alternative branch
(origin: the step it branches from and the transition), or at a step entered by several
transitions, none, or a convergence (origin: that step). Steps on one such path share their
origin. Walks are memoised and iterative, so the whole analysis is linear. The rules report
only what is certain from the chart; ON actions and jumps between sequencers are not
followed, so a sequence that relies on them is not reported.
"""

from __future__ import annotations

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check_context import BlockContext, names_list, step_key, transition_key
from nasaq.lang.graph.model import Step, Transition

# ("sim", id(transition), branch) | ("alt", id(step), id(transition)) | ("step", id(step))
Origin = tuple[str, int, int]


def check_branches(ctx: BlockContext) -> list[Diagnostic]:
    origins = _Origins(ctx)
    return [*_joins_never_together(ctx, origins), *_branches_merged_apart(ctx, origins)]


class _Origins:
    def __init__(self, ctx: BlockContext) -> None:
        self.incoming: dict[int, list[tuple[Transition, int]]] = {}  # step → (transition, index)
        self.leaving: dict[int, int] = {}  # step → number of transitions leaving it
        self.single_source: dict[int, Step | None] = {}  # transition → its one source step
        for (_, transition), (sources, targets) in zip(ctx.transitions, ctx.links, strict=True):
            for index, target in enumerate(targets):
                if target is not None:
                    self.incoming.setdefault(id(target), []).append((transition, index))
            for source in sources:
                if source is not None:
                    self.leaving[id(source)] = self.leaving.get(id(source), 0) + 1
            self.single_source[id(transition)] = sources[0] if len(sources) == 1 else None
        self.known: dict[int, Origin] = {}

    def _own(self, step: Step) -> tuple[Origin | None, Step | None]:
        """The origin a step has by its own incoming transition, or the step to walk to."""
        incoming = self.incoming.get(id(step), [])
        if len(incoming) != 1:
            return ("step", id(step), 0), None
        transition, index = incoming[0]
        if len(transition.target) > 1:
            return ("sim", id(transition), index), None
        source = self.single_source[id(transition)]
        if source is None:
            return ("step", id(step), 0), None
        if self.leaving.get(id(source), 0) > 1:
            return ("alt", id(source), id(transition)), None
        return None, source

    def of(self, step: Step) -> Origin:
        path: list[Step] = []
        on_path: set[int] = set()
        current: Step | None = step
        origin: Origin | None = None
        while current is not None:
            if id(current) in self.known:
                origin = self.known[id(current)]
                break
            if id(current) in on_path:  # a ring of single links: no start
                origin = ("step", id(current), 0)
                break
            path.append(current)
            on_path.add(id(current))
            origin, current = self._own(current)
        assert origin is not None
        for member in path:
            self.known[id(member)] = origin
        return origin


def _joins_never_together(ctx: BlockContext, origins: _Origins) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for (_, transition), (sources, _) in zip(ctx.transitions, ctx.links, strict=True):
        steps = [step for step in sources if step is not None]
        if len(steps) < 2:
            continue
        seen: dict[Origin, Step] = {}
        alternatives: dict[int, tuple[int, Step]] = {}  # branching step → (transition, step)
        joined = {id(step): step for step in steps}
        pair: tuple[Step, Step] | None = None
        for step in steps:
            origin = origins.of(step)
            if origin[0] == "alt" and origin[1] in joined and joined[origin[1]] is not step:
                pair = (joined[origin[1]], step)  # it branches off another joined step
                break
            earlier = seen.get(origin)
            if earlier is not None and earlier is not step:
                pair = (earlier, step)
                break
            seen[origin] = step
            if origin[0] == "alt":
                other = alternatives.setdefault(origin[1], (origin[2], step))
                if other[0] != origin[2]:
                    pair = (other[1], step)
                    break
        if pair is not None:
            found.append(
                ctx.problem(
                    "GRA220",
                    transition_key(transition),
                    transition=transition.name,
                    first=pair[0].name,
                    second=pair[1].name,
                )
            )
    return found


def _branches_merged_apart(ctx: BlockContext, origins: _Origins) -> list[Diagnostic]:
    """A step entered by several transitions from different branches of one divergence."""
    found: list[Diagnostic] = []
    for _, step in ctx.steps:
        incoming = origins.incoming.get(id(step), [])
        if len(incoming) < 2:
            continue
        by_divergence: dict[int, dict[int, Transition]] = {}
        for transition, _ in incoming:
            source = origins.single_source[id(transition)]
            if source is None or len(transition.target) != 1:
                continue
            kind, divergence, branch = origins.of(source)
            if kind == "sim":
                by_divergence.setdefault(divergence, {}).setdefault(branch, transition)
        for branches in by_divergence.values():
            if len(branches) > 1:
                merging = sorted(branches.values(), key=lambda item: item.number)
                found.append(
                    ctx.problem(
                        "GRA221",
                        step_key(step),
                        step=step.name,
                        transitions=names_list([item.name for item in merging]),
                    )
                )
    return found
