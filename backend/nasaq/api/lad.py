"""``POST /api/lad/read``: a LAD/FBD file read as the network model, as it is (each block in its own
language), with the reader's problems only: the graphical editors draw what it gives, and refuse
to draw (saying why) a text with syntax errors."""

from __future__ import annotations

import asyncio

from fastapi import APIRouter
from pydantic import BaseModel, Field

from nasaq.api.errors import ApiErrorBody
from nasaq.api.files import checked_text
from nasaq.diagnostics import Diagnostic
from nasaq.lang.lad.model import LadBlock
from nasaq.lang.lad.text import parse_lad

router = APIRouter(prefix="/lad", tags=["convert"])


class LadReadIn(BaseModel):
    name: str = Field(max_length=128, description="The file name (.fbd: FBD is the default view)")
    text: str


class LadReadOut(BaseModel):
    blocks: list[LadBlock] = Field(description="The blocks the reader made of the text")
    diagnostics: list[Diagnostic] = Field(description="The text's syntax problems (LAD1xx)")


@router.post(
    "/read",
    response_model=LadReadOut,
    responses={
        413: {"model": ApiErrorBody, "description": "Text too large (API110)"},
        422: {"model": ApiErrorBody, "description": "Invalid request (API103)"},
    },
    summary="Read a LAD/FBD source as the network model",
)
async def read_lad(body: LadReadIn) -> LadReadOut:
    text = checked_text(body.name, body.text)
    blocks, diagnostics = await asyncio.to_thread(parse_lad, text, body.name)
    return LadReadOut(blocks=blocks, diagnostics=diagnostics)
