"""Random sentences of a Lark grammar, fast enough for tens of thousands of fuzz cases.

Hypothesis' ``hypothesis.extra.lark.from_lark`` draws the same kind of text, but at 30 to 100 ms
per example on these grammars (its engine and its regex strategies); the bounded run in
``make test`` has about 4 ms per case for generation and compilation together. So this module
expands the grammar itself: a rule's alternatives are picked at random until a depth budget is
spent, then the alternative that ends soonest (precomputed) is taken; a terminal's regular
expression is sampled with ``re._parser`` (repeats bounded, mostly ASCII, the odd non-ASCII
character). Tokens are joined by a space or, for grammars that end statements with ``_NL``, a
newline where the grammar asks for one. Deterministic: everything comes from the caller's
``random.Random``.
"""

from __future__ import annotations

import random
import re
import string
from functools import cache
from typing import Any

from lark import Lark
from lark.grammar import NonTerminal, Terminal

try:  # Python 3.11 names it re._parser; older ones sre_parse
    from re import _parser as sre_parse  # type: ignore[attr-defined]
except ImportError:  # pragma: no cover
    import sre_parse  # type: ignore[no-redef]

_CATEGORY = {
    "CATEGORY_DIGIT": string.digits,
    "CATEGORY_NOT_DIGIT": string.ascii_letters + "_ ",
    "CATEGORY_SPACE": " \t",
    "CATEGORY_NOT_SPACE": string.ascii_letters + string.digits + "_#.",
    "CATEGORY_WORD": string.ascii_letters + string.digits + "_",
    "CATEGORY_NOT_WORD": " .,;:+-*/()",
}
_ODD = "äÄßé€ا٣ب\u200fه\u00a0\u2028"  # non-ASCII a user may paste: umlauts, Arabic, RTL mark


class _RegexSampler:
    """Draws strings matching a regular expression (its parse tree from ``re._parser``)."""

    def __init__(self, pattern: str, flags: int, rng: random.Random) -> None:
        self.tree = sre_parse.parse(pattern, flags)
        self.ignore_case = bool(flags & re.IGNORECASE)
        self.rng = rng

    def sample(self) -> str:
        out: list[str] = []
        self._emit(self.tree, out, 0)
        return "".join(out)

    def _char(self, code: int) -> str:
        ch = chr(code)
        if self.ignore_case and self.rng.random() < 0.3:
            return ch.swapcase()
        return ch

    def _emit(self, items: Any, out: list[str], depth: int) -> None:
        rng = self.rng
        for op, arg in items:
            name = str(op)
            if name == "LITERAL":
                out.append(self._char(arg))
            elif name == "NOT_LITERAL":
                out.append(rng.choice([c for c in "aZ0 _;" if ord(c) != arg]))
            elif name == "ANY":
                out.append(rng.choice(string.ascii_letters + " ;:" + _ODD[:3]))
            elif name == "IN":
                out.append(self._in(arg))
            elif name in ("MAX_REPEAT", "MIN_REPEAT", "POSSESSIVE_REPEAT"):
                low, high, sub = arg
                top = min(high, low + (3 if depth < 2 else 1))
                for _ in range(rng.randint(low, max(low, top))):
                    self._emit(sub, out, depth + 1)
            elif name == "SUBPATTERN":
                self._emit(arg[-1], out, depth)
            elif name == "BRANCH":
                self._emit(rng.choice(arg[1]), out, depth)
            elif name in ("AT", "ASSERT", "ASSERT_NOT", "GROUPREF"):
                continue
            else:  # pragma: no cover - an operator the grammars do not use
                continue

    def _in(self, arg: Any) -> str:
        rng = self.rng
        negate = any(str(op) == "NEGATE" for op, _ in arg)
        if negate:
            return rng.choice("azAZ09 _" + _ODD[:4])
        op, value = rng.choice(arg)
        name = str(op)
        if name == "LITERAL":
            return self._char(value)
        if name == "RANGE":
            low, high = value
            return self._char(rng.randint(low, high))
        if name == "CATEGORY":
            return rng.choice(_CATEGORY.get(str(value), "a"))
        return "a"


class GrammarSampler:
    """Random sentences of one Lark grammar."""

    def __init__(self, grammar: str, start: str | None = None) -> None:
        kwargs: dict[str, Any] = {"parser": "lalr", "lexer": "contextual"}
        if start:
            kwargs["start"] = start
        lark = Lark(grammar, **kwargs)
        self.start = start or lark.options.start[0]
        self.rules: dict[str, list[tuple[Any, ...]]] = {}
        for rule in lark.rules:
            self.rules.setdefault(rule.origin.name, []).append(tuple(rule.expansion))
        self.terminals = {t.name: t for t in lark.terminals}
        self.cost = self._min_costs()

    def _min_costs(self) -> dict[str, int]:
        """Per nonterminal, the fewest expansion steps to a sentence (to end a deep branch)."""
        cost: dict[str, int] = {}
        changed = True
        while changed:
            changed = False
            for name, expansions in self.rules.items():
                for expansion in expansions:
                    total = 1
                    for symbol in expansion:
                        if isinstance(symbol, NonTerminal):
                            if symbol.name not in cost:
                                break
                            total += cost[symbol.name]
                    else:
                        if total < cost.get(name, 1 << 30):
                            cost[name] = total
                            changed = True
        return cost

    def _expansion_cost(self, expansion: tuple[Any, ...]) -> int:
        return sum(self.cost.get(s.name, 1 << 20) for s in expansion if isinstance(s, NonTerminal))

    def sentence(self, rng: random.Random, budget: int = 12, max_tokens: int = 400) -> str:
        tokens: list[str] = []
        samplers: dict[str, _RegexSampler] = {}
        stack: list[tuple[Any, int]] = [(NonTerminal(self.start), 0)]
        while stack:
            symbol, depth = stack.pop()
            if isinstance(symbol, Terminal):
                tokens.append(self._terminal(symbol.name, rng, samplers))
                continue
            expansions = self.rules.get(symbol.name, [()])
            if depth >= budget or len(tokens) > max_tokens:
                chosen = min(expansions, key=self._expansion_cost)
            else:
                chosen = rng.choice(expansions)
                if not chosen and len(expansions) > 1 and rng.random() < 0.85:
                    chosen = rng.choice([e for e in expansions if e])  # grow, mostly
            # A list's own recursion (Lark's ``__x_star_0``) does not deepen the sentence.
            step = 0 if symbol.name.startswith("__") and depth < budget else 1
            for child in reversed(chosen):
                stack.append((child, depth + step))
        return self._join(tokens, rng)

    def _terminal(self, name: str, rng: random.Random, samplers: dict[str, _RegexSampler]) -> str:
        if name in ("_NL", "NEWLINE"):
            return "\n"
        if name == "ERROR":  # the parsers' synthetic recovery token: never in a source
            return ""
        definition = self.terminals.get(name)
        if definition is None:
            return ""
        pattern = definition.pattern
        if pattern.type == "str":
            value = str(pattern.value)
            if "i" in pattern.flags and rng.random() < 0.2:
                return "".join(c.swapcase() if rng.random() < 0.5 else c for c in value)
            return value
        sampler = samplers.get(name)
        if sampler is None:
            flags = re.IGNORECASE if "i" in pattern.flags else 0
            flags |= re.MULTILINE if "m" in pattern.flags else 0
            flags |= re.DOTALL if "s" in pattern.flags else 0
            sampler = samplers[name] = _RegexSampler(pattern.value, flags, rng)
        sampler.rng = rng
        return sampler.sample()

    @staticmethod
    def _join(tokens: list[str], rng: random.Random) -> str:
        out: list[str] = []
        for token in tokens:
            if not token:
                continue
            if out and not out[-1].endswith("\n") and token != "\n":
                out.append(" " if rng.random() < 0.9 else "\n")
            out.append(token)
        return "".join(out) + "\n"


@cache
def sampler_for(path: str, start: str | None = None) -> GrammarSampler:
    from pathlib import Path

    return GrammarSampler(Path(path).read_text(encoding="utf-8"), start)
