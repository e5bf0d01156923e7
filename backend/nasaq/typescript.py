"""TypeScript types generated from pydantic models, so the front end's types cannot drift.

:func:`generate` writes TypeScript declarations for a few *roots* (a model, a union, any type a
``TypeAdapter`` takes) and every model they reach, from their JSON Schemas: a model becomes an
interface, a union or a literal a type alias. A root that is a model is written as that model's
interface; a root that is a union of models (``Element``, ``Final`` ...) is a type alias, and
wherever the same union appears inside another model, its name stands for it. The JSON Schema
of a root is in input (``validation``) mode or in ``serialization`` mode, where every field is
always present. A model used in both modes whose two schemas differ becomes two interfaces,
``<Name>Input`` and ``<Name>Output`` (pydantic's own naming of such pairs).

Only the schema constructs these types need are translated; any other raises
:class:`UnsupportedSchemaError` rather than turning into a loose type. The generated files and
their commands: ``nasaq.monitor.typescript`` (the monitoring protocol) and
``nasaq.lang.lad.typescript`` (the LAD/FBD network model and its layouts).
"""

from __future__ import annotations

import argparse
import json
import re
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any, NamedTuple

from pydantic import TypeAdapter
from pydantic.json_schema import GenerateJsonSchema, JsonSchemaMode, JsonSchemaValue
from pydantic_core import core_schema

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
_UNIONS = ("anyOf", "oneOf")


class UnsupportedSchemaError(ValueError):
    """A JSON Schema construct this generator does not translate."""


class Root(NamedTuple):
    """A top-level type: ``export type <name> = ...`` for what ``adapter`` reads or writes (or,
    when ``adapter`` is a model's and ``name`` the model's name, its ``export interface``);
    ``description`` is the doc comment of a type alias."""

    name: str
    adapter: TypeAdapter[Any]
    mode: JsonSchemaMode
    description: str = ""


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
    written = [(root, schemas[root.name, root.mode]) for root in roots]
    aliases = [(root, schema) for root, schema in written if not _is_own_model(root, schema)]
    writer = _Writer(definitions.get("$defs", {}), aliases)
    return writer.write(written)


def _is_own_model(root: Root, schema: JsonSchemaValue) -> bool:
    """Whether the root is a model named as the root: written as the model's interface."""
    return schema == {"$ref": f"#/$defs/{root.name}"}


def _union_key(schema: JsonSchemaValue) -> tuple[str, ...] | None:
    """The references a union of references joins, in order; None for any other schema."""
    for union in _UNIONS:
        members = schema.get(union)
        if isinstance(members, list) and all(set(member) == {"$ref"} for member in members):
            return tuple(member["$ref"] for member in members)
    return None


def write_or_print(
    text: Callable[[], str], target: Path, prog: str, argv: Sequence[str] | None
) -> None:
    """The command line of a generated file: print ``text()``, or with ``--write`` write it to
    ``target`` (relative to the source checkout this package sits in)."""
    parser = argparse.ArgumentParser(prog=prog, description=f"Print (or write) {target}.")
    parser.add_argument("--write", action="store_true", help=f"write {target} instead of printing")
    write = parser.parse_args(argv).write
    if not write:
        print(text(), end="")
        return
    root = Path(__file__).resolve().parents[2]
    if not (root / "frontend").is_dir():
        raise SystemExit(f"no frontend/ beside backend/ in {root}: run this from a source checkout")
    (root / target).write_text(text(), encoding="utf-8")
    print(f"wrote {root / target}")


class _Writer:
    def __init__(
        self,
        definitions: dict[str, JsonSchemaValue],
        aliases: Sequence[tuple[Root, JsonSchemaValue]],
    ) -> None:
        self.definitions = definitions
        self.names: dict[str, str] = {}  # $defs key -> TypeScript name
        used = {root.name for root, _ in aliases}
        for key in definitions:
            name = re.sub(r"[^A-Za-z0-9_$]", "", key)
            if not _IDENTIFIER.fullmatch(name) or name in used:
                raise UnsupportedSchemaError(f"no distinct TypeScript name for definition {key!r}")
            used.add(name)
            self.names[key] = name
        self.unions: dict[tuple[str, ...], str] = {}  # a root union's references -> its name
        for root, schema in aliases:
            refs = _union_key(schema)
            if refs is not None:
                self.unions.setdefault(refs, root.name)
        self.pending: list[str] = []  # $defs keys mentioned but not yet written
        self.queued: set[str] = set()

    def write(self, roots: Sequence[tuple[Root, JsonSchemaValue]]) -> str:
        blocks: list[str] = []
        for root, schema in roots:
            if _is_own_model(root, schema):
                self._ref(schema["$ref"])
            else:
                blocks.append(self._alias(root.name, schema, root.description))
            while self.pending:
                key = self.pending.pop(0)
                blocks.append(self._definition(self.names[key], self.definitions[key]))
        return "\n\n".join(blocks) + "\n"

    def _definition(self, name: str, schema: JsonSchemaValue) -> str:
        if schema.get("type") == "object" and "properties" in schema:
            return self._interface(name, schema)
        return self._alias(name, schema)

    def _alias(self, name: str, schema: JsonSchemaValue, description: str = "") -> str:
        members = self._union(schema) if _union_key(schema) else self._members(schema)
        line = f"export type {name} = {' | '.join(members)};"
        if len(line) > _LINE_LENGTH and len(members) > 1:
            line = f"export type {name} =\n" + "\n".join(f"  | {m}" for m in members) + ";"
        return _comment({"description": description, **schema}, "") + line

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
        if keys & set(_UNIONS):
            key = _union_key(schema)
            named = self.unions.get(key) if key else None
            return [named] if named else self._union(schema)
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

    def _union(self, schema: JsonSchemaValue) -> list[str]:
        """The members of an ``anyOf``/``oneOf`` (a ``discriminator`` only helps validators:
        TypeScript tells the members apart by their literal ``kind`` on its own)."""
        union = next(union for union in _UNIONS if union in schema)
        _expect(schema, {union, "discriminator"})
        return _unique(m for member in schema[union] for m in self._members(member))

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
