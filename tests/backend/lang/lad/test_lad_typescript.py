"""The front end's LAD/FBD model types are generated from the pydantic models, and the writer's
parts these types need: a model as a root, named unions, recursion, dicts of unions."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Literal

import pytest
from pydantic import BaseModel, Field, TypeAdapter

from nasaq.lang.lad.typescript import COMMAND, TARGET, model_typescript
from nasaq.typescript import Root, UnsupportedSchemaError, generate

ROOT = Path(__file__).resolve().parents[4]


def test_the_committed_typescript_matches_the_model() -> None:
    committed = (ROOT / TARGET).read_text("utf-8")
    assert committed == model_typescript(), f"the LAD model changed: run `{COMMAND}`"


def test_the_model_types_name_their_unions() -> None:
    typescript = model_typescript()
    assert "export interface Series {\n  elements: Element[];\n}" in typescript
    assert "  target: Final;\n" in typescript
    assert "  inputs: Record<string, string | Series>;\n" in typescript
    assert "  flow: FbdNode | null;\n" in typescript
    assert "export type Final = Coil | Jump | Return | OpenDb | Box;" in typescript


class Leaf(BaseModel):
    kind: Literal["leaf"] = "leaf"
    name: str


class Fork(BaseModel):
    kind: Literal["fork"] = "fork"
    parts: list[Node]
    named: dict[str, str | Node] = {}
    spare: Node | None = None


Node = Annotated[Leaf | Fork, Field(discriminator="kind")]
Fork.model_rebuild()


def test_a_model_root_is_its_interface_and_a_union_root_names_the_union() -> None:
    typescript = generate(
        [
            Root("Fork", TypeAdapter(Fork), "serialization"),
            Root("Node", TypeAdapter(Node), "serialization", "A leaf or a fork."),
        ]
    )
    assert typescript == (
        "export interface Fork {\n"
        "  kind: 'fork';\n"
        "  parts: Node[];\n"
        "  named: Record<string, string | Node>;\n"
        "  spare: Node | null;\n"
        "}\n"
        "\n"
        "/** A leaf or a fork. */\n"
        "export type Node = Leaf | Fork;\n"
        "\n"
        "export interface Leaf {\n"
        "  kind: 'leaf';\n"
        "  name: string;\n"
        "}\n"
    )


def test_without_a_union_root_the_union_is_written_out() -> None:
    typescript = generate([Root("Fork", TypeAdapter(Fork), "validation")])
    assert "  parts: Array<Leaf | Fork>;\n" in typescript
    assert "  spare?: Leaf | Fork | null;\n" in typescript


def test_a_root_named_as_another_model_raises() -> None:
    with pytest.raises(UnsupportedSchemaError, match="no distinct TypeScript name"):
        generate([Root("Leaf", TypeAdapter(Fork), "serialization")])


def test_a_union_with_both_kinds_of_members_lists_raises() -> None:
    writer_schema = {"anyOf": [{"type": "string"}], "oneOf": [{"type": "integer"}]}

    class Odd(BaseModel):
        value: Annotated[str, Field(json_schema_extra=writer_schema)]

    with pytest.raises(UnsupportedSchemaError, match="oneOf"):
        generate([Root("Odd", TypeAdapter(Odd), "validation")])
