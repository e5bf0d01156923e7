"""``/api/plants``: the catalogue of virtual plants a project or a lesson can attach.

Each kind with its signals (direction seen from the PLC, bit or word, NC contacts), its faults
(raised by the process, or injectable), its parameters with their defaults and the course's
usual wiring, so the plant file editor, the drawings and the lesson authors use one source.
Titles and descriptions are English; the front end names plants and signals in the user's
language by ``kind`` and signal name. ``POST /api/plants/check`` reads a ``.plant`` file's text
as a download would (``nasaq.plants.plant_file``): the configuration, or its problem with the
line, for the editor to mark before the user downloads.
"""

from __future__ import annotations

from typing import Literal

from fastapi import APIRouter
from pydantic import BaseModel, Field

from nasaq.diagnostics import Diagnostic
from nasaq.plants.plant_file import MAX_PLANT_CHARS, PlantFileError, read_plant_file
from nasaq.plants.registry import plants
from nasaq.plants.runtime import PlantConfig

router = APIRouter(prefix="/plants", tags=["plants"])


class PlantSignalOut(BaseModel):
    name: str
    direction: Literal["sensor", "control", "actuator"]
    kind: Literal["bool", "word"]
    normally_closed: bool = Field(description="An NC contact: its input reads 1 at rest")
    description: str


class PlantFaultOut(BaseModel):
    code: str
    injectable: bool = Field(description="Injected by a lesson or the learner (else raised)")
    description: str


class PlantKindOut(BaseModel):
    kind: str
    title: str
    signals: list[PlantSignalOut]
    faults: list[PlantFaultOut]
    defaults: dict[str, float] = Field(description="The parameters and their default values")
    default_wiring: dict[str, str] = Field(description="signal -> address, the course's usual I/O")


def catalogue() -> list[PlantKindOut]:
    return [
        PlantKindOut(
            kind=kind,
            title=plant.title,
            signals=[
                PlantSignalOut(
                    name=s.name,
                    direction=s.direction,
                    kind=s.kind,
                    normally_closed=s.normally_closed,
                    description=s.description,
                )
                for s in plant.signals
            ],
            faults=[
                PlantFaultOut(code=f.code, injectable=f.injectable, description=f.description)
                for f in plant.faults
            ],
            defaults=dict(plant.defaults),
            default_wiring=dict(plant.default_wiring),
        )
        for kind, plant in plants().items()
    ]


@router.get(
    "",
    response_model=list[PlantKindOut],
    summary="The virtual plants: signals, faults, parameters and usual wiring of each kind",
)
def list_plants() -> list[PlantKindOut]:
    return catalogue()


class PlantFileText(BaseModel):
    name: str = Field(default="plant.plant", min_length=1, max_length=128)
    text: str = Field(max_length=MAX_PLANT_CHARS, description="The text of the .plant file")


class PlantFileCheck(BaseModel):
    config: PlantConfig | None = Field(description="The configuration (null: it has a problem)")
    diagnostics: list[Diagnostic] = Field(description="The file's problem, with its line")


@router.post(
    "/check",
    response_model=PlantFileCheck,
    summary="What a .plant file's text means: its configuration or its problem by line",
)
def check_plant_file(body: PlantFileText) -> PlantFileCheck:
    try:
        return PlantFileCheck(config=read_plant_file(body.name, body.text), diagnostics=[])
    except PlantFileError as error:
        return PlantFileCheck(config=None, diagnostics=[error.diagnostic])
