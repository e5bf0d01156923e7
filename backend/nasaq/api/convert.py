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
from nasaq.lang.lad.fbd import FbdNetwork, to_fbd
from nasaq.lang.lad.layout import FbdLayout, LadLayout, fbd_layout, lad_layout
from nasaq.lang.lad.model import LadBlock, Network

router = APIRouter(tags=["convert"])


class ConvertIn(BaseModel):
    name: str = Field(max_length=128, description="The file name: its suffix says the language")
    text: str
    to: Target


class NetworkDrawing(BaseModel):
    """What an editor needs to draw one network without computing it again: to LAD the rung's
    grid (``lad``), to FBD the boxes and wires (``fbd``) and their layered layout
    (``fbd_layout``). A network kept as STL has empty layouts."""

    lad: LadLayout | None = None
    fbd: FbdNetwork | None = None
    fbd_layout: FbdLayout | None = None


def drawing(network: Network, to: Target) -> NetworkDrawing:
    if to == "lad":
        return NetworkDrawing(lad=lad_layout(network))
    view = to_fbd(network)
    return NetworkDrawing(fbd=view, fbd_layout=fbd_layout(view))


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
    drawings: list[list[NetworkDrawing]] | None = Field(
        description="To LAD or FBD: per block, per network (in the order of ``blocks``), the "
        "LAD grid, or the FBD boxes and wires with their layout; null for STL"
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
    return await asyncio.to_thread(_answer, body.name, text, body.to)


def _answer(name: str, text: str, to: Target) -> ConvertOut:
    result = convert(name, text, to)
    drawings = None
    if result.blocks is not None:
        drawings = [[drawing(net, to) for net in block.networks] for block in result.blocks]
    return ConvertOut(
        text=result.text,
        diagnostics=result.diagnostics,
        converted=result.converted,
        kept=result.kept,
        blocks=result.blocks,
        drawings=drawings,
    )
