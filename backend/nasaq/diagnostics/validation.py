"""Pydantic's validation errors as phrases (API103, MON601), so the reason reaches the UI as a key.

Pydantic words its messages in English ("String should have at least 1 character"); its error
``type`` and ``ctx`` are stable, so the common types map to phrases the UI translates. A type not
listed here becomes the generic "the value is not valid", with pydantic's English kept in the
API's message.
"""

from __future__ import annotations

from collections.abc import Mapping
from string import Formatter
from typing import Any

from nasaq.diagnostics.phrases import PHRASES, Phrase

# pydantic error type → phrase key; the phrase's parameters come from the error's ``ctx``.
_TYPES = {
    "missing": "value_missing",
    "string_type": "text_expected",
    "string_too_short": "text_too_short",
    "string_too_long": "text_too_long",
    "string_pattern_mismatch": "text_pattern",
    "int_type": "number_expected",
    "int_parsing": "number_expected",
    "int_from_float": "number_expected",
    "float_type": "decimal_expected",
    "float_parsing": "decimal_expected",
    "bool_type": "bool_expected",
    "bool_parsing": "bool_expected",
    "list_type": "list_expected",
    "dict_type": "object_expected",
    "model_type": "object_expected",
    "model_attributes_type": "object_expected",
    "greater_than_equal": "number_ge",
    "greater_than": "number_gt",
    "less_than_equal": "number_le",
    "less_than": "number_lt",
    "literal_error": "choice_expected",
    "enum": "choice_expected",
    "too_short": "list_too_short",
    "too_long": "list_too_long",
    "extra_forbidden": "field_unknown",
    "json_invalid": "json_invalid",
}


def validation_reason(error: Mapping[str, Any]) -> Phrase:
    """The reason of one pydantic error (an item of ``ValidationError.errors()``)."""
    context = error.get("ctx") or {}
    raised = context.get("error")
    if isinstance(raised, ValueError) and raised.args and isinstance(raised.args[0], Phrase):
        return raised.args[0]  # a validator of Nasaq's own said why, as a phrase
    key = _TYPES.get(str(error.get("type", "")), "value_invalid")
    names = [name for _, name, _, _ in Formatter().parse(PHRASES[key]) if name]
    params = {name: _shown(context.get(name, "?")) for name in names}
    english = str(error.get("msg", "invalid")).removeprefix("Value error, ")
    return Phrase(key, params, english)


def _shown(value: Any) -> str:
    return str(value).replace("'", "")
