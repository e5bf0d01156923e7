"""Text → ``SourceNode``: drives the LALR parser, decides which newlines end statements, and
recovers from syntax errors so one typo gives one message and the rest is still checked.

Newlines: STEP 7 ends statements with ``;``, awlsim programs with the end of the line; both are
accepted inside code. In headers, declarations, DB values and inside a CALL's parameter list a
newline is white space. ``NewlineFilter`` tracks that from the token stream alone; the token loop
also drops a newline that ends nothing (after ``;``, a label, a NETWORK or TITLE line), so the
parser sees one token fewer per line of a STEP 7 export.

Recovery (yacc style): on a syntax error the parser pops its stack to the nearest state where a
list item may start (code statement, declaration, DB value, header item), shifts the ``ERROR``
terminal there, and drops input up to the end of the statement (``;`` or newline) or the next
structural keyword (NETWORK, BEGIN, END_...). Missing END_... keywords are supplied when the next
block or the end of the file shows they are missing. Errors are not reported again until a real
token has been accepted, so a typo does not cascade.
"""

from __future__ import annotations

import gc
import re
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from lark import Lark, Token, Tree
from lark.exceptions import UnexpectedCharacters, UnexpectedToken

from nasaq.diagnostics import Diagnostic
from nasaq.lang.lalr_recovery import RecoveringDriver
from nasaq.lang.stl import ast
from nasaq.lang.stl.build import loc
from nasaq.lang.stl.diag import problem
from nasaq.lang.stl.grammar import parser
from nasaq.lang.stl.nesting import limit_nesting

MAX_SYNTAX_ERRORS = 50

_CODE_BLOCKS = frozenset({"ORGANIZATION_BLOCK", "FUNCTION_BLOCK", "FUNCTION"})
_DATA_BLOCKS = frozenset({"DATA_BLOCK", "TYPE"})
_BLOCK_ENDS = frozenset(
    {"END_ORGANIZATION_BLOCK", "END_FUNCTION_BLOCK", "END_FUNCTION", "END_DATA_BLOCK", "END_TYPE"}
)
_SYNC = (
    _CODE_BLOCKS
    | _DATA_BLOCKS
    | _BLOCK_ENDS
    | {
        "BEGIN",
        "END_VAR",
        "END_STRUCT",
        "VAR_KW",
        "NETWORK",
        "TITLE",
    }
)
# Reserved words: where the contextual lexer read one as a name (because no rule accepts the
# keyword in that state), it is turned back into the keyword, so a missing END_VAR or BEGIN is
# reported where it is missing and recovery can resynchronise on it.
_RESERVED = {
    name: name
    for name in (
        *_CODE_BLOCKS,
        *_DATA_BLOCKS,
        *_BLOCK_ENDS,
        "BEGIN",
        "END_VAR",
        "END_STRUCT",
    )
} | dict.fromkeys(("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP"), "VAR_KW")
_NAME_TOKENS = frozenset({"IDENT", "WORD_OP", "HEADER_VALUE"})

_END_OF = {
    "ORGANIZATION_BLOCK": "END_ORGANIZATION_BLOCK",
    "FUNCTION_BLOCK": "END_FUNCTION_BLOCK",
    "FUNCTION": "END_FUNCTION",
    "DATA_BLOCK": "END_DATA_BLOCK",
    "TYPE": "END_TYPE",
}
_REOPENING = _CODE_BLOCKS | _DATA_BLOCKS | {"BEGIN"}
_CLOSERS = ("END_STRUCT", "END_VAR", *sorted(_BLOCK_ENDS))

_NAMES = {
    "_NL": "end of line",
    "_SEMI": "';'",
    "_LPAR": "'('",
    "_RPAR": "')'",
    "_DOT": "'.'",
    "COMMA": "','",
    "COLON": "':'",
    "LSQB": "'['",
    "RSQB": "']'",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "IDENT": "a name",
    "WORD_OP": "an instruction",
    "SYM_OP": "an instruction",
    "LABEL": "a label",
    "ADDR": "an address",
    "AREA": "an address",
    "NUMBER": "a number",
    "REAL": "a number",
    "TYPED": "a constant",
    "BYTES": "a constant",
    "POINTER": "a pointer",
    "CHARS": "a character constant",
    "QSYM": "a symbol",
    "LOCAL": "a #variable",
    "STATUS_CMP": "a status condition",
    "TITLE_TEXT": "'='",
    "HEADER_KEY": "AUTHOR, FAMILY, NAME or VERSION",
    "HEADER_VALUE": "a value",
    "FLAG_KW": "KNOW_HOW_PROTECT",
    "VAR_KW": "VAR",
    "$END": "end of file",
}
# What ``NewlineFilter.keep`` looks at besides newlines, and the modes where a newline counts.
_MODE_TOKENS = _CODE_BLOCKS | _DATA_BLOCKS | _BLOCK_ENDS | {"BEGIN", "_LPAR", "_RPAR"}
_MODE_TOKENS |= {"LBRACE", "RBRACE"}
_NEWLINE_MODES = frozenset({"top", "code"})
# After these a newline ends no statement (the parser would take it as an empty code item).
_NO_STATEMENT_BEFORE = frozenset(
    {"", "_SEMI", "_NL", "LABEL", "NETWORK", "TITLE_TEXT", "BEGIN", *_BLOCK_ENDS}
)
_BINARY = re.compile(r"[\x00-\x08\x0e-\x19\x7f]")
_REST_OF_STATEMENT = re.compile(r"[^\n;]*")
# TIA Portal writes a CALL's parameter list on the lines after the CALL ("CALL #V1" newline
# "(  Open := ...", or first "{time_type := 'Time'}"): there the newline after the CALL ends
# nothing.
_PARAMETERS_FOLLOW = re.compile(r"\s*(?://[^\n]*\s*)*[({]")


@dataclass(slots=True)
class ParseResult:
    source: ast.SourceNode
    diagnostics: list[Diagnostic] = field(default_factory=list)
    comments: dict[int, str] = field(default_factory=dict)  # line -> text of its // comment


class NewlineFilter:
    """Says which ``_NL`` tokens the parser sees: at file level and in code, outside a CALL's
    parentheses. Everything else is white space."""

    __slots__ = ("depth", "mode", "pending")

    def __init__(self) -> None:
        self.mode = "top"  # top | head | code | data
        self.pending = "code"
        self.depth = 0

    def keep(self, token: Token) -> bool:
        kind = token.type
        if kind == "_NL":
            return self.mode in ("top", "code") and self.depth == 0
        if kind in _CODE_BLOCKS or kind in _DATA_BLOCKS:
            self.pending = "code" if kind in _CODE_BLOCKS else "data"
            self.mode = "head"
            self.depth = 0
        elif kind == "BEGIN":
            self.mode = "code" if self.pending == "code" else "data"
        elif kind in _BLOCK_ENDS:
            self.mode = "top"
            self.depth = 0
        elif self.mode in ("top", "code"):  # code outside blocks is code too (implicit OB 1)
            if kind == "_LPAR" or kind == "LBRACE":  # a CALL's parameters or attributes
                self.depth += 1
            elif (kind == "_RPAR" or kind == "RBRACE") and self.depth:
                self.depth -= 1
        return True


def describe(token: Token) -> str:
    if token.type in ("_NL", "$END"):
        return _NAMES[token.type]
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


def expected_text(choices: set[str] | frozenset[str] | list[str]) -> str:
    known = _terminal_names()
    terminals = [name for name in choices if name == name.upper() and name != "ERROR"]
    names = sorted({known.get(name, name) for name in terminals})
    if len(names) > 3:
        return ""
    return " or ".join(names)


def is_binary(text: str) -> bool:
    """Text with NUL or other control characters (not tab/newline/CR/FF) is no STL source."""
    sample = text[:65536]
    return "\x00" in text or len(_BINARY.findall(sample)) > max(8, len(sample) // 200)


def line_comments(text: str) -> dict[int, str]:
    """The ``//`` comment of every line that has one (outside quotes), by 1-based line."""
    comments: dict[int, str] = {}
    if "//" not in text:
        return comments
    for number, line in enumerate(text.split("\n"), start=1):
        if "//" not in line:
            continue
        at = line.find("//")
        if "'" in line[:at] or '"' in line[:at]:
            at = _comment_start(line)
            if at < 0:
                continue
        comments[number] = line[at + 2 :].strip()
    return comments


def _comment_start(line: str) -> int:
    quote = ""
    for i, char in enumerate(line):
        if quote:
            if char == quote:
                quote = ""
        elif char in "'\"":
            quote = char
        elif line.startswith("//", i):
            return i
    return -1


class _Driver(RecoveringDriver):
    def __init__(self, file: str, text: str, lark: Lark) -> None:
        self.file = file
        self.text = text
        self.diagnostics: list[Diagnostic] = []
        self.errors = 0
        self.quiet = False
        self.skipping = False
        self.skip_call = False
        self.filter = NewlineFilter()
        self.interactive = lark.parse_interactive(text)
        self.state = self.interactive.parser_state
        self.states: dict[Any, dict[str, Any]] = self.state.parse_conf.states
        self.last: Token | None = None

    # ---- reporting ----------------------------------------------------------------------

    def report(self, code: str, where: ast.Loc, **params: Any) -> bool:
        """Reports unless a recovery is still settling; False when parsing must stop."""
        if self.quiet:
            return True
        self.quiet = True
        self.errors += 1
        if self.errors > MAX_SYNTAX_ERRORS:
            self.diagnostics.append(problem("STL104", self.file, where, file=self.file))
            return False
        self.diagnostics.append(problem(code, self.file, where, **params))
        return True

    def try_feed(self, token: Token) -> bool:
        try:
            self.state.feed_token(token)
        except UnexpectedToken:
            return False
        return True

    def place(self, token: Token) -> bool:
        """Feeds ``token`` after an ERROR, closing open sections with synthetic END_... first."""
        for _ in range(12):
            if self.acceptable(token.type):
                return self.try_feed(token)
            closer = next((kind for kind in _CLOSERS if self.acceptable(kind)), None)
            if closer is None:
                return False
            self.filter.keep(self.synthetic(closer, token))
            if token.type in _REOPENING:
                self.filter.keep(token)  # the synthetic END reset the mode this token had set
            if not self.try_feed(self.synthetic(closer, token)):
                return False
        return False

    # ---- main loop ----------------------------------------------------------------------

    def run(self) -> list[Any] | None:
        """The token loop. Its common path (no error being recovered from) feeds the parser
        directly; a newline reaches the parser only where it ends a statement, and not right
        after a ``;``, another newline, a label or a NETWORK/TITLE line: there it ends nothing,
        and a STEP 7 export has one after every ``;``."""
        lexer: Any = self.interactive.lexer_thread
        newlines = self.filter
        state = self.state
        previous = ""
        calling = False  # in a CALL statement that has no parameter list yet
        text = self.text
        while True:
            try:
                for token in lexer.lex(state):
                    kind = token.type
                    if kind == "_NL":
                        if newlines.depth or newlines.mode not in _NEWLINE_MODES:
                            continue
                        if previous in _NO_STATEMENT_BEFORE and not self.skipping:
                            continue
                        if calling:
                            if _PARAMETERS_FOLLOW.match(text, token.end_pos or 0):
                                continue
                            calling = False
                    else:
                        if kind == "WORD_OP":
                            calling = len(token) == 4 and token.upper() == "CALL"
                        elif kind == "_LPAR" or (kind == "_SEMI" and not newlines.depth):
                            calling = False
                        if kind in _NAME_TOKENS:
                            reserved = _RESERVED.get(token.upper())
                            if reserved is not None:
                                token.type = kind = reserved
                        if kind in _MODE_TOKENS:
                            newlines.keep(token)
                    previous = kind
                    self.last = token
                    if self.skipping or self.quiet:
                        if not self.feed(token):
                            return self.harvest()
                        continue
                    try:
                        state.feed_token(token)
                    except UnexpectedToken:
                        if not self.syntax_error(token):
                            return self.harvest()
                return self.finish()
            except UnexpectedCharacters as error:
                at: int = error.pos_in_stream or 0
                where = ast.Loc(error.line, error.column, error.line, error.column + 1)
                char = self.text[at] if at < len(self.text) else ""
                if not self.report("STL102", where, char=repr(char)):
                    return self.harvest()
                rest = _REST_OF_STATEMENT.match(self.text, at)
                skip = max(1, rest.end() - at) if rest else 1
                lexer.state.line_ctr.feed(self.text[at : at + skip])
                self.recover(None)
            except UnexpectedToken as error:
                # the contextual lexer found a token that no rule accepts here
                token = error.token
                if token.type in _NAME_TOKENS:
                    token.type = _RESERVED.get(token.upper(), token.type)
                self.filter.keep(token)
                self.last = token
                previous = token.type
                if not self.syntax_error(token):
                    return self.harvest()

    def feed(self, token: Token) -> bool:
        if self.skipping:
            kind = token.type
            if self.skip_call:  # a broken CALL parameter list: skip to its ")"
                if kind == "_RPAR" or (kind == "SYM_OP" and str(token) == ")"):
                    self.skip_call = False
                if kind not in _SYNC or kind == "TITLE":
                    return True
                self.skip_call = False
            if kind == "_SEMI":
                self.skipping = False
                return True
            if kind != "_NL" and kind not in _SYNC:
                return True
            self.skipping = False
            if self.place(token):
                return True
            return self.syntax_error(token, fed=True)
        try:
            self.state.feed_token(token)
        except UnexpectedToken:
            return self.syntax_error(token)
        if self.quiet and token.type not in ("_NL", "_SEMI"):
            self.quiet = False
        return True

    def syntax_error(self, token: Token, fed: bool = False) -> bool:
        candidates = self.states[self.state.state_stack[-1]]
        expected = {kind for kind in candidates if kind.isupper() and self.acceptable(kind)}
        hint = expected_text(expected)
        hint = f"; expected {hint}" if hint else ""
        if not self.report("STL101", loc(token), found=describe(token), hint=hint):
            return False
        self.recover(token)
        return True

    def recover(self, token: Token | None) -> None:
        self.skip_call = self.filter.depth > 0
        self.filter.depth = 0  # the contextual lexer no longer sees a CALL's parentheses
        self.shift_error(token or self.last)
        self.skipping = True
        if token is not None and (token.type == "_NL" or token.type in _SYNC):
            self.skipping = False
            if not self.place(token):
                self.skipping = token.type != "_NL"

    def finish(self) -> list[Any] | None:
        end = self.synthetic("$END", self.last)
        for _ in range(12):
            try:
                result: list[Any] = self.state.feed_token(end, True)
                return result
            except UnexpectedToken:
                pass
            construct = self.open_construct()
            self.report(
                "STL103",
                loc(self.last) if self.last is not None else ast.Loc(1, 1, 1, 1),
                construct=construct,
                expected=_END_OF.get(construct, "the end of a declaration"),
            )
            self.quiet = True
            self.shift_error(self.last)
            closer = next((kind for kind in _CLOSERS if self.acceptable(kind)), None)
            if closer is not None:
                self.try_feed(self.synthetic(closer, self.last))
        return self.harvest()

    def open_construct(self) -> str:
        for value in reversed(self.state.value_stack):
            if isinstance(value, Token) and value.type in _CODE_BLOCKS | _DATA_BLOCKS:
                return str(value).upper()
        return "the file"

    def harvest(self) -> list[Any]:
        """Whatever complete items sit on the parser's stack when parsing had to stop: the
        blocks already closed, and code outside any block. The code of a block still open
        belongs to that block, whose header is gone: it is dropped, never made loose code
        (which would run as an OB 1 the user did not write)."""
        found: list[Any] = []

        def walk(value: Any) -> None:
            if isinstance(value, Tree):
                for child in value.children:
                    walk(child)
            elif isinstance(value, ast.BlockNode | ast.InstrNode | ast.LabelNode):
                found.append(value)
            elif isinstance(value, list):
                for child in value:
                    walk(child)

        for value in self.state.value_stack:
            if isinstance(value, Token) and value.type in _CODE_BLOCKS | _DATA_BLOCKS:
                break
            walk(value)
        return found


def parse_source(file: str, text: str, lark: Lark | None = None) -> ParseResult:
    """Parses one STL source; never raises for bad input (every problem is a diagnostic).
    ``lark`` replaces the shared parser (tests pass one that records the rules it reduces)."""
    if text.startswith("\ufeff"):
        text = text[1:]
    if is_binary(text):
        empty = ast.SourceNode(file, [], [])
        return ParseResult(empty, [problem("STL105", file, ast.Loc(1, 1, 1, 1), file=file)])
    if not text.endswith("\n"):
        text += "\n"
    gc_was_enabled = gc.isenabled()
    gc.disable()  # the parse allocates many small objects; collection passes make it quadratic
    try:
        driver = _Driver(file, text, lark or parser())
        items = driver.run() or []
    finally:
        if gc_was_enabled:
            gc.enable()
    blocks = [item for item in items if isinstance(item, ast.BlockNode)]
    loose = [item for item in items if not isinstance(item, ast.BlockNode)]
    driver.diagnostics += limit_nesting(file, blocks)  # what the recursive passes cannot take
    result = ParseResult(ast.SourceNode(file, blocks, loose), driver.diagnostics)
    result.comments = line_comments(text)
    return result
