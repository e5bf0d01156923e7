"""``fast_init``: a faster ``__init__`` for the frozen, slotted dataclasses of the IR.

The ``__init__`` that ``dataclass`` writes for a frozen class sets each field through
``object.__setattr__`` (the class refuses plain assignment), which makes an ``Origin`` cost as much
as four ``Instruction``s. This one calls each slot's own setter instead, about twice as fast; a
compilation makes 100,000s of origins and operands. The class stays what ``dataclass`` made of it:
the same parameters and defaults, equality, hash, repr and immutability.
"""

from __future__ import annotations

from dataclasses import MISSING, fields
from typing import Any, TypeVar

T = TypeVar("T")


def fast_init(cls: type[T]) -> type[T]:
    """Gives ``cls``, a ``dataclass(frozen=True, slots=True)`` whose fields have plain defaults
    (no ``default_factory``, no ``__post_init__``), the faster ``__init__``."""
    namespace: dict[str, Any] = {}
    params: list[str] = []
    body: list[str] = []
    for item in fields(cls):  # type: ignore[arg-type]  # a dataclass, as documented
        assert item.init, item.name
        assert item.default_factory is MISSING, item.name
        namespace[f"_set_{item.name}"] = cls.__dict__[item.name].__set__  # the slot's setter
        if item.default is MISSING:
            params.append(item.name)
        else:
            namespace[f"_default_{item.name}"] = item.default
            params.append(f"{item.name}=_default_{item.name}")
        body.append(f"    _set_{item.name}(self, {item.name})\n")
    assert not hasattr(cls, "__post_init__"), cls
    exec(f"def __init__(self, {', '.join(params)}):\n{''.join(body)}", namespace)
    init = namespace["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__module__ = cls.__module__
    cls.__init__ = init  # type: ignore[method-assign]
    return cls
