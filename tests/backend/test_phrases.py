"""Server messages carry no fixed English sentence the UI cannot translate (MON6xx, API1xx).

A parameter that is a fixed phrase (a reason, an action, a place) is sent as the English text plus
``<name>_key`` and ``<name>_params``; the front end translates ``phrases.<key>``.
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from nasaq.diagnostics import render
from nasaq.diagnostics.phrases import PHRASES, phrase
from nasaq.lang.stl import SourceFile, compile_sources
from nasaq.monitor import targets
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.worker import error_json

ROOT = Path(__file__).resolve().parents[2]
PHRASE_FILES = ROOT / "frontend" / "src" / "i18n" / "phrases"
MONITOR = ROOT / "backend" / "nasaq" / "monitor"

PROGRAM = """\
DATA_BLOCK DB 1
STRUCT
  level : INT;
  vals : ARRAY [1..3] OF INT;
END_STRUCT
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK OB 1
BEGIN
NETWORK
      A     I 0.0
      =     Q 4.0
END_ORGANIZATION_BLOCK
"""


def _keys_checked(params: dict[str, Any]) -> list[str]:
    """Every phrase key in ``params`` (nested ones too), checked to be catalogued."""
    found = []
    for name, value in params.items():
        if name.endswith("_key"):
            assert value in PHRASES, value
            assert isinstance(params[name.removesuffix("_key")], str)
            found.append(value)
            found += _keys_checked(params[name.removesuffix("_key") + "_params"])
    return found


@pytest.mark.parametrize("language", ["en", "ar", "fa", "vi"])
def test_every_phrase_is_translated_with_the_same_params(language: str) -> None:
    texts = json.loads((PHRASE_FILES / f"{language}.json").read_text(encoding="utf-8"))["phrases"]
    assert set(texts) == set(PHRASES)
    for key, english in PHRASES.items():
        wanted = set(re.findall(r"\{(\w+)\}", english))
        assert set(re.findall(r"\{\{(\w+)\}\}", texts[key])) == wanted, f"{language}: {key}"


def test_a_refused_command_sends_keys_and_keeps_the_english_message() -> None:
    error = MonitorError("MON607", action=phrase("act_step"), reason=phrase("cpu_in_stop"))
    sent = json.loads(error_json(7, error))
    assert sent["message"] == "A single step is not possible now: the CPU is in STOP"
    assert sent["params"] == {
        "action": "A single step",
        "action_key": "act_step",
        "action_params": {},
        "reason": "the CPU is in STOP",
        "reason_key": "cpu_in_stop",
        "reason_params": {},
    }


def test_nested_phrases_expand_into_nested_params() -> None:
    allowed = phrase("range", low="-32768", high="32767")
    found = render("MON606", target="MW10", reason=phrase("value_not_fit", value="99999",
                   type="INT", allowed=allowed))  # fmt: skip
    assert found.message == "MW10: 99999 does not fit type INT: -32768 to 32767"
    reason = found.params["reason_params"]
    assert reason["allowed_key"] == "range"
    assert reason["allowed_params"] == {"low": "-32768", "high": "32767"}
    json.dumps(found.params)  # plain JSON


@pytest.fixture(scope="module")
def program() -> Any:
    result = compile_sources([SourceFile("plant.awl", PROGRAM)])
    assert result.ok, [d.message for d in result.diagnostics]
    return result.program


@pytest.mark.parametrize(
    ("text", "key"),
    [
        ("", "target_empty"),
        ("#count", "target_local"),
        ("DBW2", "target_open_db"),
        ("PI 0.0", "target_peripheral_width"),
        ("DB9.DBW0", "db_missing_has"),
        ("DB1.DBW400", "db_range_last"),
        ('"Pump"', "symbol_unknown"),
        ("DB1", "db_name_variable"),
        ("DB1.nothing", "no_such_variable"),
        ("DB1.vals[9]", "index_outside"),
        ("DB1.level[1]", "type_not_array"),
        ("DB1.vals", "add_index"),
        ("M 1.9", "bit_number_range"),
        ("MW 10 +", "target_unreadable"),
    ],
)
def test_unknown_targets_give_phrase_keys(program: Any, text: str, key: str) -> None:
    with pytest.raises(targets.TargetError) as caught:
        targets.resolve(text, program)
    params = caught.value.diagnostic.params
    assert params["reason_key"] == key
    _keys_checked(params)


@pytest.mark.parametrize(
    ("text", "value", "key"),
    [
        ("M 0.0", "7", "not_bool"),
        ("MW10", "99999", "value_not_fit"),
        ("MW10", "1.5", "not_whole"),
        ("MW10", "T#2S", "constant_of_type"),
        ("MW10", "abc", "not_of_type"),
        ("MW10", None, "value_needed"),
        ("MD20", "x", "not_of_type"),
    ],
)
def test_values_that_do_not_fit_give_phrase_keys(
    program: Any, text: str, value: str | None, key: str
) -> None:
    with pytest.raises(targets.TargetError) as caught:
        targets.encode(targets.resolve(text, program), value)
    assert caught.value.diagnostic.params["reason_key"] == key
    _keys_checked(caught.value.diagnostic.params)


# The parameters that take sentences; an English literal there is what this issue removes.
_SENTENCE_PARAMS = {"reason", "action", "what", "where", "hint"}
_RAISERS = {"MonitorError", "TargetError", "error", "_bad"}


def _literal_sentences(tree: ast.AST) -> list[int]:
    lines = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
        if isinstance(func, ast.Attribute) and getattr(func.value, "id", "") == "log":
            continue  # the server log stays English
        if name not in _RAISERS:
            continue
        values = [k.value for k in node.keywords if k.arg in _SENTENCE_PARAMS]
        if name in ("error", "_bad"):
            values += node.args[-1:]
        elif name == "TargetError":
            values += node.args[2:3]
        for value in values:
            literal = isinstance(value, ast.JoinedStr) or (
                isinstance(value, ast.Constant)
                and isinstance(value.value, str)
                and re.search("[A-Za-z]", value.value) is not None
            )
            if literal:
                lines.append(node.lineno)
    return lines


@pytest.mark.parametrize("module", sorted(p.name for p in MONITOR.glob("*.py")))
def test_no_monitor_error_takes_an_english_sentence(module: str) -> None:
    tree = ast.parse((MONITOR / module).read_text(encoding="utf-8"))
    assert _literal_sentences(tree) == [], f"{module}: use a phrase (diagnostics/phrases.py)"


@pytest.mark.parametrize(
    ("body", "key"),
    [
        ({"name": "a/b"}, "name_characters"),
        ({"name": "   "}, "name_empty"),
        ({"name": "x" * 65}, "text_too_long"),
        ({}, "value_missing"),
        ({"name": 5}, "text_expected"),
    ],
)
def test_request_validation_reasons_are_phrases(
    client: TestClient, body: dict[str, Any], key: str
) -> None:
    response = client.post("/api/projects", json=body)
    assert response.status_code == 422
    error = response.json()["error"]
    assert error["code"] == "API103"
    assert error["params"]["reason_key"] == key
    assert error["message"].startswith(f"{error['params']['field']}: ")
    _keys_checked(error["params"])
