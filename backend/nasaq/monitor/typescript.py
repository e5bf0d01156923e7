"""TypeScript types for the monitoring protocol, generated from its pydantic models.

``python -m nasaq.monitor.typescript`` prints ``frontend/src/api/monitor.ts``; with ``--write`` it
writes it. The types come from the JSON Schema of ``CLIENT_MESSAGE`` in input (validation) mode, as
a client may leave out fields that have defaults, and of ``SERVER_MESSAGE`` in serialization mode,
where every field is always sent. A model used on both sides whose two schemas differ becomes two
interfaces, ``<Name>Input`` and ``<Name>Output`` (pydantic's own naming of such pairs).

Only the schema constructs the protocol needs are translated; any other raises
:class:`UnsupportedSchemaError` rather than turning into a loose type.
"""

from __future__ import annotations

import argparse
import json
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any, NamedTuple

from pydantic import TypeAdapter
from pydantic.json_schema import GenerateJsonSchema, JsonSchemaMode, JsonSchemaValue
from pydantic_core import core_schema

from nasaq.monitor import protocol

COMMAND = ".venv/bin/python -m nasaq.monitor.typescript --write"
TARGET = Path("frontend") / "src" / "api" / "monitor.ts"

# Keywords that say nothing about a value's TypeScript type: annotations and value constraints.
_IGNORED = frozenset(
    {
        "title",
        "description",
        "default",
        "examples",
        "deprecated",
        "readOnly",
        "writeOnly",
        "format",
        "minimum",
        "maximum",
        "exclusiveMinimum",
        "exclusiveMaximum",
        "multipleOf",
        "minLength",
        "maxLength",
        "pattern",
        "minItems",
        "maxItems",
        "uniqueItems",
    }
)
_PRIMITIVES = {
    "string": "string",
    "integer": "number",
    "number": "number",
    "boolean": "boolean",
    "null": "null",
}
_IDENTIFIER = re.compile(r"[A-Za-z_$][A-Za-z0-9_$]*")
_REF = re.compile(r"#/\$defs/(.+)")
_LINE_LENGTH = 100


class UnsupportedSchemaError(ValueError):
    """A JSON Schema construct this generator does not translate."""


class Root(NamedTuple):
    """A top-level type: ``export type <name> = ...`` for what ``adapter`` reads or writes."""

    name: str
    adapter: TypeAdapter[Any]
    mode: JsonSchemaMode


class _AlwaysSent(GenerateJsonSchema):
    """Serialization schemas that mark fields with defaults required: pydantic sends every field
    (unless one is conditionally excluded)."""

    def field_is_required(
        self,
        field: core_schema.ModelField | core_schema.DataclassField | core_schema.TypedDictField,
        total: bool,
    ) -> bool:
        if self.mode == "serialization" and field["type"] != "typed-dict-field":
            return field.get("serialization_exclude_if") is None
        return super().field_is_required(field, total)


def generate(roots: Sequence[Root]) -> str:
    """TypeScript declarations for ``roots`` and every model they refer to: each root's type,
    then the interfaces it reaches in the order it first mentions them."""
    schemas, definitions = TypeAdapter.json_schemas(
        [(root.name, root.mode, root.adapter) for root in roots], schema_generator=_AlwaysSent
    )
    return _Writer(definitions.get("$defs", {}), [root.name for root in roots]).write(
        [(root.name, schemas[root.name, root.mode]) for root in roots]
    )


def protocol_typescript() -> str:
    """The contents of ``frontend/src/api/monitor.ts``."""
    return (
        "// Generated from backend/nasaq/monitor/protocol.py; do not edit. Regenerate with\n"
        f"// `{COMMAND}`.\n\n"
        f"export const PROTOCOL_VERSION = {json.dumps(protocol.PROTOCOL_VERSION)};\n\n"
        + generate(
            [
                Root("ClientMessage", protocol.CLIENT_MESSAGE, "validation"),
                Root("ServerMessage", protocol.SERVER_MESSAGE, "serialization"),
            ]
        )
    )


class _Writer:
    def __init__(self, definitions: dict[str, JsonSchemaValue], taken: Sequence[str]) -> None:
        self.definitions = definitions
        self.names: dict[str, str] = {}  # $defs key -> TypeScript name
        used = set(taken)
        for key in definitions:
            name = re.sub(r"[^A-Za-z0-9_$]", "", key)
            if not _IDENTIFIER.fullmatch(name) or name in used:
                raise UnsupportedSchemaError(f"no distinct TypeScript name for definition {key!r}")
            used.add(name)
            self.names[key] = name
        self.pending: list[str] = []  # $defs keys mentioned but not yet written
        self.queued: set[str] = set()

    def write(self, roots: Sequence[tuple[str, JsonSchemaValue]]) -> str:
        blocks: list[str] = []
        for name, schema in roots:
            blocks.append(self._alias(name, schema))
            while self.pending:
                key = self.pending.pop(0)
                blocks.append(self._definition(self.names[key], self.definitions[key]))
        return "\n\n".join(blocks) + "\n"

    def _definition(self, name: str, schema: JsonSchemaValue) -> str:
        if schema.get("type") == "object" and "properties" in schema:
            return self._interface(name, schema)
        return self._alias(name, schema)

    def _alias(self, name: str, schema: JsonSchemaValue) -> str:
        members = self._members(schema)
        line = f"export type {name} = {' | '.join(members)};"
        if len(line) > _LINE_LENGTH and len(members) > 1:
            line = f"export type {name} =\n" + "\n".join(f"  | {m}" for m in members) + ";"
        return _comment(schema, "") + line

    def _interface(self, name: str, schema: JsonSchemaValue) -> str:
        _expect(schema, {"type", "properties", "required", "additionalProperties"})
        if schema.get("additionalProperties", False) is not False:
            raise UnsupportedSchemaError(f"{name}: an object with both properties and extra keys")
        required = set(schema.get("required", []))
        body = ""
        for prop, prop_schema in schema["properties"].items():
            key = prop if _IDENTIFIER.fullmatch(prop) else _string(prop)
            optional = "" if prop in required else "?"
            type_ = " | ".join(self._members(prop_schema))
            body += f"{_comment(prop_schema, '  ')}  {key}{optional}: {type_};\n"
        head = f"{_comment(schema, '')}export interface {name} {{"
        return f"{head}\n{body}}}" if body else f"{head}}}"

    def _members(self, schema: JsonSchemaValue) -> list[str]:
        """The TypeScript type of ``schema``, as the members of a union (usually one)."""
        keys = set(schema) - _IGNORED
        if "$ref" in keys:
            _expect(schema, {"$ref"})
            return [self._ref(schema["$ref"])]
        for union in ("anyOf", "oneOf"):
            if union in keys:
                _expect(schema, {union, "discriminator"})
                return _unique(m for member in schema[union] for m in self._members(member))
        if "const" in keys:
            _expect(schema, {"const", "type"})
            return [_literal(schema["const"])]
        if "enum" in keys:
            _expect(schema, {"enum", "type"})
            return _unique(_literal(value) for value in schema["enum"])
        if not keys:
            return ["unknown"]  # Any
        kind = schema.get("type")
        if kind == "array":
            _expect(schema, {"type", "items"})
            items = self._members(schema.get("items", {}))
            return [f"Array<{' | '.join(items)}>" if len(items) > 1 else f"{items[0]}[]"]
        if kind == "object" and "properties" not in schema:
            _expect(schema, {"type", "additionalProperties"})
            values = schema.get("additionalProperties", True)
            if values is False:
                raise UnsupportedSchemaError(f"an object that allows no keys: {schema}")
            value = "unknown" if values is True else " | ".join(self._members(values))
            return [f"Record<string, {value}>"]
        if isinstance(kind, str) and kind in _PRIMITIVES:
            _expect(schema, {"type"})
            return [_PRIMITIVES[kind]]
        raise UnsupportedSchemaError(f"no TypeScript type for the schema {schema}")

    def _ref(self, ref: str) -> str:
        match = _REF.fullmatch(ref)
        if match is None or match[1] not in self.definitions:
            raise UnsupportedSchemaError(f"a reference outside $defs: {ref!r}")
        key = match[1]
        if key not in self.queued:
            self.queued.add(key)
            self.pending.append(key)
        return self.names[key]


def _expect(schema: JsonSchemaValue, allowed: set[str]) -> None:
    unknown = set(schema) - _IGNORED - allowed
    if unknown:
        raise UnsupportedSchemaError(f"schema keyword(s) {sorted(unknown)} in {schema}")


def _unique(members: Iterable[str]) -> list[str]:
    return list(dict.fromkeys(members))


def _literal(value: object) -> str:
    if isinstance(value, str):
        return _string(value)
    if value is None or isinstance(value, bool | int):
        return json.dumps(value)
    raise UnsupportedSchemaError(f"a literal of type {type(value).__name__}: {value!r}")


def _string(value: str) -> str:
    if any(ord(char) < 0x20 for char in value):
        raise UnsupportedSchemaError(f"a string with control characters: {value!r}")
    return "'" + value.replace("\\", "\\\\").replace("'", "\\'") + "'"


def _comment(schema: JsonSchemaValue, indent: str) -> str:
    """``description`` as a doc comment (reST double backquotes become Markdown's single), or
    nothing."""
    text = schema.get("description")
    if not text:
        return ""
    lines = text.replace("``", "`").replace("*/", "*\\/").splitlines()
    single = f"{indent}/** {lines[0]} */"
    if len(lines) == 1 and len(single) <= _LINE_LENGTH:
        return single + "\n"
    body = "".join(f"{indent} *{' ' + line if line else ''}\n" for line in lines)
    return f"{indent}/**\n{body}{indent} */\n"


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m nasaq.monitor.typescript",
        description="Print (or write) the monitoring protocol's TypeScript types.",
    )
    parser.add_argument("--write", action="store_true", help=f"write {TARGET} instead of printing")
    write = parser.parse_args(argv).write
    text = protocol_typescript()
    if not write:
        print(text, end="")
        return
    root = Path(__file__).resolve().parents[3]
    if not (root / "frontend").is_dir():
        raise SystemExit(f"no frontend/ beside backend/ in {root}: run this from a source checkout")
    (root / TARGET).write_text(text, encoding="utf-8")
    print(f"wrote {root / TARGET}")


if __name__ == "__main__":
    main()
