"""``POST /api/convert``: a source in another language, STL ↔ LAD ↔ FBD (see
``nasaq.lang.lad.convert``); the answer says which networks stayed STL and why."""

from __future__ import annotations

import asyncio

from fastapi import APIRouter
from pydantic import BaseModel, Field

from nasaq.api.errors import ApiErrorBody
from nasaq.api.files import checked_text
from nasaq.diagnostics import Diagnostic
from nasaq.lang.lad.convert import Target, convert
from nasaq.lang.lad.model import LadBlock

router = APIRouter(tags=["convert"])


class ConvertIn(BaseModel):
    name: str = Field(max_length=128, description="The file name: its suffix says the language")
    text: str
    to: Target


class ConvertOut(BaseModel):
    text: str = Field(description="The converted source; empty when the source has errors")
    diagnostics: list[Diagnostic] = Field(
        description="The source's problems, and (severity info) why each network kept as STL "
        "does not convert"
    )
    converted: int = Field(description="Networks shown as LAD/FBD rungs")
    kept: int = Field(description="Networks that stay STL")
    blocks: list[LadBlock] | None = Field(
        description="To LAD or FBD: the blocks as the network model (JSON of the same structure "
        "as the text); null for STL"
    )


@router.post(
    "/convert",
    response_model=ConvertOut,
    responses={
        413: {"model": ApiErrorBody, "description": "Text too large (API110)"},
        422: {"model": ApiErrorBody, "description": "Invalid request (API103)"},
    },
    summary="Convert a source between STL, LAD and FBD",
)
async def convert_source(body: ConvertIn) -> ConvertOut:
    text = checked_text(body.name, body.text)
    # Lifting a large block takes a while: in a thread, off the event loop.
    result = await asyncio.to_thread(convert, body.name, text, body.to)
    return ConvertOut(
        text=result.text,
        diagnostics=result.diagnostics,
        converted=result.converted,
        kept=result.kept,
        blocks=result.blocks,
    )
