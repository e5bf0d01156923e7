"""Reads the LAD/FBD text format (``grammars/lad.lark`` is its reference) into the model.

Recursive descent over ``text_scan.Scanner``, so that recovery can work at the level a
student thinks in: a bad element is reported once and dropped, and reading goes on with the
next element; a network whose rung cannot be built is dropped with one message and reading
goes on with the next NETWORK; junk between blocks is skipped up to the next block keyword.
The block header and VAR sections are not parsed: their text up to BEGIN is kept verbatim
for the STL compiler, which declares the interface.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import TypeVar, get_args

from pydantic import BaseModel

from nasaq.lang.lad.model import (
    Box,
    Coil,
    CoilKind,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    LadBlock,
    Midline,
    Network,
    OpenDb,
    Output,
    Parallel,
    Return,
    Series,
    StatusBit,
    StatusContact,
)
from nasaq.lang.lad.text_ids import number_elements
from nasaq.lang.lad.text_scan import Pos, Scanner
from nasaq.lang.limits import MAX_LAD_NESTING

BLOCK_KINDS = {"ORGANIZATION_BLOCK": "OB", "FUNCTION_BLOCK": "FB", "FUNCTION": "FC"}
BLOCK_ENDS = {f"END_{word}": word for word in BLOCK_KINDS}
_BLOCK_WORDS = frozenset(BLOCK_KINDS) | frozenset(BLOCK_ENDS)
ELEMENTS = frozenset(
    {"CONTACT", "CONTACTNC", "STATUS", "STATUSNC", "NOT", "EDGE", "MIDLINE", "BOX", "PARALLEL"}
)
# The final elements and the coil each one writes (None: not a coil).
FINALS: dict[str, CoilKind | None] = {
    "COIL": "=",
    "SETCOIL": "S",
    "RESETCOIL": "R",
    "SP": "SP",
    "SE": "SE",
    "SD": "SD",
    "SS": "SS",
    "SF": "SF",
    "CU": "CU",
    "CD": "CD",
    "SC": "SC",
    "SAVE": "SAVE",
    "JUMP": None,
    "JUMPN": None,
    "RETURN": None,
    "OPEN": None,
}
_WITH_VALUE = frozenset({"SP", "SE", "SD", "SS", "SF", "SC"})
_NO_ARGUMENTS = frozenset({"NOT", "SAVE", "RETURN"})
STRUCTURE = _BLOCK_WORDS | {
    "BEGIN",
    "NETWORK",
    "RUNG",
    "END_RUNG",
    "OUTPUTS",
    "END_OUTPUTS",
    "BRANCH",
    "END_BRANCH",
    "END_PARALLEL",
}
_SYNC = STRUCTURE | ELEMENTS | frozenset(FINALS)
_NETWORK_SYNC = frozenset({"NETWORK"}) | _BLOCK_WORDS
_END_STL = re.compile(r"^[ \t]*END_STL\b", re.IGNORECASE | re.MULTILINE)
_AFTER_STL = re.compile(
    r"^[ \t]*(?:NETWORK|END_ORGANIZATION_BLOCK|END_FUNCTION_BLOCK|END_FUNCTION)\b",
    re.IGNORECASE | re.MULTILINE,
)
_REASON = re.compile(r"[ \t]+REASON[ \t]+([A-Za-z_]\w*)", re.IGNORECASE)
_STATUS_BITS = frozenset(get_args(StatusBit))
_NAME = re.compile(r"[A-Za-z_]\w*\Z")
_ID = re.compile(r"@[A-Za-z_]\w*")
_BAD_ID = re.compile(r"@[^\s,()]*")
_BLOCK_NAME = re.compile(r'(?:(OB|FB|FC)[ \t]*\d+(?!\w))|"[^"\r\n]*"', re.IGNORECASE)
_TYPE_TEXT = re.compile(r"[^\s/(]+(?:[ \t]+[^\s/(]+)*")
_DECL_TOKEN = re.compile(
    r"//[^\n]*|\(\*[\s\S]*?(?:\*\)|\Z)|\"[^\"\n]*\"?|'[^'\n]*'?|[A-Za-z_]\w*|[\s\S]"
)
_DECL_STOPS = _BLOCK_WORDS | {"BEGIN", "NETWORK"}


_Node = TypeVar("_Node", bound=BaseModel)


@dataclass(frozen=True, slots=True)
class _Item:
    """An element or final element as read, with where it starts and its name as written."""

    node: Element | Final
    at: Pos
    name: str

    @property
    def is_final(self) -> bool:
        """A coil, jump, RET, OPN or box: what may end a rung (a box may also stand in it)."""
        return isinstance(self.node, (Coil, Jump, Return, OpenDb, Box))


class LadReader:
    """One reading of one file; ``blocks`` and the scanner's ``diagnostics`` are the result."""

    def __init__(self, text: str, file: str) -> None:
        self.scan = Scanner(text, file)
        self.default_language = "FBD" if file.lower().endswith(".fbd") else "LAD"
        self.blocks: list[LadBlock] = []
        self._ids: dict[str, list[Pos]] = {}
        self._depth = 0  # series being read inside each other (parallels, logic pins)
        self._silenced = False  # LAD150 silenced the scanner until the network ends

    def read(self) -> list[LadBlock]:
        scan = self.scan
        while not scan.at_end():
            if scan.peek_word() in BLOCK_KINDS:
                block = self.block()
                if block is not None:
                    self.blocks.append(block)
            else:
                scan.report("LAD101", found=scan.found())
                scan.skip_to(frozenset(BLOCK_KINDS))
        return self.blocks

    # ---- blocks ---------------------------------------------------------------------------
    def block(self) -> LadBlock | None:
        scan = self.scan
        opener = scan.word().upper()
        kind = BLOCK_KINDS[opener]
        scan.skip()
        named = _BLOCK_NAME.match(scan.text, scan.pos)
        name = ""
        return_type: str | None = None
        if named and (named.group(1) is None or named.group(1).upper() == kind):
            name = named.group()
            scan.pos = named.end()
            return_type = self.return_type(kind)
        else:
            scan.report("LAD102", found=scan.found())
            scan.skip_line()
        title, language, declarations = self.header()
        networks: list[Network] = []
        number = 0
        while True:
            word = scan.peek_word()
            if scan.at_end():
                scan.report("LAD106", expected=f"END_{opener}", found=scan.found())
                break
            if word == "NETWORK":
                number += 1
                network = self.network(number)
                scan.network = None  # later problems belong to the block
                if network is not None:
                    networks.append(network)
            elif word in BLOCK_ENDS or word in BLOCK_KINDS:
                if word != f"END_{opener}":
                    scan.report("LAD106", expected=f"END_{opener}", found=scan.found())
                if word in BLOCK_ENDS:
                    scan.word()
                break
            else:
                scan.report("LAD107", found=scan.found())
                scan.skip_to(_NETWORK_SYNC)
        scan.network = None
        if not name:
            return None
        return LadBlock(
            language="FBD" if language == "FBD" else "LAD",
            kind="OB" if kind == "OB" else "FB" if kind == "FB" else "FC",
            name=name,
            return_type=return_type,
            title=title,
            declarations=declarations,
            networks=networks,
        )

    def return_type(self, kind: str) -> str | None:
        scan = self.scan
        if not scan.take(":"):
            if kind == "FC":
                scan.report("LAD103")
            return None
        scan.skip()
        found = _TYPE_TEXT.match(scan.text, scan.pos)
        if found is None:
            scan.report("LAD103")
            return None
        scan.pos = found.end()
        return found.group()

    def header(self) -> tuple[str, str, str]:
        """TITLE and LANGUAGE lines, then the declaration text up to BEGIN."""
        scan = self.scan
        title: str | None = None
        language: str | None = None
        start = scan.pos
        while True:
            word = scan.peek_word()
            if word == "TITLE":
                at = scan.where()
                scan.word()
                text = self.equals_text()
                if title is not None:
                    scan.report("LAD125", at, item="TITLE")
                title = text
            elif word == "LANGUAGE":
                at = scan.where()
                scan.word()
                chosen = (scan.peek_word() or "").upper()
                if chosen in ("LAD", "FBD"):
                    scan.word()
                else:
                    scan.report("LAD104", found=scan.found())
                    scan.skip_line()
                if language is not None:
                    scan.report("LAD125", at, item="LANGUAGE")
                language = chosen if chosen in ("LAD", "FBD") else language
            else:
                break
            start = scan.pos
        declarations = self.declarations(start)
        if scan.peek_word() == "BEGIN":
            scan.word()
        else:
            scan.report("LAD105", found=scan.found())
        return title or "", language or self.default_language, declarations

    def declarations(self, start: int) -> str:
        scan = self.scan
        text = scan.text
        pos = start
        while pos < len(text):
            token = _DECL_TOKEN.match(text, pos)
            assert token is not None  # the last alternative matches any character
            if token.group().upper() in _DECL_STOPS:
                break
            pos = token.end()
        scan.pos = pos
        lines = text[start:pos].split("\n")
        while lines and not lines[0].strip():
            lines.pop(0)
        return "\n".join(lines).rstrip()

    def equals_text(self) -> str:
        scan = self.scan
        if not scan.take("="):
            scan.report("LAD111", expected="'='", found=scan.found())
            scan.skip_line()
            return ""
        return scan.line_text()

    # ---- networks -------------------------------------------------------------------------
    def network(self, number: int) -> Network | None:
        scan = self.scan
        scan.network = number
        self._ids = {}
        at = scan.where()
        scan.word()
        title: str | None = None
        label: str | None = None
        comment: list[str] = []
        while True:
            word = scan.peek_word()
            where = scan.where()
            if word == "TITLE":
                scan.word()
                text = self.equals_text()
                if title is not None:
                    scan.report("LAD125", where, item="TITLE")
                title = text
            elif word == "COMMENT":
                scan.word()
                comment.append(self.equals_text())
            elif word == "LABEL":
                scan.word()
                found = scan.peek_word()
                if found is None or found in STRUCTURE:
                    scan.report("LAD124", found=scan.found())
                    scan.skip_line()
                    continue
                written = scan.word()
                if label is not None:
                    scan.report("LAD125", where, item="LABEL")
                label = written
            else:
                break
        if scan.peek_word() == "STL":
            return self.stl_network(title or "", "\n".join(comment), label)
        if scan.peek_word() != "RUNG":
            scan.report("LAD108", found=scan.found())
            scan.skip_to(_NETWORK_SYNC)
            return None
        rung = self.rung()
        if self._silenced:
            self._silenced = False
            scan.truncated = False
            return None
        if rung is None:
            return None
        logic, outputs = rung
        network = Network(
            title=title or "", comment="\n".join(comment), label=label, logic=logic, outputs=outputs
        )
        named, duplicates = number_elements(network)
        for duplicate in dict.fromkeys(duplicates):
            places = self._ids.get(duplicate, [at])
            scan.report("LAD123", places[-1], id=duplicate)
        return named

    def stl_network(self, title: str, comment: str, label: str | None) -> Network | None:
        """``STL [REASON LAD3xx]`` then the network's STL lines as written, up to ``END_STL``:
        a network that has no LAD shape stays STL."""
        scan = self.scan
        at = scan.where()
        scan.word()
        # REASON only on the STL line itself: the next line is the network's first STL line.
        given = _REASON.match(scan.text, scan.pos)
        reason = given.group(1) if given else None
        scan.skip_line()
        text = scan.text
        start = scan.pos + 1 if scan.pos < len(text) else scan.pos
        end = _END_STL.search(text, start)
        stop = _AFTER_STL.search(text, start)
        if end is None or (stop is not None and stop.start() < end.start()):
            # Recovery: the lines up to the next network or the block's end were the network.
            scan.report("LAD129", at, construct="STL ... END_STL")
            scan.pos = stop.start() if stop is not None else len(text)
            return None
        body = text[start : end.start()].rstrip("\n")
        scan.pos = end.end()
        return Network(title=title, comment=comment, label=label, stl=body, stl_reason=reason)

    def rung(self) -> tuple[Series, list[Output]] | None:
        """RUNG ... END_RUNG; None (reported) when it is broken. A rung whose items do not end
        in a final element is being drawn: all of them are logic and it has no outputs yet."""
        scan = self.scan
        scan.word()
        items = self.series(frozenset({"OUTPUTS", "END_RUNG"}))
        outputs: list[Output] | None = []
        if scan.peek_word() == "OUTPUTS":
            logic = self.logic(items, "LAD118")
            outputs = self.outputs()
        elif items and items[-1].is_final:
            logic = self.logic(items[:-1], "LAD118")
            outputs = [Output(target=_final(items[-1].node))]
        else:
            logic = self.logic(items, "LAD118")
        if scan.peek_word() != "END_RUNG":
            if scan.at_end():
                scan.report("LAD129", construct="a rung")
            else:
                scan.report("LAD109", found=scan.found())
                scan.skip_to(_NETWORK_SYNC)
            return None
        scan.word()
        return None if outputs is None else (logic, outputs)

    def outputs(self) -> list[Output] | None:
        scan = self.scan
        scan.word()
        outputs: list[Output] = []
        failed = False
        while True:
            word = scan.peek_word()
            if word == "BRANCH":
                where = scan.where()
                scan.word()
                reported = len(scan.diagnostics)
                items = self.series(frozenset({"END_BRANCH"}))
                if items and items[-1].is_final:
                    conditions = self.logic(items[:-1], "LAD118")
                    outputs.append(Output(conditions=conditions, target=_final(items[-1].node)))
                else:
                    failed = True
                    if len(scan.diagnostics) == reported:  # else a dropped element
                        scan.report("LAD121", where)
                self.expect_end("END_BRANCH")
            elif word == "END_OUTPUTS":
                scan.word()
                break
            else:
                scan.report("LAD117", end="END_OUTPUTS", found=scan.found())
                failed = True
                if (
                    scan.at_end()
                    or word in _NETWORK_SYNC
                    or word == "END_RUNG"
                    or word in scan.host_words
                ):
                    break
                scan.skip_to(frozenset({"BRANCH", "END_OUTPUTS", "END_RUNG"}) | _NETWORK_SYNC)
        return None if failed else outputs  # no branch yet: a rung being drawn

    def expect_end(self, word: str) -> None:
        if self.scan.peek_word() == word:
            self.scan.word()
        else:
            self.scan.report("LAD111", expected=word, found=self.scan.found())

    def logic(self, items: list[_Item], code: str) -> Series:
        """The items as a series of logic elements; a final element among them is reported
        (``code``) and left out."""
        elements: list[Element] = []
        for item in items:
            node = item.node
            if isinstance(
                node, (Contact, StatusContact, Invert, EdgeContact, Midline, Box, Parallel)
            ):
                elements.append(node)
            else:
                self.scan.report(code, item.at, element=item.name)
        return Series(elements=elements)

    # ---- elements -------------------------------------------------------------------------
    def series(self, stops: frozenset[str], in_pin: bool = False) -> list[_Item]:
        """Elements up to a word in ``stops`` or any other structural word (in a box pin also
        up to the ``,`` or ``)`` that ends the pin)."""
        items: list[_Item] = []
        if self._depth >= MAX_LAD_NESTING:
            self.too_deep()
            return items
        self._depth += 1
        try:
            self._series(stops, in_pin, items)
        finally:
            self._depth -= 1
        return items

    def too_deep(self) -> None:
        """LAD150 where parallels and logic pins nest past ``MAX_LAD_NESTING``: the rest of
        the network is skipped, and the levels still open report nothing more about it."""
        scan = self.scan
        scan.report("LAD150", limit=MAX_LAD_NESTING)
        was = scan.truncated
        scan.truncated = True
        scan.skip_to(_NETWORK_SYNC)
        self._silenced = self._silenced or not was

    def _series(self, stops: frozenset[str], in_pin: bool, items: list[_Item]) -> None:
        scan = self.scan
        while not scan.at_end():
            word = scan.peek_word()
            if word in stops or word in STRUCTURE or word in scan.host_words:
                break
            if in_pin and (scan.looking_at(",") or scan.looking_at(")")):
                break
            at = scan.where()
            if word not in ELEMENTS and word not in FINALS:
                scan.report("LAD110", found=scan.found())
                scan.skip_to(_SYNC)
                continue
            name = scan.word()
            node = self.element(name.upper(), name, at)
            if node is not None:
                items.append(_Item(node, at, name))

    def element(self, word: str, name: str, at: Pos) -> Element | Final | None:
        scan = self.scan
        if word == "PARALLEL":
            return self.parallel(at)
        if word == "BOX":
            return self.box(name)
        if word in _NO_ARGUMENTS:
            if scan.looking_at("("):
                given = self.arguments(name)
                if given is not None:
                    scan.report("LAD112", at, element=name, expected="0", count=len(given))
                return None
            node: Element | Final = (
                Invert() if word == "NOT" else Return() if word == "RETURN" else Coil(coil="SAVE")
            )
            return self.with_id(node)
        arguments = self.arguments(name)
        if arguments is None:
            return None
        built = self.build(word, name, at, arguments)
        return None if built is None else self.with_id(built)

    def build(
        self, word: str, name: str, at: Pos, arguments: list[tuple[str, Pos]]
    ) -> Element | Final | None:
        scan = self.scan
        texts = [text for text, _ in arguments]
        wanted = (1, 2) if word in _WITH_VALUE else (2,) if word == "EDGE" else (1,)
        if len(texts) not in wanted:
            expected = " or ".join(str(count) for count in wanted)
            scan.report("LAD112", at, element=name, expected=expected, count=len(texts))
            return None
        for text, where in arguments:
            if not text:
                scan.report("LAD113", where, element=name)
                return None
        first = texts[0]
        if word in ("CONTACT", "CONTACTNC"):
            return Contact(operand=first, negated=word == "CONTACTNC")
        if word in ("STATUS", "STATUSNC"):
            bit = first.upper()
            if bit not in _STATUS_BITS:
                scan.report("LAD114", arguments[0][1], found=first)
                return None
            return StatusContact(bit=bit, negated=word == "STATUSNC")
        if word == "EDGE":
            edge = first.upper()
            if edge not in ("P", "N"):
                scan.report("LAD115", arguments[0][1], found=first)
                return None
            return EdgeContact(edge="P" if edge == "P" else "N", memory=texts[1])
        if word == "MIDLINE":
            return Midline(operand=first)
        if word in ("JUMP", "JUMPN"):
            if not _NAME.match(first):
                scan.report("LAD124", arguments[0][1], found=first)
                return None
            return Jump(label=first, negated=word == "JUMPN")
        if word == "OPEN":
            return OpenDb(block=first)
        coil = FINALS[word]
        assert coil is not None
        return Coil(coil=coil, operand=first, value=texts[1] if len(texts) > 1 else None)

    def arguments(self, name: str) -> list[tuple[str, Pos]] | None:
        """``( operand , ... )``: the operands as written with where each starts; None when
        the list is broken (reported, skipped)."""
        scan = self.scan
        if not scan.take("("):
            scan.report("LAD111", expected="'('", found=scan.found())
            scan.skip_to(_SYNC)
            return None
        found: list[tuple[str, Pos]] = []
        reported = len(scan.diagnostics)
        while True:
            scan.skip()
            where = scan.where()
            found.append((scan.operand(_SYNC), where))
            broken = len(scan.diagnostics) > reported  # an unclosed quote, reported
            if scan.take(","):
                continue
            if scan.take(")") and not broken:
                break
            if not broken:
                scan.report("LAD111", expected="',' or ')'", found=scan.found())
                scan.skip_to(_SYNC)
            return None
        return [] if found == [("", found[0][1])] else found

    def with_id(self, node: _Node) -> _Node:
        element_id = self.given_id()
        return node.model_copy(update={"id": element_id}) if element_id else node

    def given_id(self) -> str:
        """An ``@name`` after an element (empty when there is none or it is malformed)."""
        scan = self.scan
        if not scan.looking_at("@"):
            return ""
        where = scan.where()
        given = _ID.match(scan.text, scan.pos)
        if given is None:
            bad = _BAD_ID.match(scan.text, scan.pos)
            assert bad is not None
            scan.report("LAD128", found=bad.group())
            scan.pos = bad.end()
            return ""
        scan.pos = given.end()
        element_id = given.group()[1:]
        self._ids.setdefault(element_id, []).append(where)
        return element_id

    def parallel(self, at: Pos) -> Parallel | None:
        scan = self.scan
        element_id = self.given_id()
        branches: list[Series] = []
        while True:
            word = scan.peek_word()
            if word == "BRANCH":
                scan.word()
                items = self.series(frozenset({"END_BRANCH"}))
                self.expect_end("END_BRANCH")
                branches.append(self.logic(items, "LAD119"))
            elif word == "END_PARALLEL":
                scan.word()
                break
            else:
                scan.report("LAD117", end="END_PARALLEL", found=scan.found())
                scan.skip_to(frozenset({"END_PARALLEL", "END_RUNG", "OUTPUTS"}) | _NETWORK_SYNC)
                if scan.peek_word() == "END_PARALLEL":
                    scan.word()
                return None
        if len(branches) < 2:
            scan.report("LAD116", at)
            return None
        return Parallel(id=element_id, branches=branches)

    def box(self, name: str) -> Box | None:
        scan = self.scan
        if not scan.take("("):
            scan.report("LAD111", expected="'('", found=scan.found())
            scan.skip_to(_SYNC)
            return None
        where = scan.where()
        box_name = scan.operand(_SYNC)
        if not box_name:
            scan.report("LAD113", where, element=name)
            scan.skip_to(_SYNC)
            return None
        instance: str | None = None
        inputs: dict[str, str | Series] = {}
        outputs: dict[str, str] = {}
        reported = len(scan.diagnostics)
        while scan.take(","):
            scan.skip()
            where = scan.where()
            pin = self.pin(name, box_name)
            if pin is None:
                scan.skip_to(_SYNC)
                return None
            key, value, is_input = pin
            if key is None:
                instance = str(value)
            elif key in inputs or key in outputs:
                scan.report("LAD122", where, pin=key, box=box_name)
            elif is_input:
                inputs[key] = value
            else:
                outputs[key] = str(value)
        if not scan.take(")"):
            scan.report("LAD111", expected="',' or ')'", found=scan.found())
            scan.skip_to(_SYNC)
            return None
        if len(scan.diagnostics) > reported:  # a broken pin or an element in a pin's logic
            return None
        return self.with_id(Box(name=box_name, instance=instance, inputs=inputs, outputs=outputs))

    def pin(self, name: str, box_name: str) -> tuple[str | None, str | Series, bool] | None:
        """One ``PIN := value``, ``PIN := RUNG ... END_RUNG``, ``PIN => operand`` or
        ``INSTANCE db`` (key None); None when broken (reported)."""
        scan = self.scan
        if scan.peek_word() is None:
            scan.report("LAD111", expected="a pin name", found=scan.found())
            return None
        key = scan.word()
        if key.upper() == "INSTANCE" and not (scan.looking_at(":=") or scan.looking_at("=>")):
            scan.skip()
            where = scan.where()
            value = scan.operand(_SYNC)
            if not value:
                scan.report("LAD113", where, element=name)
                return None
            return None, value, True
        is_input = scan.take(":=")
        if not is_input and not scan.take("=>"):
            scan.report("LAD111", expected="':=' or '=>'", found=scan.found())
            return None
        if is_input and scan.peek_word() == "RUNG":
            scan.word()
            items = self.series(frozenset({"END_RUNG"}), in_pin=True)
            if scan.peek_word() != "END_RUNG":
                scan.report("LAD109", found=scan.found())
                return None
            scan.word()
            return key, self.logic(items, "LAD119"), True
        scan.skip()
        where = scan.where()
        value = scan.operand(_SYNC)
        if not value:
            scan.report("LAD113", where, element=f"{box_name}.{key}")
            return None
        return key, value, is_input


def _final(node: Element | Final) -> Final:
    assert isinstance(node, (Coil, Jump, Return, OpenDb, Box))
    return node
