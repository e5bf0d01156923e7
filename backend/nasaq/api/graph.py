"""``POST /api/graph/read``: a ``.graph`` file read as the S7-Graph model, for the chart and the
step view. Like the LAD/FBD read, the editors draw what it gives and refuse to draw (saying why)
a text with syntax errors (``diagnostics``, GRA1xx/LAD1xx); the checker's findings on a text that
reads (``problems``, GRA2xx) are drawn on the steps and transitions they concern, found through
``places`` (the line of each part, keyed as the generated code's origins: ``S3``, ``T2``,
``S3/A1`` ..., ``nasaq/lang/graph/source.py``)."""

from __future__ import annotations

import asyncio

from fastapi import APIRouter
from pydantic import BaseModel, Field

from nasaq.api.errors import ApiErrorBody
from nasaq.api.files import checked_text
from nasaq.diagnostics import Diagnostic
from nasaq.lang.graph.check import check_block, has_errors
from nasaq.lang.graph.model import GraphBlock
from nasaq.lang.graph.text import parse_graph

router = APIRouter(prefix="/graph", tags=["convert"])


class GraphReadIn(BaseModel):
    name: str = Field(max_length=128, description="The file name (for the diagnostics)")
    text: str


class GraphReadOut(BaseModel):
    blocks: list[GraphBlock] = Field(description="The blocks the reader made of the text")
    diagnostics: list[Diagnostic] = Field(description="The text's syntax problems (GRA1xx)")
    problems: list[Diagnostic] = Field(
        description="The checker's findings per block (GRA2xx), when the text reads"
    )
    places: list[dict[str, int]] = Field(
        description="Per block, the 1-based line of each part: BLOCK, SETTINGS, SEQ:<name>, "
        "S<n>, S<n>/A<k>, S<n>/C, S<n>/V, T<n>, PRE<n>, POST<n>"
    )


def _read(name: str, text: str) -> GraphReadOut:
    parsed = parse_graph(text, name)
    problems: list[Diagnostic] = []
    if not has_errors(parsed.diagnostics):
        for index in range(len(parsed.blocks)):
            problems += check_block(parsed, index)
    return GraphReadOut(
        blocks=parsed.blocks,
        diagnostics=parsed.diagnostics,
        problems=problems,
        places=parsed.places,
    )


@router.post(
    "/read",
    response_model=GraphReadOut,
    responses={
        413: {"model": ApiErrorBody, "description": "Text too large (API110)"},
        422: {"model": ApiErrorBody, "description": "Invalid request (API103)"},
    },
    summary="Read an S7-Graph source as the sequencer model",
)
async def read_graph(body: GraphReadIn) -> GraphReadOut:
    text = checked_text(body.name, body.text)
    return await asyncio.to_thread(_read, body.name, text)
