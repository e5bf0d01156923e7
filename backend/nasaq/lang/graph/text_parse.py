"""Reads the ``.graph`` text format (``grammars/graph.lark`` is its reference) into the model.

Recursive descent over the LAD reader's ``Scanner``: the structure (blocks, settings,
sequencers, steps, transitions) is read here, action rows by ``text_actions``, and the LAD
parts by ``nasaq.lang.lad.text_parse.LadReader`` itself: condition bodies with its ``series``,
permanent instructions with its ``network``. While it reads them the scanner's ``host_words``
are the Graph structure words, so a LAD mistake never swallows an ``END_CONDITION`` or the next
``STEP``; LAD mistakes keep their ``LAD1xx`` codes.

Recovery works at the level a student thinks in: a bad action row is reported and dropped,
reading goes on with the next row; a step or transition whose header is broken is reported and
skipped up to its ``END_STEP``/``END_TRANSITION`` (or the next ``STEP``/``TRANSITION``/
``END_SEQUENCER``); a missing end word is reported and the part is kept as read. The block
header and VAR sections are not parsed: their text up to BEGIN is kept verbatim for the STL
compiler, as in a ``.lad`` file (without BEGIN, up to the first SEQUENCER or PERMANENT_ line).

Places (``ParsedGraph.places``): the line of each part's keyword; when two steps (or
transitions) share a number, the first one written keeps the place (the checker reports the
clash). Names are identifiers; the format's own words are refused as names except FROM, TO,
JUMP and STOP, which stand only where no name can (a step may be called ``Stop``).

Speed (a 200-step, 4,000-row FB in a few tens of milliseconds): plain action rows and plain
conditions are read at once by ``text_actions.plain_row`` and ``text_conditions.plain_condition``
(elements numbered as they are built), anything else by the general reading, with the same
result; lines are counted on from the last one asked for (``line_at``), not looked up per part.
"""

from __future__ import annotations

import re

from nasaq.lang.graph.model import (
    Action,
    GraphBlock,
    Sequencer,
    Settings,
    Step,
    Transition,
)
from nasaq.lang.graph.source import ParsedGraph
from nasaq.lang.graph.text_actions import plain_row, read_row
from nasaq.lang.graph.text_conditions import plain_condition
from nasaq.lang.graph.text_words import (
    BODY,
    CONDITION_SYNC,
    HOST_WORDS,
    KEYWORDS,
    NOT_NAMES,
    OUTER,
    PARAMETER_SETS,
    ROW_STOPS,
    SEQUENCER_SYNC,
    SETTING_NAMES,
    STEP_PARTS,
    STEP_SYNC,
    TRANSITION_PARTS,
    TRANSITION_SYNC,
)
from nasaq.lang.lad.model import Network, Series
from nasaq.lang.lad.text_ids import number_series
from nasaq.lang.lad.text_parse import LadReader
from nasaq.lang.lad.text_scan import Pos

_BLOCK_NAME = re.compile(r'FB[ \t]*\d+(?!\w)|"[^"\r\n]*"', re.IGNORECASE)
_NUMBER = re.compile(r"\d+")
_LINKS = re.compile(
    r"[ \t]+FROM[ \t]+([A-Za-z_]\w*)[ \t]+(?:(TO|JUMP)[ \t]+([A-Za-z_]\w*)|STOP)(?!\w)",
    re.IGNORECASE,
)
_HEAD = re.compile(r"[ \t]+([A-Za-z_]\w*)[ \t]*\([ \t]*(\d+)[ \t]*\)")
_BODY_START = re.compile(
    r"^[ \t]*(?=(?:SEQUENCER|PERMANENT_PRE|PERMANENT_POST)(?!\w))", re.IGNORECASE | re.MULTILINE
)
_NEXT_WORD = re.compile(r"\s*([A-Za-z_]\w*)")  # a word after blanks only
_OTHER_BLOCKS = frozenset({"FUNCTION", "ORGANIZATION_BLOCK", "DATA_BLOCK"})


class GraphReader:
    """One reading of one file; ``read`` returns the blocks, diagnostics and places."""

    def __init__(self, text: str, file: str) -> None:
        self.lad = LadReader(text, file)
        self.scan = self.lad.scan
        self.parsed = ParsedGraph(file=file)
        self._word_end = -1  # where the word ``peek`` saw ends
        self._counted = 0  # ``line_at``: the offset whose line is ``_line``
        self._line = 1

    def read(self) -> ParsedGraph:
        scan = self.scan
        while not scan.at_end():
            word = scan.peek_word()
            if word == "FUNCTION_BLOCK":
                places: dict[str, int] = {}
                self.parsed.blocks.append(self.block(places))
                self.parsed.places.append(places)
            elif word in _OTHER_BLOCKS:
                scan.report("GRA102", found=scan.found())
                scan.word()
                scan.skip_to(frozenset({"FUNCTION_BLOCK"}))
            else:
                scan.report("GRA101", found=scan.found())
                scan.skip_to(frozenset({"FUNCTION_BLOCK"}))
        self.parsed.diagnostics = scan.diagnostics
        return self.parsed

    # ---- helpers --------------------------------------------------------------------------
    def lad_network(self, number: int) -> Network | None:
        """A permanent network, read by the LAD reader with the Graph structure words ending
        whatever it reads."""
        self.scan.host_words = HOST_WORDS
        try:
            return self.lad.network(number)
        finally:
            self.scan.host_words = frozenset()
            self.scan.network = None

    def lad_series(self, end: str) -> tuple[Series, dict[str, list[Pos]]]:
        """The elements of a condition up to ``end`` and where each given id was written."""
        lad = self.lad
        self.scan.host_words = HOST_WORDS
        try:
            lad._ids = {}
            return lad.logic(lad.series(frozenset({end})), "GRA116"), lad._ids
        finally:
            self.scan.host_words = frozenset()

    def peek(self) -> str | None:
        """``scan.peek_word()``, in one step when only blanks stand before the word (the usual
        case); ``take`` then consumes it."""
        scan = self.scan
        found = _NEXT_WORD.match(scan.text, scan.pos)
        if found is None:
            self._word_end = -1
            return scan.peek_word()
        scan.pos = found.start(1)
        self._word_end = found.end()
        return found.group(1).upper()

    def take(self) -> None:
        """Consumes the word ``peek`` has just returned."""
        if self._word_end > self.scan.pos:
            self.scan.pos = self._word_end
        else:
            self.scan.word()

    def line(self) -> int:
        self.scan.skip()
        return self.line_at(self.scan.pos)

    def line_at(self, offset: int) -> int:
        """The line of ``offset``, counted from the last offset asked for (reading goes
        forward, so the whole file is counted about once)."""
        text = self.scan.text
        if offset >= self._counted:
            self._line += text.count("\n", self._counted, offset)
        else:
            self._line -= text.count("\n", offset, self._counted)
        self._counted = offset
        return self._line

    def comment_line(self) -> str:
        self.scan.word()
        return self.lad.equals_text()

    def skip_part(self, end: str, stops: frozenset[str]) -> None:
        """Recovery: drops text up to ``end`` (consumed) or a word of ``stops``."""
        self.scan.skip_to(stops | {end})
        if self.scan.peek_word() == end:
            self.scan.word()

    def name(self, keyword: str) -> str | None:
        """A name after ``keyword``; None (reported, nothing consumed) when none comes."""
        scan = self.scan
        word = scan.peek_word()
        if word is None or word in NOT_NAMES:
            scan.report("GRA108", keyword=keyword, found=scan.found())
            return None
        return scan.word()

    # ---- blocks ---------------------------------------------------------------------------
    def block(self, places: dict[str, int]) -> GraphBlock:
        scan = self.scan
        places["BLOCK"] = self.line()
        scan.word()
        scan.skip()
        named = _BLOCK_NAME.match(scan.text, scan.pos)
        name = ""
        if named:
            name = named.group()
            scan.pos = named.end()
        else:
            scan.report("GRA103", found=scan.found())
            scan.skip_line()
        title: str | None = None
        comment: list[str] = []
        settings: Settings | None = None
        start = scan.pos
        while True:
            word = scan.peek_word()
            at = scan.where()
            if word == "TITLE":
                scan.word()
                text = self.lad.equals_text()
                if title is not None:
                    scan.report("GRA130", at, item="TITLE")
                title = text
            elif word == "COMMENT":
                comment.append(self.comment_line())
            elif word == "SETTINGS":
                if settings is not None:
                    scan.report("GRA130", at, item="SETTINGS")
                settings = self.settings(places)
            else:
                break
            start = scan.pos
        declarations = self.lad.declarations(start)
        if scan.peek_word() == "BEGIN":
            scan.word()
        else:
            # Without BEGIN the declarations end where the sequencers start, if they do.
            body = _BODY_START.search(scan.text, start, scan.pos)
            if body:
                declarations = _declarations(scan.text[start : body.start()])
                scan.pos = body.start()
            scan.report("GRA104", found=scan.found())
        pre: list[Network] = []
        post: list[Network] = []
        sequencers: list[Sequencer] = []
        while True:
            word = scan.peek_word()
            at = scan.where()
            if scan.at_end() or word == "FUNCTION_BLOCK":
                scan.report("GRA105", found=scan.found())
                break
            if word == "END_FUNCTION_BLOCK":
                scan.word()
                break
            if word == "PERMANENT_PRE":
                if sequencers or post or pre:
                    scan.report("GRA107", at, section="PERMANENT_PRE")
                self.permanent("PRE", pre, places)
            elif word == "PERMANENT_POST":
                if post:
                    scan.report("GRA107", at, section="PERMANENT_POST")
                self.permanent("POST", post, places)
            elif word == "SEQUENCER":
                if post:
                    scan.report("GRA107", at, section="SEQUENCER")
                sequencers.append(self.sequencer(places))
            else:
                scan.report("GRA106", found=scan.found())
                scan.skip_to(BODY)
        return GraphBlock(
            name=name,
            title=title or "",
            comment="\n".join(comment),
            settings=settings or Settings(),
            declarations=declarations,
            pre=pre,
            sequencers=sequencers,
            post=post,
        )

    def settings(self, places: dict[str, int]) -> Settings:
        scan = self.scan
        places.setdefault("SETTINGS", self.line())
        scan.word()
        values: dict[str, str] = {}
        while True:
            word = scan.peek_word()
            at = scan.where()
            if word == "END_SETTINGS":
                scan.word()
                break
            if word not in SETTING_NAMES:
                if scan.at_end() or word is None or word in KEYWORDS or word.startswith("VAR"):
                    scan.report("GRA111", expected="END_SETTINGS", found=scan.found())
                    break
                scan.report("GRA128", found=scan.found())
                self.skip_row()
                continue
            scan.word()
            value = self.setting_value(word)
            if value is None:
                self.skip_row()
                continue
            if not scan.take(";"):
                scan.report("GRA132", expected="';'", found=scan.found())
            if word in values:
                scan.report("GRA130", at, item=word)
            values[word] = value
        parameters = values.get("PARAMETERS", "STANDARD")
        return Settings(
            parameters="MINIMUM"
            if parameters == "MINIMUM"
            else "MAXIMUM"
            if parameters == "MAXIMUM"
            else "USER_DEFINED"
            if parameters == "USER_DEFINED"
            else "STANDARD",
            skip_steps=values.get("SKIP_STEPS", "FALSE") == "TRUE",
            acknowledge_required=values.get("ACKNOWLEDGE", "TRUE") == "TRUE",
            interlock_blocks=values.get("INTERLOCK_BLOCKS", "FALSE") == "TRUE",
        )

    def setting_value(self, setting: str) -> str | None:
        scan = self.scan
        if not scan.take(":="):
            scan.report("GRA132", expected="':='", found=scan.found())
            return None
        allowed = PARAMETER_SETS if setting == "PARAMETERS" else frozenset({"TRUE", "FALSE"})
        scan.skip()
        at = scan.where()
        value = scan.peek_word()
        if value not in allowed:
            expected = " | ".join(sorted(allowed))
            scan.report("GRA129", at, setting=setting, expected=expected, found=scan.found())
            return None
        scan.word()
        return value

    def skip_row(self) -> None:
        """Recovery in SETTINGS: up to and past the next ';' of this line, else its end."""
        scan = self.scan
        end = scan.text.find("\n", scan.pos)
        end = len(scan.text) if end < 0 else end
        semicolon = scan.text.find(";", scan.pos, end)
        scan.pos = end if semicolon < 0 else semicolon + 1

    def permanent(self, kind: str, networks: list[Network], places: dict[str, int]) -> None:
        """PERMANENT_PRE/POST: LAD networks, read by the LAD reader."""
        scan = self.scan
        scan.word()
        end = f"END_PERMANENT_{kind}"
        while True:
            word = scan.peek_word()
            if word == end:
                scan.word()
                return
            if word == "NETWORK":
                line = self.line()
                network = self.lad_network(len(networks) + 1)
                if network is not None:
                    networks.append(network)
                    places[f"{kind}{len(networks)}"] = line
            elif scan.at_end() or word in BODY:
                scan.report("GRA111", expected=end, found=scan.found())
                return
            else:
                scan.report("GRA131", end=end, found=scan.found())
                scan.skip_to(BODY | {"NETWORK", end})

    # ---- sequencers -----------------------------------------------------------------------
    def sequencer(self, places: dict[str, int]) -> Sequencer:
        scan = self.scan
        line = self.line()
        scan.word()
        name = self.name("SEQUENCER")
        if name is None and scan.peek_word() is None:
            scan.skip_line()  # SEQUENCER 12: the rest of the line was meant as its name
        name = name or ""
        places.setdefault(f"SEQ:{name}", line)
        comment: list[str] = []
        while scan.peek_word() == "COMMENT":
            comment.append(self.comment_line())
        steps: list[Step] = []
        transitions: list[Transition] = []
        while True:
            word = self.peek()
            if word in ("STEP", "INITIAL_STEP"):
                step = self.step(places)
                if step is not None:
                    steps.append(step)
            elif word == "TRANSITION":
                transition = self.transition(places)
                if transition is not None:
                    transitions.append(transition)
            elif word == "END_SEQUENCER":
                self.take()
                break
            elif (word is None and scan.at_end()) or word in OUTER:
                scan.report("GRA111", expected="END_SEQUENCER", found=scan.found())
                break
            else:
                scan.report("GRA112", found=scan.found())
                scan.skip_to(SEQUENCER_SYNC)
        return Sequencer(
            name=name, comment="\n".join(comment), steps=steps, transitions=transitions
        )

    def header(self, keyword: str) -> tuple[str, int] | None:
        """``Name (number)`` after STEP/INITIAL_STEP/TRANSITION; None when broken (reported)."""
        scan = self.scan
        quick = _HEAD.match(scan.text, scan.pos)  # the common, well-formed case in one step
        if quick and quick.group(1).upper() not in NOT_NAMES and int(quick.group(2)) >= 1:
            scan.pos = quick.end()
            return quick.group(1), int(quick.group(2))
        name = self.name(keyword)
        if name is None:
            return None
        example = "1"
        if not scan.take("("):
            scan.report("GRA109", name=name, example=example, found=scan.found())
            return None
        scan.skip()
        at = scan.where()
        digits = _NUMBER.match(scan.text, scan.pos)
        if digits is None:
            scan.report("GRA109", name=name, example=example, found=scan.found())
            return None
        scan.pos = digits.end()
        if not scan.take(")"):
            scan.report("GRA109", name=name, example=example, found=scan.found())
            return None
        number = int(digits.group())
        if number < 1:
            scan.report("GRA110", at, name=name, number=number)
            return None
        return name, number

    def step(self, places: dict[str, int]) -> Step | None:
        scan = self.scan
        line = self.line()
        keyword = scan.word().upper()
        header = self.header(keyword)
        if header is None:
            self.skip_part("END_STEP", SEQUENCER_SYNC)
            return None
        name, number = header
        key = f"S{number}"
        found: dict[str, int] = {key: line}
        comment: list[str] = []
        interlock: Series | None = None
        supervision: Series | None = None
        actions: list[Action] | None = None
        while True:
            word = self.peek()
            if word == "COMMENT":
                comment.append(self.comment_line())
            elif word in ("INTERLOCK", "SUPERVISION"):
                at = scan.pos
                marker = "C" if word == "INTERLOCK" else "V"
                known = interlock if word == "INTERLOCK" else supervision
                if known is not None:
                    scan.report("GRA115", at, part=word, name=name)
                found[f"{key}/{marker}"] = self.line_at(at)
                condition = self.condition(f"END_{word}")
                if word == "INTERLOCK":
                    interlock = condition
                else:
                    supervision = condition
            elif word == "ACTIONS":
                if actions is not None:
                    scan.report("GRA115", part=word, name=name)
                actions = self.actions(name, key, found)
            elif word == "END_STEP":
                self.take()
                break
            elif (word is None and scan.at_end()) or word in SEQUENCER_SYNC:
                scan.report("GRA111", expected="END_STEP", found=scan.found())
                break
            else:
                scan.report("GRA113", name=name, found=scan.found())
                scan.skip_to(STEP_SYNC | STEP_PARTS)
        for place, where in found.items():
            places.setdefault(place, where)
        return Step(
            number=number,
            name=name,
            initial=keyword == "INITIAL_STEP",
            comment="\n".join(comment),
            interlock=interlock,
            supervision=supervision,
            actions=actions or [],
        )

    def transition(self, places: dict[str, int]) -> Transition | None:
        scan = self.scan
        line = self.line()
        scan.word()
        header = self.header("TRANSITION")
        if header is None:
            self.skip_part("END_TRANSITION", SEQUENCER_SYNC)
            return None
        name, number = header
        links = self.links(name)
        if links is None:
            self.skip_part("END_TRANSITION", SEQUENCER_SYNC)
            return None
        source, target, jump = links
        comment: list[str] = []
        condition: Series | None = None
        seen = False
        while True:
            word = self.peek()
            if word == "COMMENT":
                comment.append(self.comment_line())
            elif word == "CONDITION":
                if seen:
                    scan.report("GRA115", part=word, name=name)
                seen = True
                condition = self.condition("END_CONDITION")
            elif word == "END_TRANSITION":
                self.take()
                break
            elif (word is None and scan.at_end()) or word in SEQUENCER_SYNC:
                scan.report("GRA111", expected="END_TRANSITION", found=scan.found())
                break
            else:
                scan.report("GRA114", name=name, found=scan.found())
                scan.skip_to(TRANSITION_SYNC | TRANSITION_PARTS)
        places.setdefault(f"T{number}", line)
        return Transition(
            number=number,
            name=name,
            comment="\n".join(comment),
            source=source,
            target=target,
            jump=jump,
            condition=condition,
        )

    def links(self, name: str) -> tuple[list[str], list[str], bool] | None:
        """``FROM steps (TO steps | JUMP steps | STOP)``; None when broken (reported)."""
        scan = self.scan
        quick = _LINKS.match(scan.text, scan.pos)  # FROM one step TO/JUMP one step, or STOP
        if quick and not {quick.group(1).upper(), (quick.group(3) or "").upper()} & NOT_NAMES:
            scan.pos = quick.end()
            if quick.group(2) is None:
                return [quick.group(1)], [], False
            return [quick.group(1)], [quick.group(3)], quick.group(2).upper() == "JUMP"
        if scan.peek_word() != "FROM":
            scan.report("GRA118", name=name, found=scan.found())
            return None
        scan.word()
        source = self.step_list()
        if source is None:
            return None
        word = scan.peek_word()
        if word == "STOP":
            scan.word()
            return source, [], False
        if word not in ("TO", "JUMP"):
            scan.report("GRA119", name=name, found=scan.found())
            return None
        scan.word()
        target = self.step_list()
        return None if target is None else (source, target, word == "JUMP")

    def step_list(self) -> list[str] | None:
        scan = self.scan
        if not scan.take("("):
            word = scan.peek_word()
            if word is None or word in NOT_NAMES:
                scan.report("GRA120", found=scan.found())
                return None
            return [scan.word()]
        names: list[str] = []
        while True:
            word = scan.peek_word()
            if word is None or word in NOT_NAMES:
                scan.report("GRA120", found=scan.found())
                return None
            names.append(scan.word())
            if scan.take(")"):
                return names
            if not scan.take(","):
                scan.report("GRA132", expected="',' or ')'", found=scan.found())
                return None

    # ---- conditions -----------------------------------------------------------------------
    def condition(self, end: str) -> Series:
        """``CONDITION``/``INTERLOCK``/``SUPERVISION`` elements ``END_...``: LAD logic read
        by the LAD reader, elements numbered e1, e2 ... as in a network."""
        scan = self.scan
        scan.word()
        quick = plain_condition(scan.text, scan.pos, end)
        if quick is not None:  # the common case, read at once (same result, no problem)
            named, scan.pos = quick
            return named
        at = scan.where()
        logic, given = self.lad_series(end)
        named, duplicates = number_series(logic)
        for duplicate in dict.fromkeys(duplicates):
            scan.report("GRA117", given.get(duplicate, [at])[-1], id=duplicate)
        if scan.peek_word() == end:
            scan.word()
        else:
            scan.report("GRA111", expected=end, found=scan.found())
            scan.skip_to(CONDITION_SYNC | {end})
            if scan.peek_word() == end:
                scan.word()
        return named

    # ---- actions --------------------------------------------------------------------------
    def actions(self, step: str, key: str, found: dict[str, int]) -> list[Action]:
        """``ACTIONS`` rows ``END_ACTIONS``; rows without an id are a1, a2 ... in order."""
        scan = self.scan
        scan.word()
        text = scan.text
        actions: list[Action] = []
        starts: list[int] = []
        given = False  # a row with an @id: the ids may clash
        while True:
            plain = plain_row(text, scan.pos, len(actions) + 1)  # the common case, at once
            if plain is not None:
                action, at, scan.pos = plain
            else:
                word = self.peek()
                if word == "END_ACTIONS":
                    self.take()
                    break
                if (word is None and scan.at_end()) or word in ROW_STOPS:
                    scan.report("GRA111", expected="END_ACTIONS", found=scan.found())
                    break
                at = scan.pos
                row = read_row(scan)
                if row is None:
                    continue
                action = row.action(len(actions) + 1)
                given = given or bool(row.id)
            actions.append(action)
            starts.append(at)
            found[f"{key}/A{len(actions)}"] = self.line_at(at)
        if given:
            seen: set[str] = set()
            for action, at in zip(actions, starts, strict=True):
                if action.id in seen:
                    scan.report("GRA126", at, id=action.id, name=step)
                seen.add(action.id)
        return actions


def _declarations(text: str) -> str:
    """Declaration text as ``LadReader.declarations`` keeps it: no leading blank lines, no
    trailing blanks."""
    lines = text.split("\n")
    while lines and not lines[0].strip():
        lines.pop(0)
    return "\n".join(lines).rstrip()
