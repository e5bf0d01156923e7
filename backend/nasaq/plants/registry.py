"""Every plant by its ``kind``: each module of this package that defines a ``Plant`` subclass
with a ``kind`` is found here, so adding a plant is adding one module."""

from __future__ import annotations

import importlib
import pkgutil
from functools import cache

import nasaq.plants as package
from nasaq.plants.base import Plant, PlantError

_NOT_PLANTS = {"base", "registry", "wiring", "runtime", "plant_file"}


@cache
def plants() -> dict[str, type[Plant]]:
    found: dict[str, type[Plant]] = {}
    for module_info in pkgutil.iter_modules(package.__path__):
        if module_info.name in _NOT_PLANTS or module_info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{package.__name__}.{module_info.name}")
        for value in vars(module).values():
            if (
                isinstance(value, type)
                and issubclass(value, Plant)
                and value is not Plant
                and value.__module__ == module.__name__
                and "kind" in vars(value)
            ):
                if value.kind in found:
                    raise RuntimeError(f"two plants of kind '{value.kind}'")
                found[value.kind] = value
    return dict(sorted(found.items()))


def plant_class(kind: str) -> type[Plant]:
    found = plants().get(kind)
    if found is None:
        known = ", ".join(plants())
        raise PlantError(
            f"no plant of kind '{kind}' (known: {known})",
            "PLT002",
            ("kind",),
            kind=kind,
            known=known,
        )
    return found
