"""The shape of the sequencers: numbers, links between steps and transitions, reachability,
limits and loops (GRA200–GRA219).

Decisions, where S7-Graph's editor makes a mistake impossible that a text file allows:

- Step numbers and transition numbers are unique in the FB (S_SEL/S_NO and ``ON S<n>`` name
  steps by number across all sequencers). Sequencer names are unique too (they key the
  places of their parts).
- Every step must be left by a transition (GRA204, error): S7-Graph closes every path (a step
  is always followed by a transition, and a path ends in a jump or a branch stop after a
  transition, never after a step). A transition with no target is a sequence end (STOP).
- A transition is written in the sequencer of its source steps: the chart (and the printer)
  draws it under them. A simultaneous divergence opens its branches in its own sequencer; a
  single-target transition may jump into another sequencer (S7-Graph allows jumps between
  sequencers).
- No initial step in the whole FB: one warning (§2.14 item 4: allowed, the FB then does
  nothing until a step is switched on). A sequencer without an initial step that no other
  sequencer jumps into and no ON action reaches: a warning of its own. Several initial
  steps are allowed (§2.14 item 3).
- Unreachable step (warning): not reached from an initial step or an ON target through the
  transitions. A convergence is followed when any of its source steps is reached (the check
  shows a step no path can reach, not every structural mistake). Not reported for a
  sequencer already warned about (GRA207), nor when the FB has no initial step (GRA206).
- Limits: at most 256 steps and 256 transitions per FB (S7-Graph's 256 step+transition
  pairs), 125 alternative and 256 simultaneous branches per FB (the digest's §2.2; a
  divergence into n branches counts n).
- A loop of steps linked only by transitions without a condition (``None`` or an empty
  CONDITION) is an error: the sequencer would run round it for ever (with Skip Step even
  within one call). A step switching to itself by such a transition is a loop too.

Every rule is one pass over the block (dicts, an iterative Tarjan for the loops): linear.
"""

from __future__ import annotations

from collections import deque

from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check_context import (
    BlockContext,
    names_list,
    step_key,
    transition_key,
)
from nasaq.lang.graph.model import Step, Transition

MAX_STEPS = 256
MAX_TRANSITIONS = 256
MAX_ALTERNATIVE_BRANCHES = 125
MAX_SIMULTANEOUS_BRANCHES = 256


def check_structure(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    found += _sequencers(ctx)
    found += _numbers(ctx)
    found += _limits(ctx)
    found += _links(ctx)
    found += _exits(ctx)
    found += _initial_and_reachable(ctx)
    found += _loops_without_condition(ctx)
    return found


def _sequencers(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    if not ctx.block.sequencers:
        return [ctx.problem("GRA219", "BLOCK", block=ctx.block.name)]
    seen: set[str] = set()
    for sequencer in ctx.block.sequencers:
        key = f"SEQ:{sequencer.name}"
        if sequencer.name.upper() in seen:
            found.append(ctx.problem("GRA217", key, sequencer=sequencer.name))
        seen.add(sequencer.name.upper())
        if not sequencer.steps:
            found.append(ctx.problem("GRA218", key, sequencer=sequencer.name))
    return found


def _numbers(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    first_step: dict[int, Step] = {}
    for _, step in ctx.steps:
        earlier = first_step.setdefault(step.number, step)
        if earlier is not step:
            found.append(
                ctx.problem(
                    "GRA200",
                    step_key(step),
                    number=step.number,
                    first=earlier.name,
                    second=step.name,
                )
            )
    first_transition: dict[int, Transition] = {}
    for _, transition in ctx.transitions:
        earlier_t = first_transition.setdefault(transition.number, transition)
        if earlier_t is not transition:
            found.append(
                ctx.problem(
                    "GRA201",
                    transition_key(transition),
                    number=transition.number,
                    first=earlier_t.name,
                    second=transition.name,
                )
            )
    return found


def _limits(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    if len(ctx.steps) > MAX_STEPS:
        over = ctx.steps[MAX_STEPS][1]
        found.append(ctx.problem("GRA208", step_key(over), count=len(ctx.steps), limit=MAX_STEPS))
    if len(ctx.transitions) > MAX_TRANSITIONS:
        over_t = ctx.transitions[MAX_TRANSITIONS][1]
        found.append(
            ctx.problem(
                "GRA209",
                transition_key(over_t),
                count=len(ctx.transitions),
                limit=MAX_TRANSITIONS,
            )
        )
    leaving: dict[str, int] = {}
    simultaneous = 0
    for _, transition in ctx.transitions:
        if len(transition.source) == 1:
            name = transition.source[0].upper()
            leaving[name] = leaving.get(name, 0) + 1
        if len(transition.target) > 1:
            simultaneous += len(transition.target)
    alternative = sum(count for count in leaving.values() if count > 1)
    if alternative > MAX_ALTERNATIVE_BRANCHES:
        found.append(
            ctx.problem("GRA210", "BLOCK", count=alternative, limit=MAX_ALTERNATIVE_BRANCHES)
        )
    if simultaneous > MAX_SIMULTANEOUS_BRANCHES:
        found.append(
            ctx.problem("GRA211", "BLOCK", count=simultaneous, limit=MAX_SIMULTANEOUS_BRANCHES)
        )
    return found


def _links(ctx: BlockContext) -> list[Diagnostic]:
    """Each transition's FROM and TO name existing steps, each once, in the right sequencer."""
    found: list[Diagnostic] = []
    known: list[str] | None = None
    for (position, transition), (sources, targets) in zip(ctx.transitions, ctx.links, strict=True):
        key = transition_key(transition)
        for names, steps, code in (
            (transition.source, sources, "GRA202"),
            (transition.target, targets, "GRA203"),
        ):
            seen: set[str] = set()
            for name, resolved in zip(names, steps, strict=True):
                if name.upper() in seen:
                    found.append(ctx.problem("GRA213", key, transition=transition.name, step=name))
                seen.add(name.upper())
                if resolved is None:
                    if known is None:
                        known = [step.name for _, step in ctx.steps]
                    found.append(
                        ctx.problem(
                            code,
                            key,
                            transition=transition.name,
                            step=name,
                            known=names_list(known),
                        )
                    )
        if transition.jump and len(transition.target) != 1:
            found.append(ctx.problem("GRA214", key, transition=transition.name))
        for step in sources:
            if step is not None and ctx.sequencer_of_step[id(step)] != position:
                other = ctx.sequencer_name(ctx.sequencer_of_step[id(step)])
                found.append(
                    ctx.problem(
                        "GRA215",
                        key,
                        transition=transition.name,
                        sequencer=ctx.sequencer_name(position),
                        step=step.name,
                        other=other,
                    )
                )
        if len(transition.target) > 1:
            outside = [
                step.name
                for step in targets
                if step is not None and ctx.sequencer_of_step[id(step)] != position
            ]
            if outside:
                found.append(
                    ctx.problem(
                        "GRA216",
                        key,
                        transition=transition.name,
                        sequencer=ctx.sequencer_name(position),
                        steps=names_list(outside),
                    )
                )
    return found


def _exits(ctx: BlockContext) -> list[Diagnostic]:
    """Every step is a source of some transition (S7-Graph closes every path)."""
    left = {name.upper() for _, transition in ctx.transitions for name in transition.source}
    return [
        ctx.problem("GRA204", step_key(step), step=step.name)
        for _, step in ctx.steps
        if step.name.upper() not in left
    ]


def _on_targets(ctx: BlockContext) -> dict[int, Step]:
    """The steps ON actions switch on (by id), whoever writes them."""
    targets: dict[int, Step] = {}
    for _, step in ctx.steps:
        for action in step.actions:
            if action.qualifier == "ON":
                target = ctx.step_reference(action.operand)
                if target is not None:
                    targets[id(target)] = target
    return targets


def _initial_and_reachable(ctx: BlockContext) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    if not ctx.steps:
        return found
    initial = [step for _, step in ctx.steps if step.initial]
    if not initial:
        return [ctx.problem("GRA206", "BLOCK", block=ctx.block.name)]
    switched_on = _on_targets(ctx)
    entered: set[int] = {ctx.sequencer_of_step[key] for key in switched_on}
    for (position, _), (_, targets) in zip(ctx.transitions, ctx.links, strict=True):
        for step in targets:
            if step is not None and ctx.sequencer_of_step[id(step)] != position:
                entered.add(ctx.sequencer_of_step[id(step)])
    silent: set[int] = set()
    for position, sequencer in enumerate(ctx.block.sequencers):
        has_initial = any(step.initial for step in sequencer.steps)
        if sequencer.steps and not has_initial and position not in entered:
            silent.add(position)
            found.append(ctx.problem("GRA207", f"SEQ:{sequencer.name}", sequencer=sequencer.name))
    found += _unreachable(ctx, [*initial, *switched_on.values()], silent)
    return found


def _unreachable(ctx: BlockContext, roots: list[Step], silent: set[int]) -> list[Diagnostic]:
    leaving: dict[int, list[list[Step | None]]] = {}
    for sources, targets in ctx.links:
        for step in sources:
            if step is not None:
                leaving.setdefault(id(step), []).append(targets)
    reached: set[int] = {id(step) for step in roots}
    queue = deque(roots)
    while queue:
        step = queue.popleft()
        for targets in leaving.pop(id(step), []):
            for target in targets:
                if target is not None and id(target) not in reached:
                    reached.add(id(target))
                    queue.append(target)
    return [
        ctx.problem("GRA205", step_key(step), step=step.name)
        for position, step in ctx.steps
        if id(step) not in reached and position not in silent
    ]


def _loops_without_condition(ctx: BlockContext) -> list[Diagnostic]:
    """Strongly connected parts of the graph of steps linked by transitions without a
    condition (Tarjan, iterative: a long chain does not exhaust the stack)."""
    order = {id(step): k for k, (_, step) in enumerate(ctx.steps)}
    edges: list[list[int]] = [[] for _ in ctx.steps]
    by_edge: dict[tuple[int, int], Transition] = {}
    for (_, transition), (sources, targets) in zip(ctx.transitions, ctx.links, strict=True):
        if transition.condition is not None and transition.condition.elements:
            continue
        for source in sources:
            for target in targets:
                if source is None or target is None:
                    continue
                edge = (order[id(source)], order[id(target)])
                edges[edge[0]].append(edge[1])
                by_edge.setdefault(edge, transition)
    components = _components(edges)
    component_of: dict[int, int] = {}
    for number, component in enumerate(components):
        component_of.update(dict.fromkeys(component, number))
    inside: list[list[Transition]] = [[] for _ in components]
    for (a, b), transition in by_edge.items():
        if a in component_of and component_of[a] == component_of.get(b):
            inside[component_of[a]].append(transition)
    found: list[Diagnostic] = []
    for component, transitions in zip(components, inside, strict=True):
        if not transitions:
            continue  # a single step without a loop onto itself
        unique = {id(transition): transition for transition in transitions}
        transitions = sorted(unique.values(), key=lambda item: item.number)
        steps = [ctx.steps[k][1].name for k in sorted(component)]
        found.append(
            ctx.problem(
                "GRA212",
                transition_key(transitions[0]),
                steps=names_list(steps),
                transitions=names_list([transition.name for transition in transitions]),
            )
        )
    return found


def _components(edges: list[list[int]]) -> list[list[int]]:
    """Tarjan's strongly connected components of the graph ``edges`` (node → successors);
    only those that may hold a loop (nodes with an edge) are visited."""
    index: list[int] = [-1] * len(edges)
    low: list[int] = [0] * len(edges)
    on_stack: list[bool] = [False] * len(edges)
    stack: list[int] = []
    components: list[list[int]] = []
    counter = 0
    for root in range(len(edges)):
        if index[root] != -1 or not edges[root]:
            continue
        work: list[tuple[int, int]] = [(root, 0)]
        while work:
            node, child = work.pop()
            if child == 0:
                index[node] = low[node] = counter
                counter += 1
                stack.append(node)
                on_stack[node] = True
            if child < len(edges[node]):
                work.append((node, child + 1))
                successor = edges[node][child]
                if index[successor] == -1:
                    work.append((successor, 0))
                elif on_stack[successor]:
                    low[node] = min(low[node], index[successor])
                continue
            if low[node] == index[node]:
                component: list[int] = []
                while True:
                    member = stack.pop()
                    on_stack[member] = False
                    component.append(member)
                    if member == node:
                        break
                components.append(component)
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
    return components
