"""Fixed phrases inside a diagnostic's parameters, so the UI can show them in its language.

A catalogue message such as MON607 "{action} is not possible now: {reason}" takes whole sentences
as parameters. Passed as plain English strings they would reach an Arabic, Persian or Vietnamese
user untranslated. A :class:`Phrase` is such a parameter with a stable key: :func:`expand` (which
:func:`nasaq.diagnostics.render` applies) keeps the English text in the parameter, for the API's
English ``message`` and for clients that know no keys, and adds ``<name>_key`` and
``<name>_params`` beside it. The front end translates ``phrases.<key>`` with those parameters
(``frontend/src/i18n/phraseParams.ts``; the texts are in ``frontend/src/i18n/phrases/``). A phrase
parameter may itself be a phrase.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

# key → English template ({name} parameters). Grouped by where they are used.
PHRASES: dict[str, str] = {
    # framing and validation of requests (MON601, API103)
    "frames_json": "frames must be JSON text",
    "field_reason": "{field}: {reason}",
    "value_missing": "a value is required",
    "value_invalid": "the value is not valid",
    "text_expected": "text is expected",
    "text_too_short": "at least {min_length} character(s) are needed",
    "text_too_long": "at most {max_length} character(s) are allowed",
    "text_pattern": "the text does not have the required form",
    "number_expected": "a whole number is expected",
    "decimal_expected": "a number is expected",
    "bool_expected": "true or false is expected",
    "list_expected": "a list is expected",
    "object_expected": "an object is expected",
    "number_ge": "the number must be {ge} or more",
    "number_gt": "the number must be more than {gt}",
    "number_le": "the number must be {le} or less",
    "number_lt": "the number must be less than {lt}",
    "choice_expected": "one of {expected} is expected",
    "list_too_short": "at least {min_length} item(s) are needed",
    "list_too_long": "at most {max_length} item(s) are allowed",
    "field_unknown": "this field is not known",
    "json_invalid": "the request is not valid JSON",
    "request_refused": "the request was refused",
    "name_empty": "the name is empty",
    "name_characters": 'the name may not contain control characters or / \\ : * ? " < > |',
    # what a monitor request names (MON603)
    "not_an_input": "this is not an input (I, PI)",
    "force_only_io": "only inputs and outputs (I, Q) can be forced",
    "unforce_only_io": "only inputs and outputs are forced",
    "no_such_local": "{block} has no such variable (it has: {known})",
    "no_such_client": "no such client is connected",
    "client_n": "client {client}",
    "target_empty": "type an address, a symbol or a DB variable (examples: {examples})",
    "target_local": "local data (#name, L) exists only while its block runs: watch it while the "
    "CPU holds in that block",
    "target_open_db": "say which data block, e.g. DB1.DBW2",
    "target_peripheral_width": "the peripheral areas are read by byte, word or doubleword, "
    "e.g. PIB0, PIW256, PQD4",
    "db_missing_has": "DB{db} is not in the downloaded program (its data blocks: {known})",
    "db_missing_none": "DB{db} is not in the downloaded program (it has no data blocks)",
    "db_range_last": "DB{db} is {size} bytes long: its last byte is {last}",
    "db_range_empty": "DB{db} is {size} bytes long: it holds no data",
    "symbol_unknown_close": '"{name}" is neither an address nor a symbol of the program; '
    'did you mean "{close}"?',
    "symbol_unknown": '"{name}" is neither an address nor a symbol of the program '
    "(examples: {examples})",
    "symbol_not_address": '"{name}" stands for {address}, which is not an address',
    "symbol_is_block": "{label} is the block {address}, which has no value to watch",
    "symbol_is_local": "{label} is {address}, which exists only inside a running block",
    "symbol_not_db": '"{name}" is {address}, not a data block: only a DB has variables '
    "(e.g. DB1.level)",
    "target_unreadable": "not an address, a symbol or a DB variable (examples: {examples})",
    "db_no_layout": "{label} declares no variables Nasaq knows: use its addresses, e.g. {example}",
    "db_name_variable": "{label} is a data block: name one of its variables, e.g. {example} "
    "(it has {known})",
    "index_first": "{path} has type {type}: give an index first, e.g. {example}",
    "type_no_variables": "{path} has type {type}, which has no variables",
    "no_such_variable": "{path} has no variable {name} (it has {known})",
    "in_out_pointer": "{path} is an IN_OUT parameter of type {type}: the instance DB holds only "
    "a pointer to it; watch the actual parameter instead",
    "db_not_array": "{path} is a data block, not an ARRAY: only an array takes an index",
    "type_not_array": "{path} has type {type}, not an ARRAY: only an array takes an index",
    "index_count": "{path} has type {type}: it takes {count} index(es), e.g. {example}",
    "index_outside": "index {index} is outside {low}..{high} ({path} has type {type})",
    "element_layout": "Nasaq does not know the layout of the {type} elements of {path}: watch "
    "{name} by address, from {start}",
    "add_index": "{path} has type {type}: add an index, e.g. {example}",
    "name_member": "{path} has type {type}: name one of its variables, e.g. {example} "
    "(it has {known})",
    "not_elementary": "{path} has type {type} ({bytes} bytes), not one elementary value: watch "
    "its bytes by address from {first}",
    "array_index_whole": "an array index is a whole number, e.g. DB1.arr[3] or DB1.m[1, 2]",
    "db_not_loaded": "DB{db} is not loaded",
    "no_memory_address": "it has no address in the CPU's memory",
    "numbered_range": "the {cpu} has {first} to {last}",
    "db_length": "DB{db} is {size} bytes long",
    "area_range": "the {cpu} has {first} to {last}",
    # addresses (headless/addresses.py)
    "bit_needs_number": "a bit address needs a bit number, e.g. {example}",
    "bit_number_range": "the bit number must be 0 to 7",
    "bit_only": "only bit addresses have a bit number",
    "no_db_zero": "there is no DB 0",
    "not_an_address": "{text} is not an address (examples: I0.0, MW10, DB1.DBD4, T1, C2)",
    # values written to the CPU (MON606)
    "param_fixed": "a block parameter is fixed",
    "timers_not_written": "the program runs timers and counters (SD, CU ...); they cannot be "
    "written",
    "value_needed": "a value of type {type} is needed, e.g. {example}",
    "type_not_writable": "type {type} is not one elementary value and cannot be written",
    "value_not_fit": "{value} does not fit type {type}: {allowed}",
    "not_bool": "{value} is not a BOOL: write TRUE or FALSE (1 or 0)",
    "not_real": "{value} is not a REAL: write a number, e.g. 1.5",
    "not_whole": "{value} is not a whole number; type {type} holds {allowed}",
    "constant_of_type": "{value} is of type {actual}, not {type} (e.g. {example})",
    "not_of_type": "{value} is not a value of type {type} (e.g. {example})",
    "not_constant": "{value}: {reason}",
    "range": "{low} to {high}",
    "char_range": "one character of code 0 to 255",
    "out_of_range": "out of range",
    # commands refused (MON607) and what they name (MON604, MON605)
    "act_clear_breakpoint": "Clearing breakpoint {id}",
    "act_modify": "Modifying {target}",
    "act_continue": "Continue",
    "act_step": "A single step",
    "act_run_scans": "Running {count} scans",
    "act_download": "A download",
    "act_command": "This command",
    "no_such_breakpoint": "there is no such breakpoint",
    "locals_only_holding": "locals exist only while the CPU holds",
    "cpu_not_holding": "the CPU neither holds nor is paused",
    "cpu_in_stop": "the CPU is in STOP",
    "cpu_must_run": "the CPU must be in RUN, not holding",
    "switch_to_stop": "switch the CPU to STOP first",
    "internal_error": "internal error",
    "what_clients": "clients of this session",
    "what_watch": "watch",
    "what_trend": "trend",
    "where_instruction": "{block} instruction {instruction}",
    "where_network": "{block} network {network}",
    "where_line": "{file} line {line}",
    "hint_block_has": " (the block has {count})",
    "hint_give_place": " (give a line, network or instruction)",
    "hint_give_block": " (give a block, or a file and a line)",
    "hint_next_line": " (the next line with code is {line})",
    "db_too_large": "{size} bytes of data blocks, at most {limit}",
    # breakpoint conditions (MON612)
    "condition_form": "write <operand> <comparison> <value>, e.g. MW10 > 5",
    "condition_not_number": "{value} is not a number or TRUE/FALSE",
    "condition_no_variable": "{block} has no variable {name}",
}


@dataclass(frozen=True, slots=True)
class Phrase:
    """A fixed phrase with its parameters; ``str()`` is the English text (``english`` when given:
    a library's own wording that the phrase translates, e.g. pydantic's)."""

    key: str
    params: Mapping[str, Any] = field(default_factory=dict)
    english: str | None = None

    def __str__(self) -> str:
        return self.english if self.english is not None else PHRASES[self.key].format(**self.params)

    def __format__(self, spec: str) -> str:
        return format(str(self), spec)


def phrase(key: str, **params: Any) -> Phrase:
    """The phrase ``key``; an unknown key is a programming error (KeyError, at once)."""
    PHRASES[key].format(**params)  # a missing parameter fails here, not when shown
    return Phrase(key, params)


def expand(params: Mapping[str, Any]) -> dict[str, Any]:
    """``params`` with each phrase turned into its English text plus ``<name>_key`` and
    ``<name>_params`` (expanded the same way), so the result is plain JSON."""
    out: dict[str, Any] = {}
    for name, value in params.items():
        if isinstance(value, Phrase):
            out[name] = str(value)
            out[f"{name}_key"] = value.key
            out[f"{name}_params"] = expand(value.params)
        else:
            out[name] = value
    return out
