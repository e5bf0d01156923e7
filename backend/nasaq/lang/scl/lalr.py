"""The fast parse of a source without syntax errors: Lark's LALR table run directly, each
reduction calling the AST builder's method with the children Lark would have passed it.

Lark reduces through layers of wrappers (``ChildFilterLALR_NoPlaceholders`` dropping filtered
tokens and splicing in ``_rule`` children, ``ExpandSingleChild`` for ``?rule``, ``Tree`` objects
for the inlined ``_rule`` and ``__x_star`` helpers). Here those layers are read once per parser
and turned into one step per rule: a ``_rule``'s value is the plain list of its children, a
``?rule`` of one kept child keeps the child's value without a call, and terminals that no rule
keeps are never made into tokens nor put on the value stack (``nasaq.lang.scl.lexer``), so a
rule's values are mostly the builder's children as they are. Kept terminals are ``FastToken``s.
The callbacks' semantics stay Lark's; a parser whose callbacks are not Lark's plain ones (a
test recording them) has no fast table.

Where the state after a token's shift reduces it, whatever follows, by a rule of one token that
the builder makes from the token's text and position (``name: IDENT``, ``literal: INTEGER``:
its ``token_rules``), the shift makes the node at once (``_Made``): about a third of the tokens.

``parse`` returns None at the first thing it cannot do as Lark would (a syntax error, a lexer
problem): the caller then parses the source with the recovering driver.

The table: per state, the action of each terminal and the goto of each rule name. A shift or
goto is the next state (an ``int``); a reduction is ``(size, width, reduce, goto, rule name)``:
it pops ``size`` states and ``width`` values (a terminal no rule keeps has no token, so no
value), ``reduce`` None where the rule's value is the list of them, ``goto`` the state it leads
to (passes included) per state below it; or a ``_Pass``; or a ``_Made``.
"""

from __future__ import annotations

import weakref
from bisect import bisect_left
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import partial
from operator import itemgetter
from sys import intern
from types import MethodType
from typing import Any

from lark import Lark, Tree
from lark.grammar import Terminal
from lark.lexer import ContextualLexer
from lark.parse_tree_builder import ChildFilterLALR_NoPlaceholders, ExpandSingleChild
from lark.parsers.lalr_analysis import Shift

from nasaq.lang.scl.ast import Loc
from nasaq.lang.scl.lexer import FastLexer, FastPathError, FastToken, line_breaks

Children = list[Any]
Reduce = Callable[[Children], Any]
Make = Callable[[str, str, Loc], Any]  # a node of a token's kind, text and position


class _Pass:
    """A reduction by a rule of one symbol whose value is that symbol's (``?expr: unary``,
    ``_stmt: _statement``): only the state on top of the stack changes. ``after`` remembers,
    per state below it, the state the whole chain of such reductions ends in (``a`` in
    ``x := a;`` is reduced as primary, power, unary and expr in one step)."""

    __slots__ = ("after", "name")

    def __init__(self, name: str) -> None:
        self.name = name
        self.after: dict[int, int] = {}


class _Made:
    """The shift of a token after which the parser reduces by one rule whatever comes next (a
    default reduction), a rule of one token whose node the transformer makes from the token's
    kind, text and position (its ``token_rules``): the node is made at once, without a token,
    and ``state`` is where the reduction (and the ``_Pass`` reductions that also
    come whatever follows) would lead. ``lexes``: the state after the shift, whose terminals
    Lark's contextual lexer reads the next token with."""

    __slots__ = ("lexes", "make", "state")

    def __init__(self, state: int, make: Make, lexes: int) -> None:
        self.state = state
        self.make = make
        self.lexes = lexes


Table = list[dict[str, Any]]  # see the module's docstring


@dataclass(frozen=True, slots=True)
class _Fast:
    table: Table
    start: int
    end: int
    dropped: frozenset[str]  # terminals that no rule keeps
    lexer: FastLexer
    reserved: Mapping[str, frozenset[str]]


_PLANS: weakref.WeakKeyDictionary[Lark, _Fast | None] = weakref.WeakKeyDictionary()


Keep = list[tuple[int, bool]]  # Lark's child filter: the index of each kept child, and
# whether it is an inlined rule's list to splice in


def _all(keep: Keep, size: int) -> bool:
    return keep == [(index, False) for index in range(size)]


def _collect(keep: Keep, size: int) -> Reduce | None:
    """The children Lark's child filter passes on; None where that is all of them, as they
    are (the slice of the value stack is a new list already)."""
    if _all(keep, size):
        return None
    if keep == [(0, True), (1, False)]:  # a repetition helper adding an item
        return _append
    if keep == [(0, True), (1, True)]:
        return _extend
    if keep == [(0, True)] + [(index, False) for index in range(1, size)]:
        return _append_rest  # ... adding an item after an operator or a comma
    return partial(_filter, keep)


def _append(children: Children) -> Children:
    found: Children = children[0]
    found.append(children[1])
    return found


def _append_rest(children: Children) -> Children:
    found: Children = children[0]
    found += children[1:]
    return found


def _extend(children: Children) -> Children:
    found: Children = children[0]
    if not found:  # Lark then takes the second list itself
        found = children[1]
    else:
        found += children[1]
    return found


def _filter(keep: Keep, children: Children) -> Children:
    """Lark's ``ChildFilterLALR_NoPlaceholders``, with spliced children as plain lists."""
    found: Children = []
    for index, splice in keep:
        if not splice:
            found.append(children[index])
        elif found:
            found += children[index]
        else:
            found = children[index]
    return found


def _call(build: Reduce, keep: Keep, size: int) -> Reduce:
    """``build`` called with the kept children, the list made in the same step for the common
    shapes (one call per reduction instead of Lark's two or three)."""
    if _all(keep, size):
        return build
    if not any(splice for _, splice in keep):
        indices = [index for index, _ in keep]
        if len(indices) == 1:
            (first,) = indices
            return lambda children: build([children[first]])
        if len(indices) == 2:  # the common shapes, unrolled
            first, second = indices
            return lambda children: build([children[first], children[second]])
        pick = itemgetter(*indices) if indices else (lambda children: ())
        return lambda children: build(list(pick(children)))
    if keep == [(0, True)]:
        return lambda children: build(children[0])
    if keep == [(0, False), (1, True)]:
        return lambda children: build([children[0], *children[1]])
    collect = partial(_filter, keep)
    return lambda children: build(collect(children))


def _single_or(build: Reduce, keep: Keep, size: int) -> Reduce:
    """A ``?rule``: its one kept child, or the rule's node for more."""
    if keep == [(0, False), (1, True)]:  # ``?expr: unary (op unary)*``

        def first_and_list(children: Children) -> Any:
            rest: Children = children[1]
            return build([children[0], *rest]) if rest else children[0]

        return first_and_list
    collect = _collect(keep, size)

    def reduce(children: Children) -> Any:
        found = children if collect is None else collect(children)
        return found[0] if len(found) == 1 else build(found)

    return reduce


def _tree_name(build: Any) -> str | None:
    """The rule name when ``build`` is Lark's default ``partial(Tree, name)``."""
    plain = isinstance(build, partial) and build.func is Tree and not build.keywords
    if plain and len(build.args) == 1 and isinstance(build.args[0], str):
        return build.args[0]
    return None


def _pushed(rule: Any, dropped: frozenset[str]) -> list[int]:
    """The symbols of ``rule`` with a value on the value stack: all but the terminals no rule
    keeps, which the parse makes no token for."""
    return [
        index
        for index, symbol in enumerate(rule.expansion)
        if not (isinstance(symbol, Terminal) and symbol.name in dropped)
    ]


def _reduction(
    rule: Any, callback: Any, transformer: Any, dropped: frozenset[str]
) -> Reduce | _Pass | None:
    """One rule's reduction: a function of the values of its symbols that have one
    (``_pushed``); None where the rule's value is the list of them; a ``_Pass`` for the value
    of a single child. Raises ``FastPathError`` for a callback that is not one of Lark's plain
    wrappers around ``transformer``'s methods."""
    size = len(rule.expansion)
    keep: Keep = [(index, False) for index in range(size)]
    if isinstance(callback, ChildFilterLALR_NoPlaceholders):
        keep = [(index, bool(splice)) for index, splice in callback.to_include]
        callback = callback.node_builder
    pushed = _pushed(rule, dropped)
    if not {index for index, _ in keep} <= set(pushed):
        raise FastPathError(f"a kept terminal has no token: {rule}")
    passes = size == 1 and len(pushed) == 1
    keep = [(pushed.index(index), splice) for index, splice in keep]  # in the pushed values
    size = len(pushed)
    single = isinstance(callback, ExpandSingleChild)
    if single:
        callback = callback.node_builder
    name = str(rule.origin.name)
    tree = _tree_name(callback)
    if name.startswith("_"):  # spliced into its parent: its value is the list of children
        if single or tree != name:
            raise FastPathError(f"an inlined rule with its own callback: {name}")
        return _Pass(name) if passes and keep == [(0, True)] else _collect(keep, size)
    if tree is not None:
        build: Reduce = partial(Tree, tree)
    elif isinstance(callback, MethodType) and callback.__self__ is transformer:
        build = callback
    else:
        raise FastPathError(f"a callback that is not the transformer's: {name}")
    if single:
        if passes and keep == [(0, False)]:
            return _Pass(name)
        return _single_or(build, keep, size)
    return _call(build, keep, size)


def _build(lark: Lark, reserved: Mapping[str, frozenset[str]]) -> _Fast:
    frontend: Any = lark.parser
    lalr = frontend.parser.parser
    if not isinstance(frontend.lexer, ContextualLexer):
        raise FastPathError("not the contextual lexer")
    callbacks: dict[Any, Any] = lalr.callbacks
    if any(isinstance(key, str) for key in callbacks):
        raise FastPathError("terminal callbacks")
    transformer = lark.options.transformer
    kept = {
        str(symbol.name)
        for rule in lark.rules
        for symbol in rule.expansion
        if isinstance(symbol, Terminal) and (rule.options.keep_all_tokens or not symbol.filter_out)
    }
    dropped = frozenset(terminal.name for terminal in lark.terminals) - kept
    reductions = {
        rule: _reduction(rule, callbacks[rule], transformer, dropped) for rule in lark.rules
    }
    states: dict[int, dict[str, tuple[Any, Any]]] = lalr.parse_table.states
    table: Table = [{} for _ in range(max(states) + 1)]
    for state, actions in states.items():
        row = table[state]
        for name, (what, arg) in actions.items():
            kind = intern(name)  # the lexer's kinds are interned too: look-ups compare pointers
            reduction = reductions.get(arg)
            if what is Shift:
                row[kind] = arg
            elif isinstance(reduction, _Pass):  # one per action: it remembers its chains
                row[kind] = _Pass(reduction.name)
            else:
                width = len(_pushed(arg, dropped))
                row[kind] = (len(arg.expansion), width, reduction, {}, str(arg.origin.name))
    _fuse(table, states, reductions, _token_rules(lark.rules, callbacks, transformer))
    if len(lark.options.start) != 1:
        raise FastPathError("more than one start rule")
    (origin,) = lark.options.start
    start = lalr.parse_table.start_states[origin]
    end = lalr.parse_table.end_states[origin]
    lexer = FastLexer(frontend.lexer, reserved, dropped)
    return _Fast(table, start, end, dropped, lexer, reserved)


def _token_rules(rules: list[Any], callbacks: dict[Any, Any], transformer: Any) -> dict[Any, Make]:
    """The rules of one kept terminal whose callback is the transformer's method of one of its
    ``token_rules``, and the function making their node."""
    makers: dict[str, Make] = getattr(transformer, "token_rules", {})
    found: dict[Any, Make] = {}
    for rule in rules:
        callback = callbacks[rule]
        (symbol,) = rule.expansion if len(rule.expansion) == 1 else (None,)
        if (
            isinstance(symbol, Terminal)
            and not symbol.filter_out
            and isinstance(callback, MethodType)
        ):
            make = makers.get(callback.__name__)
            if make is not None and callback.__self__ is transformer:
                found[rule] = make
    return found


def _default(actions: dict[str, tuple[Any, Any]]) -> Any:
    """The rule a state reduces by whatever comes next, if there is one."""
    rules = {arg for what, arg in actions.values() if what is not Shift}
    if len(rules) == 1 and all(what is not Shift for what, _ in actions.values()):
        return rules.pop()
    return None


def _fuse(
    table: Table,
    states: dict[int, dict[str, tuple[Any, Any]]],
    reductions: dict[Any, Reduce | _Pass | None],
    makers: dict[Any, Make],
) -> None:
    """Turns the shifts into a default reduction by a rule of ``makers`` into ``_Made``."""
    for state, actions in states.items():
        for kind, (what, arg) in actions.items():
            if what is not Shift or not kind.isupper():
                continue
            rule = _default(states[arg])
            make = makers.get(rule) if rule is not None else None
            if make is None:
                continue
            after = table[state][str(rule.origin.name)]
            while (then := _default(states[after])) is not None and isinstance(
                reductions[then], _Pass
            ):
                after = table[state][str(then.origin.name)]
            table[state][kind] = _Made(after, make, arg)


def _fast(lark: Lark, reserved: Mapping[str, frozenset[str]]) -> _Fast | None:
    """The fast tables of ``lark``, made on its first parse (after a test has wrapped its
    callbacks: then there are none); None where Lark's setup is not one they reproduce."""
    found = _PLANS.get(lark)
    if lark not in _PLANS or (found is not None and found.reserved != reserved):
        try:
            found = _build(lark, reserved)
        except FastPathError:
            found = None
        _PLANS[lark] = found
    return found


def parse(text: str, lark: Lark, reserved: Mapping[str, frozenset[str]]) -> list[Any] | None:
    """The value of ``start`` for ``text``, or None where the recovering driver must parse it
    (``reserved``: per terminal, the words the driver reads as keywords instead)."""
    fast = _fast(lark, reserved)
    if fast is None:
        return None
    try:
        found: list[Any] | None = _run(fast, text)
    except FastPathError:
        return None
    return found


def _run(fast: _Fast, text: str) -> Any:
    """The parse loop: the contextual lexer's step (with ``FastLexer``'s scanners) and the
    LALR steps in one function, as calls per token would cost a good part of the parse.
    None at a syntax error; ``FastPathError`` where the lexer is unsure. Written for CPython's
    specialising interpreter: table look-ups are subscripts in ``try`` (cheaper than
    ``dict.get`` where the key is almost always there), classes are tested with ``type(x)``
    (``x.__class__`` is a slow attribute), stack indices are non-negative."""
    table = fast.table
    lexer = fast.lexer
    scanners = lexer.by_state
    newlines = line_breaks(text)
    index = 0  # of the first line break at or after the last token start read
    line_break = newlines[0]
    line, line_start = 1, 0
    pos = 0
    size = len(text)
    new_tuple = tuple.__new__  # ``Loc(...)`` without ``NamedTuple.__new__``'s Python frame
    dropped = fast.dropped
    state = lexes = fast.start  # the state on top of the stack, the state lexing in
    stack = [state]
    values: list[Any] = []
    top = 0  # len(stack) - 1: stack[top] is the state on top (a non-negative index is faster)
    while pos < size:
        # ---- the next token, as Lark's contextual lexer reads it in this state
        scanner = scanners[lexes] or lexer.scanner(lexes)
        found = scanner.match(text, pos)
        if found is None:
            if scanner.rest.fullmatch(text, pos) is not None:
                break
            raise FastPathError("no terminal of the parser state matches")
        group: Any = found.lastindex
        kind, words, keep, multiline = scanner.groups[group]
        pos = found.end()
        if keep or words is not None or pos > line_break:  # not for dropped punctuation
            start = found.end(1)
            if start > line_break:  # line breaks before the token (most often one)
                index += 1
                while newlines[index] < start:
                    index += 1
                line_break = newlines[index]
                line, line_start = index + 1, newlines[index - 1] + 1
            if pos > line_break and not multiline:
                raise FastPathError("a line break Lark does not count")
        if words is not None:  # a name: a keyword of the state, or a reserved word?
            value = text[start:pos]
            kind = words[value]
            if not kind:
                raise FastPathError("a reserved word read as a name")
            keep = kind not in dropped
        elif keep:
            value = text[start:pos]
        # ---- the LALR steps: reductions until the token is shifted
        while True:
            try:
                action = table[state][kind]
            except KeyError:  # a syntax error
                return None
            if type(action) is int:
                if keep:
                    token = FastToken()
                    token.type = kind
                    token.value = value
                    token.line = line
                    token.column = start - line_start + 1
                    if pos > line_break:
                        last = bisect_left(newlines, pos, index)
                        token.end_line, token.end_column = last + 1, pos - newlines[last - 1]
                    else:
                        token.end_line, token.end_column = line, pos - line_start + 1
                    values.append(token)
                stack.append(action)
                top += 1
                state = lexes = action
                break
            if type(action) is tuple:
                count, width, reduce, goto, _name = action
                first = top - count  # the state below the rule's symbols
                below = stack[first]
                try:
                    state = goto[below]
                except KeyError:
                    state = _goto(table, below, kind, action)
                if count == 1:
                    stack[top] = state
                else:
                    del stack[first + 1 :]
                    stack.append(state)
                    top = first + 1
                if width == 1:
                    children = [values.pop()]
                    values.append(children if reduce is None else reduce(children))
                elif width:  # the value replaces those of the children
                    children = values[-width:]
                    del values[1 - width :]
                    values[-1] = children if reduce is None else reduce(children)
                else:
                    values.append([] if reduce is None else reduce([]))
            elif type(action) is _Pass:
                try:
                    state = action.after[stack[top - 1]]
                except KeyError:
                    state = _after(table, stack, kind, action)
                stack[top] = state
            else:  # a ``_Made``: the token's node, as the next steps would make it
                if pos > line_break:
                    last = bisect_left(newlines, pos, index)
                    end_line, end_column = last + 1, pos - newlines[last - 1]
                else:
                    end_line, end_column = line, pos - line_start + 1
                where = new_tuple(Loc, (line, start - line_start + 1, end_line, end_column))
                values.append(action.make(kind, value, where))
                state = action.state
                stack.append(state)
                top += 1
                lexes = action.lexes
                break
    return _finish(fast, stack, values)


def _after(table: Table, stack: list[int], kind: str, action: _Pass) -> int:
    """The state on top once ``action`` and the ``_Pass`` reductions after it are done."""
    below = stack[-2]
    found = action.after.get(below)
    if found is None:
        found = table[below][action.name]
        while type(then := table[found].get(kind)) is _Pass:
            found = table[below][then.name]
        action.after[below] = found
    return found


def _goto(table: Table, below: int, kind: str, action: tuple[Any, ...]) -> int:
    """The state on top once the reduction ``action`` and the ``_Pass`` reductions after it
    (before ``kind``) are done over ``below``; remembered in the action."""
    found: int = table[below][action[4]]
    while type(then := table[found].get(kind)) is _Pass:
        found = table[below][then.name]
    action[3][below] = found
    return found


def _finish(fast: _Fast, stack: list[int], values: list[Any]) -> Any:
    """Lark's ``feed_token($END, is_end=True)``: reduce until the start rule's end state."""
    table = fast.table
    while True:
        action = table[stack[-1]].get("$END")
        if action is None or type(action) is int:
            return None
        if type(action) is _Pass:
            stack[-1] = table[stack[-2]][action.name]
        else:
            size, width, reduce, _gotos, name = action
            children = values[len(values) - width :]
            del stack[len(stack) - size :]
            del values[len(values) - width :]
            values.append(children if reduce is None else reduce(children))
            stack.append(table[stack[-1]][name])
        if stack[-1] == fast.end:
            return values[-1]
