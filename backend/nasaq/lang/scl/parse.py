"""Text → ``ast.SourceFile``: drives the LALR parser and recovers from syntax errors, so one
typo gives one message and the rest of the source is still parsed.

Recovery (yacc style, as the STL parser does): on a syntax error the parser pops its stack to
the nearest state where a list item may start (a file item, a block header item, a declaration
or a statement), shifts the ``ERROR`` terminal there (the grammar's ``bad``), and drops input up
to the end of the statement (``;``, consumed) or the next structural keyword (BEGIN, VAR...,
END_xxx, a block keyword), which is fed again. Where such a keyword cannot follow yet, the
END_xxx of the constructs still open are supplied (an ``IF`` without ``END_IF`` before
``END_FUNCTION``). No error is reported again until a real token has been accepted, so a typo
does not cascade. Reserved words the contextual lexer read as names (no rule accepts them
there) are turned back into keywords first, so the message names them.

Speed: a source is first parsed by ``nasaq.lang.scl.lalr`` (its own contextual lexer, Lark's
table run directly, the AST builder called without Lark's wrappers), which gives up at the first
syntax error; the driver then parses the source again from the start. The driver too lexes
(``_Driver.tokens``) and runs the LALR table (``_Driver.feed_fast``) itself on the good path;
recovery uses Lark's ``ParserState`` on the same stacks. Both run with gc off.
``python -m nasaq.lang.scl.bench`` measures the parse.
"""

from __future__ import annotations

import gc
import re
import weakref
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from lark import Lark, Token, Tree
from lark.exceptions import UnexpectedCharacters, UnexpectedToken
from lark.parse_tree_builder import ExpandSingleChild
from lark.parsers.lalr_analysis import Shift
from lark.utils import TextSlice

from nasaq.diagnostics import Diagnostic, render
from nasaq.lang.lalr_recovery import RecoveringDriver
from nasaq.lang.limits import LEX_FALLBACK_WINDOW
from nasaq.lang.scl import ast, lalr
from nasaq.lang.scl.grammar import parser
from nasaq.lang.scl.nesting import limit_nesting
from nasaq.lang.stl.build import loc
from nasaq.lang.stl.diag import span

MAX_SYNTAX_ERRORS = 50

_BLOCK_KEYWORDS = frozenset(
    {"ORGANIZATION_BLOCK", "FUNCTION_BLOCK", "FUNCTION", "PROGRAM", "DATA_BLOCK", "TYPE"}
)
_BLOCK_ENDS = frozenset(
    {
        "END_ORGANIZATION_BLOCK",
        "END_FUNCTION_BLOCK",
        "END_FUNCTION",
        "END_PROGRAM",
        "END_DATA_BLOCK",
        "END_TYPE",
    }
)
_END_OF = {
    "ORGANIZATION_BLOCK": "END_ORGANIZATION_BLOCK",
    "FUNCTION_BLOCK": "END_FUNCTION_BLOCK",
    "FUNCTION": "END_FUNCTION",
    "PROGRAM": "END_PROGRAM",
    "DATA_BLOCK": "END_DATA_BLOCK",
    "TYPE": "END_TYPE",
    "IF": "END_IF",
    "CASE": "END_CASE",
    "FOR": "END_FOR",
    "WHILE": "END_WHILE",
    "REPEAT": "END_REPEAT",
    "REGION_HEAD": "END_REGION",
    "STRUCT": "END_STRUCT",
    "VAR_KW": "END_VAR",
    "CONST": "END_CONST",
    "LABEL": "END_LABEL",
}
# Keywords that end or start a construct: recovery stops skipping at them.
_STATEMENT_ENDS = frozenset(
    {"END_IF", "ELSIF", "ELSE", "END_CASE", "END_FOR", "END_WHILE", "UNTIL", "END_REPEAT"}
)
_SYNC = (
    _BLOCK_KEYWORDS
    | _BLOCK_ENDS
    | _STATEMENT_ENDS
    | {"BEGIN", "VAR_KW", "END_VAR", "CONST", "END_CONST", "END_LABEL", "END_STRUCT"}
    | {"END_REGION"}
)
# Closers the recovery may supply, innermost constructs first.
_CLOSERS = (
    "END_IF",
    "END_CASE",
    "END_FOR",
    "END_WHILE",
    "END_REPEAT",
    "END_REGION",
    "END_STRUCT",
    "END_VAR",
    "END_CONST",
    "END_LABEL",
    *sorted(_BLOCK_ENDS),
)
_NEEDS_SEMI = frozenset({"END_IF", "END_CASE", "END_FOR", "END_WHILE", "END_REPEAT"})
_KEYWORDS = frozenset(
    {
        *_BLOCK_KEYWORDS,
        *_BLOCK_ENDS,
        *_STATEMENT_ENDS,
        "BEGIN",
        "END_VAR",
        "CONST",
        "END_CONST",
        "LABEL",
        "END_LABEL",
        "STRUCT",
        "END_STRUCT",
        "ARRAY",
        "OF",
        "IF",
        "THEN",
        "CASE",
        "FOR",
        "TO",
        "BY",
        "DO",
        "WHILE",
        "REPEAT",
        "EXIT",
        "CONTINUE",
        "GOTO",
        "RETURN",
        "END_REGION",
        "NOT",
        "AND",
        "XOR",
        "OR",
        "MOD",
        "DIV",
    }
)
_VAR_WORDS = frozenset({"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_STAT"})

_LINE_TOKENS = frozenset({"HEADER_VALUE", "TITLE_TEXT", "REGION_HEAD"})
_PUNCTUATION = frozenset(";:,.()[]{}+-*/=<>&#%")
_LEXEME = re.compile(r"[A-Za-z_]\w*|\d+|:=|=>|<>|<=|>=|\*\*|\S")

_NAMES = {
    "_SEMI": "';'",
    "COLON": "':'",
    "COMMA": "','",
    "DOT": "'.'",
    "LPAR": "'('",
    "RPAR": "')'",
    "LSQB": "'['",
    "RSQB": "']'",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "IDENT": "a name",
    "QSYM": "a symbol",
    "LOCAL": "a #variable",
    "ADDR": "an address",
    "AREA": "an address",
    "INTEGER": "a number",
    "REAL": "a number",
    "TYPED": "a constant",
    "STRING": "a character string",
    "TITLE_TEXT": "'='",
    "HEADER_KEY": "AUTHOR, FAMILY, NAME or VERSION",
    "HEADER_VALUE": "a value",
    "FLAG_KW": "KNOW_HOW_PROTECT",
    "VAR_KW": "VAR",
    "REGION_HEAD": "REGION",
    "$END": "end of file",
}


def _family(kind: str) -> str:
    if kind in _NEEDS_SEMI or kind == "END_REGION":
        return "statement"
    if kind in _BLOCK_ENDS:
        return "block"
    if kind in _CLOSERS:
        return "declaration"
    return kind


@dataclass(slots=True)
class ParseResult:
    source: ast.SourceFile
    diagnostics: list[Diagnostic] = field(default_factory=list)


def describe(token: Token) -> str:
    if token.type == "$END":
        return _NAMES["$END"]
    text = str(token)
    if len(text) > 24:
        text = text[:21] + "..."
    return f"'{text}'"


@cache
def _terminal_names() -> dict[str, str]:
    names = dict(_NAMES)
    for terminal in parser().terminals:
        if terminal.name not in names:
            pattern = terminal.pattern
            is_string = type(pattern).__name__ == "PatternStr"
            names[terminal.name] = f"'{pattern.value}'" if is_string else terminal.name
    return names


def expected_text(choices: set[str]) -> str:
    known = _terminal_names()
    terminals = [name for name in choices if name == name.upper() and name != "ERROR"]
    names = sorted({known.get(name, name) for name in terminals})
    if not names or len(names) > 3:
        return ""
    return " or ".join(names)


# A parser state's actions: a shift (or goto) is the next state, a reduction is
# ``(size, rule name, callback)``. Keys are plain strings, so lookups never reach ``Token.__eq__``.
_Action = int | tuple[int, str, Callable[[list[Any]], Any] | None]
_Table = dict[Any, dict[str, _Action]]
_TABLES: weakref.WeakKeyDictionary[Lark, _Table] = weakref.WeakKeyDictionary()


def _table(lark: Lark, states: dict[Any, dict[str, Any]], callbacks: dict[Any, Any]) -> _Table:
    """Lark's LALR table flattened for ``_Driver.feed_fast``, made once per parser (on its first
    parse, so callbacks a test installed after building the parser are the ones called)."""
    found = _TABLES.get(lark)
    if found is None:
        found = {}
        for state, actions in states.items():
            row: dict[str, _Action] = {}
            for kind, (what, arg) in actions.items():
                if what is Shift:
                    row[str(kind)] = arg
                else:
                    size = len(arg.expansion)
                    callback = callbacks[arg]
                    if size == 1 and isinstance(callback, ExpandSingleChild):
                        callback = None  # a ``?rule`` of one symbol: its value is the child's
                    row[str(kind)] = (size, str(arg.origin.name), callback)
            found[state] = row
        _TABLES[lark] = found
    return found


class _Driver(RecoveringDriver):
    def __init__(self, file: str, text: str, lark: Lark) -> None:
        self.file = file
        self.text = text
        self.diagnostics: list[Diagnostic] = []
        self.errors = 0
        self.quiet = False
        self.skipping = False
        self.interactive = lark.parse_interactive(text)
        self.state = self.interactive.parser_state
        self.states: dict[Any, dict[str, Any]] = self.state.parse_conf.states
        callbacks: dict[Any, Any] = self.state.parse_conf.callbacks
        self.table = _table(lark, self.states, callbacks)
        self.token_callbacks = {
            kind: callback for kind, callback in callbacks.items() if isinstance(kind, str)
        }
        self.last: Token | None = None

    # ---- reporting ----------------------------------------------------------------------

    def report(self, code: str, where: ast.Loc, **params: Any) -> bool:
        """Reports unless a recovery is still settling; False when parsing must stop."""
        if self.quiet:
            return True
        self.quiet = True
        self.errors += 1
        if self.errors > MAX_SYNTAX_ERRORS:
            self.diagnostics.append(render("SCL104", span(self.file, where), file=self.file))
            return False
        self.diagnostics.append(render(code, span(self.file, where), **params))
        return True

    def tokens(self) -> Iterator[Token]:
        """The contextual lexer's tokens, as ``lexer_thread.lex`` makes them but without its
        per-token layers (generator, scanner and line-counter calls). Where nothing matches in
        the current parser state, Lark's own lexer is asked, so it raises what it raises."""
        thread: Any = self.interactive.lexer_thread
        lex_state = thread.state
        contextual = thread.lexer
        counter = lex_state.line_ctr
        text: str = lex_state.text.text
        end: int = lex_state.text.end
        stack = self.state.state_stack
        plans: dict[Any, tuple[Any, ...]] = {}
        make: Any = Token._future_new
        while counter.char_pos < end:
            state = stack[-1]
            plan = plans.get(state)
            if plan is None:
                lexer = contextual.lexers[state]
                patterns = lexer.scanner._mres  # builds the scanner and its callbacks
                plan = (patterns, lexer.ignore_types, lexer.newline_types, lexer.callback)
                plans[state] = plan
            patterns, ignore, newlines, callbacks = plan
            pos = counter.char_pos
            for pattern in patterns:
                found = pattern.match(text, pos, end)
                if found is not None:
                    break
            else:
                # Lark's root lexer names the unexpected token. Its rest-of-line terminals
                # would scan to the end of the line for every token of a long broken line
                # (quadratic), so it sees a window of the text (``limits.LEX_FALLBACK_WINDOW``).
                whole = lex_state.text
                lex_state.text = TextSlice(text, whole.start, min(end, pos + LEX_FALLBACK_WINDOW))
                try:
                    token = next(contextual.lex(lex_state, self.state))
                finally:
                    lex_state.text = whole
                yield token
                continue
            value: str = found.group()
            kind: str = found.lastgroup or ""
            line = counter.line
            column = counter.column
            stop = pos + len(value)
            if kind in newlines:
                count = value.count("\n")
                if count:
                    counter.line = line + count
                    counter.line_start_pos = pos + value.rindex("\n") + 1
            counter.char_pos = stop
            counter.column = stop - counter.line_start_pos + 1
            if kind in ignore and kind not in callbacks:
                continue
            token = make(kind, value, pos, line, column, counter.line, counter.column, stop)
            if kind in callbacks:
                token = callbacks[kind](token)
            if kind not in ignore:
                lex_state.last_token = token
                yield token

    def feed_fast(self, token: Token) -> bool:
        """``ParserState.feed_token`` without its per-step overheads (asserts, ``Rule`` and
        ``Token`` comparisons); False where Lark would raise ``UnexpectedToken``, with the
        stacks reduced as far as Lark would have reduced them."""
        table = self.table
        stack = self.state.state_stack
        values = self.state.value_stack
        kind = token.type
        while True:
            action = table[stack[-1]].get(kind)
            if action is None:
                return False
            if action.__class__ is int:
                stack.append(action)
                callback = self.token_callbacks.get(kind) if self.token_callbacks else None
                values.append(token if callback is None else callback(token))
                return True
            size, name, reduce = action  # type: ignore[misc]
            if reduce is None:
                del stack[-1]
                stack.append(table[stack[-1]][name])
                continue
            if size:
                children = values[-size:]
                del stack[-size:]
                del values[-size:]
            else:
                children = []
            values.append(reduce(children))
            stack.append(table[stack[-1]][name])

    def try_feed(self, token: Token) -> bool:
        try:
            self.state.feed_token(token)
        except UnexpectedToken:
            return False
        return True

    def innermost_closer(self, state: Any = None) -> str | None:
        return next((kind for kind in _CLOSERS if self.acceptable(kind, state)), None)

    def close(self, closer: str, near: Token | None, state: Any = None) -> bool:
        """Supplies ``closer`` (and the ``;`` an END_IF ... END_REPEAT needs)."""
        target = state or self.state
        try:
            target.feed_token(self.synthetic(closer, near))
            if closer in _NEEDS_SEMI:
                target.feed_token(self.synthetic("_SEMI", near))
        except UnexpectedToken:
            return False
        return True

    def place(self, token: Token) -> bool:
        """Feeds ``token`` after an ERROR, first closing the constructs still open if that
        makes it acceptable (tried on a copy of the parser state). A closer that fits nothing
        open stands for the innermost closer of its kind (``END_WHILE`` written for
        ``END_FOR``) when there is one; otherwise the token is skipped."""
        try:
            trial = self.state.copy()
        except RecursionError:  # a value nested past nasaq.lang.limits: the token is skipped
            return False
        closers: list[str] = []
        for _ in range(16):
            if self.acceptable(token.type, trial):
                for kind in closers:
                    self.close(kind, token)
                return self.try_feed(token)
            found = self.innermost_closer(trial)
            if found is None or not self.close(found, token, trial):
                break
            closers.append(found)
        innermost = self.innermost_closer()
        if innermost is not None and _family(innermost) == _family(token.type):
            return self.close(innermost, token)
        return False

    # ---- main loop ----------------------------------------------------------------------

    def run(self) -> list[Any]:
        lexer: Any = self.interactive.lexer_thread
        while True:
            try:
                for token in self.tokens():
                    kind = token.type
                    if kind == "IDENT" or kind == "HEADER_VALUE":
                        self.retype(token)
                    self.last = token
                    if self.skipping or self.quiet:
                        if not self.feed(token):
                            return self.harvest()
                        continue
                    if not self.feed_fast(token) and not self.syntax_error(token):
                        return self.harvest()
                return self.finish()
            except UnexpectedCharacters as error:
                at: int = error.pos_in_stream or 0
                where = ast.Loc(error.line, error.column, error.line, error.column + 1)
                char = self.text[at] if at < len(self.text) else ""
                if not self.report("SCL102", where, char=repr(char)):
                    return self.harvest()
                lexer.state.line_ctr.feed(self.text[at : at + 1])
                if not self.skipping:
                    self.shift_error(self.last)
                    self.skipping = True
            except UnexpectedToken as error:
                # the contextual lexer found a token that no rule accepts here
                token = self.shorten(error.token, lexer.state.line_ctr)
                self.retype(token)
                self.last = token
                if self.skipping or self.quiet:
                    if not self.feed(token):
                        return self.harvest()
                elif not self.syntax_error(token):
                    return self.harvest()

    def shorten(self, token: Token, counter: Any) -> Token:
        """A rest-of-line token (a header value, a title, a REGION line) that the lexer took
        only to name an error is cut back to its first word; lexing resumes after that."""
        if token.type not in _LINE_TOKENS or token.start_pos is None:
            return token
        found = _LEXEME.match(self.text, token.start_pos)
        if found is None:  # pragma: no cover - the token is not empty
            return token
        size = found.end() - token.start_pos
        counter.char_pos = found.end()
        counter.line = token.line
        counter.column = (token.column or 1) + size
        counter.line_start_pos = counter.char_pos - counter.column + 1
        text = found.group()
        if text[0].isalpha() or text[0] == "_":
            kind = "IDENT"
        elif len(text) == 1 and text not in _PUNCTUATION and not text.isdigit():
            kind = "BAD_CHAR"
        else:
            kind = "PUNCTUATION"
        return Token(
            kind,
            text,
            token.start_pos,
            token.line,
            token.column,
            token.line,
            counter.column,
            found.end(),
        )

    @staticmethod
    def retype(token: Token) -> None:
        if token.type in ("IDENT", "HEADER_VALUE"):
            word = token.upper()
            if word in _KEYWORDS:
                token.type = word
            elif word in _VAR_WORDS:
                token.type = "VAR_KW"

    def feed(self, token: Token) -> bool:
        kind = token.type
        if self.skipping:
            if kind == "_SEMI":
                self.skipping = False
                return True
            if kind not in _SYNC:
                return True
            self.skipping = False
            if self.place(token):
                return True
            return self.syntax_error(token)
        try:
            self.state.feed_token(token)
        except UnexpectedToken:
            return self.syntax_error(token)
        if kind != "_SEMI":
            self.quiet = False
        return True

    def syntax_error(self, token: Token) -> bool:
        if token.type == "BAD_CHAR":
            if not self.report("SCL102", loc(token), char=repr(str(token))):
                return False
            self.shift_error(token)
            self.skipping = True
            return True
        candidates = self.states[self.state.state_stack[-1]]
        expected = {kind for kind in candidates if kind.isupper() and self.acceptable(kind)}
        hint = expected_text(expected)
        if not hint and token.type in _SYNC:
            closer = next((kind for kind in _CLOSERS if kind in expected), None)
            hint = closer or ""
        hint = f"; expected {hint}" if hint else ""
        if not self.report("SCL101", loc(token), found=describe(token), hint=hint):
            return False
        self.shift_error(token)
        self.skipping = True
        if token.type in _SYNC:
            self.skipping = False
            # a stray END_REGION (and its title) is complete: the next statement is kept
            if not self.place(token) and token.type != "END_REGION":
                self.skipping = True
        elif token.type == "_SEMI":
            self.skipping = False
        return True

    def finish(self) -> list[Any]:
        end = self.synthetic("$END", self.last)
        for _ in range(16):
            try:
                result: list[Any] = self.state.feed_token(end, True)
                return result
            except UnexpectedToken:
                pass
            construct = self.open_construct()
            where = loc(self.last) if self.last is not None else ast.Loc(1, 1, 1, 1)
            self.report(
                "SCL103", where, construct=construct, expected=_END_OF.get(construct, "';'")
            )
            self.quiet = True
            closer = self.innermost_closer()
            if closer is None or not self.close(closer, self.last):
                self.shift_error(self.last)
                closer = self.innermost_closer()
                if closer is None or not self.close(closer, self.last):
                    break
        return self.harvest()

    def open_construct(self) -> str:
        for value in reversed(self.state.value_stack):
            if isinstance(value, Token) and value.type in _END_OF:
                return "REGION" if value.type == "REGION_HEAD" else value.type
        return "the file"

    def harvest(self) -> list[Any]:
        """The complete blocks on the parser's stack when parsing had to stop."""
        found: list[Any] = []

        def walk(value: Any) -> None:
            if isinstance(value, Tree):
                for child in value.children:
                    walk(child)
            elif isinstance(value, ast.Block):
                found.append(value)
            elif isinstance(value, list):
                for child in value:
                    walk(child)

        for value in self.state.value_stack:
            walk(value)
        return found


# Per terminal, the words ``_Driver.retype`` turns into keywords (the fast parse leaves them to it).
_RESERVED = {"IDENT": _KEYWORDS | _VAR_WORDS, "HEADER_VALUE": _KEYWORDS | _VAR_WORDS}


def parse_source(
    file: str, text: str, lark: Lark | None = None, *, fast: bool = True
) -> ParseResult:
    """Parses one SCL source; never raises for bad input (every problem is a diagnostic).
    ``lark`` replaces the shared parser (tests pass one that records the rules it reduces).
    A source is first parsed by ``lalr.parse``, which gives up at the first syntax error; then
    (or with ``fast=False``) by the recovering driver, from the start."""
    if text.startswith("\ufeff"):
        text = text[1:]
    gc_was_enabled = gc.isenabled()
    gc.disable()  # the parse allocates many small objects; collection passes make it quadratic
    try:
        lark = lark or parser()
        items: list[Any] | None = lalr.parse(text, lark, _RESERVED) if fast else None
        diagnostics: list[Diagnostic] = []
        if items is None:
            driver = _Driver(file, text, lark)
            items = driver.run()
            diagnostics = driver.diagnostics
    finally:
        if gc_was_enabled:
            gc.enable()
    blocks = [item for item in items if isinstance(item, ast.Block)]
    diagnostics += limit_nesting(file, blocks)  # what the recursive passes could not take
    pragmas = [
        attribute
        for item in items
        if isinstance(item, list) and not isinstance(item, ast.Block)
        for attribute in item
        if isinstance(attribute, ast.Attribute)
    ]
    return ParseResult(ast.SourceFile(file, blocks, pragmas), diagnostics)
