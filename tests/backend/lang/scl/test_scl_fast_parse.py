"""The fast parse (``nasaq.lang.scl.lalr`` with its lexer) gives exactly what the recovering
driver gives: the same AST, positions included, for every SCL source of the repository (the
scenario sources, the grammar corpus, the programs of the SCL tests, the bench sources) and for
sources made slightly wrong at random; a source with a mistake goes to the driver, so its
diagnostics are the driver's. The fast path must really be taken for the valid ones."""

from __future__ import annotations

import ast as python_ast
import dataclasses
import random
from pathlib import Path
from typing import Any

import pytest

from nasaq.lang.scl import lalr
from nasaq.lang.scl.bench import dense, program
from nasaq.lang.scl.grammar import build_parser, parser
from nasaq.lang.scl.lexer import Words
from nasaq.lang.scl.parse import _RESERVED, parse_source

HERE = Path(__file__).parent
REPOSITORY = HERE.parents[3]
SCENARIOS = REPOSITORY / "tests" / "scenarios" / "scl"


def dump(value: Any) -> Any:
    """A node as nested tuples, with what ``==`` leaves out (``loc``, a block's ``end``)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        fields = dataclasses.fields(value)
        return (type(value).__name__, *((f.name, dump(getattr(value, f.name))) for f in fields))
    if isinstance(value, list | tuple):
        return (type(value).__name__, *(dump(item) for item in value))
    if isinstance(value, dict):
        return tuple(sorted((key, dump(item)) for key, item in value.items()))
    return (type(value).__name__, value)


def _test_programs() -> list[str]:
    """The SCL sources written as string literals in the SCL tests."""
    found: list[str] = []
    for path in sorted(HERE.glob("test_scl_*.py")):
        tree = python_ast.parse(path.read_text("utf-8"))
        for node in python_ast.walk(tree):
            text = node.value if isinstance(node, python_ast.Constant) else None
            if isinstance(text, str) and "END_" in text and "\n" in text:
                found.append(text)
    return found


SOURCES = {
    **{path.name: path.read_text("utf-8") for path in sorted(SCENARIOS.glob("*.scl"))},
    **{path.name: path.read_text("utf-8") for path in sorted((HERE / "corpus").glob("*.scl"))},
    **{f"program {number}": text for number, text in enumerate(_test_programs())},
    "bench.scl": program(400),
    "dense.scl": dense(40),
}


def assert_same(name: str, text: str) -> bool:
    """Both parses agree; True where the source is valid (and the fast path took it)."""
    fast = parse_source(name, text)
    driver = parse_source(name, text, fast=False)
    assert dump(fast.source) == dump(driver.source), name
    assert [str(item) for item in fast.diagnostics] == [str(item) for item in driver.diagnostics]
    if driver.diagnostics:
        return False
    assert lalr.parse(text.removeprefix("\ufeff"), parser(), _RESERVED) is not None, name
    return True


def test_the_repository_sources_parse_the_same_on_both_paths() -> None:
    assert len(SOURCES) > 150
    valid = [name for name, text in SOURCES.items() if assert_same(name, text)]
    assert len(valid) > 100  # most are valid: the fast path is what parses them


EDGES = [
    "FUNCTION FC1 : VOID\r\nBEGIN\r\n  x := 1;\r\nEND_FUNCTION\r\n",  # CRLF
    "FUNCTION FC1 : VOID\n\tVAR_TEMP\tx :\tINT;\tEND_VAR\nBEGIN\n\tx:=1;END_FUNCTION",  # no EOL
    "(* a *) // b\n/* c\n d */ FUNCTION FC1 : VOID BEGIN x := 1; (* e *) END_FUNCTION // f",
    "FUNCTION_BLOCK FB1\nTITLE =   'Motor' \nAUTHOR :   me\nVERSION : '0.1'\nNAME : x\n"
    "KNOW_HOW_PROTECT\nEND_FUNCTION_BLOCK\n",  # header values keep their leading blanks
    "FUNCTION FC1 : VOID\nBEGIN\nREGION  Startup (* x *)\n  x := 1;\nEND_REGION\nEND_FUNCTION\n",
    "function fc1 : void\nbegin\n  If a Then b := 1; ElsIf c then b := 2; end_if;\nend_function\n",
    "FUNCTION FC1 : VOID\nBEGIN\n  \"Größe\".Wert := 'ä$''; größe := 1;\nEND_FUNCTION\n",
    "FUNCTION FC1 : VOID\nBEGIN\n  x\u00a0:= 1;\u2028y := ſ;\nEND_FUNCTION\n",  # wide blanks
    "FUNCTION FC1 : VOID\nBEGIN\n  M 1.1 := I1.0; MW[i] := DB10.DW[i]; %QX2.3 := db1.dbx0.0;\n"
    "  t := T#2s + TIME#-1d2h; w := W#16#FF + 2#1010 + INT#-5; r := 1.5e3 + 2E-1;\nEND_FUNCTION\n",
    "DATA_BLOCK DB1\nSTRUCT a : ARRAY[1..2, 3..4] OF INT := 2(1), [3, 4]; END_STRUCT\nBEGIN\n"
    "a[1, 3] := 5;\nEND_DATA_BLOCK\n",
    "FUNCTION FC1 : VOID\nVAR_INPUT CONSTANT\n  c {S7_visible := 'false'} : INT;\nEND_VAR\n"
    "CONST k := 5; END_CONST LABEL l1, l2; END_LABEL\nBEGIN\nl1: GOTO l2; l2: ;\nEND_FUNCTION\n",
    "{ SCL_CreateDebugInfo := 'y'; S7_Optimized := 'n' }\nTYPE UDT1 STRUCT x : BOOL; END_STRUCT"
    " END_TYPE\n",
    "\ufeffFUNCTION FC1 : VOID\nBEGIN\nEND_FUNCTION\n",
]


@pytest.mark.parametrize("text", EDGES)
def test_lexical_corners_parse_the_same_on_both_paths(text: str) -> None:
    assert assert_same("edge.scl", text)


PIECES = [
    *[" ", "\t", "\n", "\r\n", "\u00a0", ";", ":", ":=", "=>", ",", ".", "..", "(", ")"],
    *["[", "]", "{", "}", "(*", "*)", "/*", "*/", "//", "'", '"', "#", "%", "$", "@", "&"],
    *["x", "IF", "end_if", "THEN", "VAR", "BEGIN", "M", "MW", "10", "16#F", "T#2s", "ä", "ſ"],
    *["REGION", "TITLE", "=", "NAME", "VERSION :", "KNOW_HOW_PROTECT", "VAR CONSTANT", "I 1.1"],
]


def _mutate(text: str, rng: random.Random) -> str:
    for _ in range(rng.randint(1, 3)):
        at = rng.randrange(len(text) + 1)
        choice = rng.random()
        if choice < 0.5:
            text = text[:at] + rng.choice(PIECES) + text[at:]
        elif choice < 0.8:
            text = text[:at] + text[at + rng.randint(1, 5) :]
        else:
            text = text[:at] + text[at : at + 20].swapcase() + text[at + 20 :]
    return text


def test_sources_made_wrong_at_random_parse_the_same_on_both_paths() -> None:
    """Where the fast parse accepts a source, so does the driver, with the same tree."""
    rng = random.Random(4)
    texts = [SOURCES[name] for name in sorted(SOURCES) if name.endswith(".scl")]
    valid = sum(assert_same("mutant.scl", _mutate(rng.choice(texts), rng)) for _ in range(250))
    assert valid > 50


def test_a_parser_with_recording_callbacks_takes_the_driver() -> None:
    """The grammar-coverage test wraps Lark's callbacks: the fast path must not bypass them."""
    lark = build_parser()
    lark._callbacks.update({rule: (lambda children: children) for rule in lark._callbacks})
    assert lalr.parse("FUNCTION FC1 : VOID\nBEGIN\nEND_FUNCTION\n", lark, _RESERVED) is None
    assert lalr.parse("FUNCTION FC1 : VOID\nBEGIN\nEND_FUNCTION\n", parser(), _RESERVED)


ERRORS_AFTER_ONE_TOKEN = [
    # a name, a number or a symbol made into its node at once (its state reduces it whatever
    # follows), then a token no state accepts: the error is still found, by the driver
    "FUNCTION FC1 : VOID\nBEGIN\n  x := a b;\nEND_FUNCTION\n",
    "FUNCTION FC1 : VOID\nBEGIN\n  x := 1 2;\nEND_FUNCTION\n",
    'FUNCTION FC1 : VOID\nBEGIN\n  x := "S" #y;\nEND_FUNCTION\n',
    "FUNCTION FC1 : VOID\nBEGIN\n  IF a b THEN x := TRUE; END_IF;\nEND_FUNCTION\n",
    "FUNCTION FC1 : VOID\nBEGIN\n  x := M1.0 IF;\nEND_FUNCTION\n",
]


@pytest.mark.parametrize("text", ERRORS_AFTER_ONE_TOKEN)
def test_an_error_after_a_node_made_at_its_token_goes_to_the_driver(text: str) -> None:
    assert lalr.parse(text, parser(), _RESERVED) is None
    assert not assert_same("error.scl", text)


def test_names_past_the_remembered_ones_are_read_the_same(monkeypatch: pytest.MonkeyPatch) -> None:
    """The kind of a name's text is remembered up to ``Words.LIMIT`` texts; past that it is
    worked out each time, with the same answers."""
    monkeypatch.setattr(Words, "LIMIT", 2)
    text = program(60)
    lark = build_parser()  # tables of its own: nothing remembered yet
    fast = parse_source("limit.scl", text, lark)
    driver = parse_source("limit.scl", text, lark, fast=False)
    assert not driver.diagnostics
    assert dump(fast.source) == dump(driver.source)
    assert lalr.parse(text, lark, _RESERVED) is not None
