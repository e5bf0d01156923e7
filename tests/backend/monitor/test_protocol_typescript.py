"""The front end's monitoring-protocol types are generated from the pydantic models."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import pytest
from pydantic import BaseModel, ConfigDict, Field, TypeAdapter

from nasaq.monitor.typescript import (
    COMMAND,
    TARGET,
    Root,
    UnsupportedSchemaError,
    generate,
    protocol_typescript,
)

ROOT = Path(__file__).resolve().parents[3]


def test_the_committed_typescript_matches_the_protocol() -> None:
    committed = (ROOT / TARGET).read_text("utf-8")
    assert committed == protocol_typescript(), f"the protocol changed: run `{COMMAND}`"


def test_the_typescript_names_the_protocol_version() -> None:
    assert "export const PROTOCOL_VERSION = 1;" in protocol_typescript()


class Point(BaseModel):
    x: float
    y: float


class Shape(BaseModel):
    """A shape.

    Drawn at ``origin``; its */ end is escaped."""

    kind: Literal["circle", "square"]
    origin: Point
    size: int | None = Field(default=None, description="Edge or diameter")
    tags: list[str] = []
    labels: dict[str, int | str] = {}
    extra: dict[str, Any] | None = None
    corners: list[int | None]


class Hit(BaseModel):
    type: Literal["hit"] = "hit"
    shape: Shape
    point: Point


def test_models_become_interfaces_and_types() -> None:
    typescript = generate(
        [
            Root("Request", TypeAdapter(Shape), "validation"),
            Root("Reply", TypeAdapter(Hit | list[Point]), "serialization"),
        ]
    )
    assert typescript == (
        "export type Request = ShapeInput;\n"
        "\n"
        "/**\n"
        " * A shape.\n"
        " *\n"
        " * Drawn at `origin`; its *\\/ end is escaped.\n"
        " */\n"
        "export interface ShapeInput {\n"
        "  kind: 'circle' | 'square';\n"
        "  origin: Point;\n"
        "  /** Edge or diameter */\n"
        "  size?: number | null;\n"
        "  tags?: string[];\n"
        "  labels?: Record<string, number | string>;\n"
        "  extra?: Record<string, unknown> | null;\n"
        "  corners: Array<number | null>;\n"
        "}\n"
        "\n"
        "export interface Point {\n"
        "  x: number;\n"
        "  y: number;\n"
        "}\n"
        "\n"
        "export type Reply = Hit | Point[];\n"
        "\n"
        "export interface Hit {\n"
        "  type: 'hit';\n"
        "  shape: ShapeOutput;\n"
        "  point: Point;\n"
        "}\n"
        "\n"
        "/**\n"
        " * A shape.\n"
        " *\n"
        " * Drawn at `origin`; its *\\/ end is escaped.\n"
        " */\n"
        "export interface ShapeOutput {\n"
        "  kind: 'circle' | 'square';\n"
        "  origin: Point;\n"
        "  /** Edge or diameter */\n"
        "  size: number | null;\n"
        "  tags: string[];\n"
        "  labels: Record<string, number | string>;\n"
        "  extra: Record<string, unknown> | null;\n"
        "  corners: Array<number | null>;\n"
        "}\n"
    )


def test_a_long_union_goes_one_member_a_line() -> None:
    members = Literal["alpha", "bravo", "charlie", "delta", "echo", "foxtrot", "golf", "hotel"]
    typescript = generate([Root("Letter", TypeAdapter(members), "validation")])
    assert typescript.startswith("export type Letter =\n  | 'alpha'\n  | 'bravo'\n")
    assert typescript.endswith("\n  | 'hotel';\n")


class Pair(BaseModel):
    both: tuple[int, str]


class Open(BaseModel):
    model_config = ConfigDict(extra="allow")
    name: str


class Ratio(BaseModel):
    value: Literal[0.5]


class Nothing(BaseModel):
    model_config = ConfigDict(extra="forbid")


@pytest.mark.parametrize(
    ("kind", "error"),
    [
        (Pair, "prefixItems"),
        (Open, "both properties and extra keys"),
        (Ratio, "a literal of type float"),
        (dict[Literal["a", "b"], int], "propertyNames"),
    ],
)
def test_an_unsupported_construct_raises(kind: Any, error: str) -> None:
    with pytest.raises(UnsupportedSchemaError, match=error):
        generate([Root("T", TypeAdapter(kind), "validation")])


def test_a_model_without_fields_is_an_empty_interface() -> None:
    typescript = generate([Root("T", TypeAdapter(dict[str, Nothing]), "validation")])
    assert typescript == (
        "export type T = Record<string, Nothing>;\n\nexport interface Nothing {}\n"
    )


def test_a_type_name_taken_twice_raises() -> None:
    with pytest.raises(UnsupportedSchemaError, match="no distinct TypeScript name"):
        generate([Root("Point", TypeAdapter(list[Point]), "validation")])
