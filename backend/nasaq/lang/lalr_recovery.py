"""Error recovery on Lark's LALR parser state, shared by the STL and SCL parsers.

Both grammars have an ``ERROR`` terminal where a statement or declaration may be skipped; after a
syntax error the driver pops the parser stack back to a state that accepts ``ERROR``, shifts a
synthetic ``ERROR`` token and resumes at the next statement boundary.
"""

from __future__ import annotations

from typing import Any

from lark import Token
from lark.exceptions import UnexpectedToken
from lark.parsers.lalr_analysis import Shift


class RecoveringDriver:
    """Mixin for a parse driver with ``states`` (Lark's parse table) and ``state`` (its
    interactive ``parser_state``)."""

    states: Any
    state: Any

    def acceptable(self, kind: str, state: Any = None) -> bool:
        """Whether the parser would shift ``kind`` now, following its reductions on a copy of
        the state stack (LALR lookaheads alone can promise a reduction that then fails)."""
        states = self.states
        stack = list((state or self.state).state_stack)
        while True:
            action = states[stack[-1]].get(kind)
            if action is None:
                return False
            what, rule = action
            if what is Shift:
                return True
            size = len(rule.expansion)
            if size:
                del stack[-size:]
            goto = states[stack[-1]].get(rule.origin.name)
            if goto is None:
                return False
            stack.append(goto[1])

    def synthetic(self, kind: str, near: Token | None) -> Token:
        """An empty token of ``kind`` placed where ``near`` is (or at 1:1)."""
        if near is None:
            return Token(kind, "", 0, 1, 1, 1, 1, 0)
        return Token.new_borrow_pos(kind, "", near)

    def shift_error(self, near: Token | None) -> None:
        """Pops states until one shifts ``ERROR``, then shifts it."""
        stack = self.state.state_stack
        values = self.state.value_stack
        while True:
            while "ERROR" not in self.states[stack[-1]] and len(stack) > 1:
                stack.pop()
                values.pop()
            try:
                self.state.feed_token(self.synthetic("ERROR", near))
                return
            except UnexpectedToken:
                if len(stack) == 1:  # the start state always shifts ERROR; be safe anyway
                    return
                stack.pop()
                values.pop()
