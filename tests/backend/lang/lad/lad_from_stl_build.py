"""Terse builders for the STL → LAD lifter tests, and a one-network lift helper."""

from __future__ import annotations

from nasaq.lang.lad.from_stl import NotConvertible, lift_block
from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    LadBlock,
    Midline,
    Network,
    Output,
    Parallel,
    Series,
    StatusContact,
)


def c(operand: str, negated: bool = False) -> Contact:
    return Contact(operand=operand, negated=negated)


def nc(operand: str) -> Contact:
    return Contact(operand=operand, negated=True)


def st(bit: str, negated: bool = False) -> StatusContact:
    return StatusContact(bit=bit, negated=negated)  # type: ignore[arg-type]


def s(*elements: Element) -> Series:
    return Series(elements=list(elements))


def par(*branches: Series | Element) -> Parallel:
    return Parallel(branches=[b if isinstance(b, Series) else s(b) for b in branches])


def out(target: Final, *conditions: Element) -> Output:
    return Output(conditions=s(*conditions), target=target)


def coil(operand: str, kind: str = "=", value: str | None = None) -> Coil:
    return Coil(coil=kind, operand=operand, value=value)  # type: ignore[arg-type]


def box(name: str, instance: str | None = None, **pins: str | Series) -> Box:
    outputs = {k: v for k, v in pins.items() if k in OUT_PINS and isinstance(v, str)}
    inputs = {k: v for k, v in pins.items() if k not in outputs}
    return Box(name=name, instance=instance, inputs=inputs, outputs=outputs)


OUT_PINS = {"OUT", "ENO", "BI", "BCD", "CV", "CV_BCD", "RET_VAL", "Result"}


def net(*logic: Element, outputs: list[Output] | None = None, label: str | None = None) -> Network:
    return Network(logic=s(*logic), outputs=outputs or [out(coil("Q 4.0"))], label=label)


def ob1(*networks: Network, declarations: str = "") -> LadBlock:
    return LadBlock(kind="OB", name="OB 1", networks=list(networks), declarations=declarations)


def lift(code: str) -> Network | NotConvertible:
    """The only network of an OB 1 whose body is ``code`` (``;`` or newlines between)."""
    text = "ORGANIZATION_BLOCK OB 1\nBEGIN\nNETWORK\n" + code + "\nEND_ORGANIZATION_BLOCK\n"
    result = lift_block(text, "test.awl")
    [network] = result.blocks[0].networks
    return network


def plain(network: Network | NotConvertible) -> object:
    """A network without ids, title and comment (what the round trip compares)."""
    if isinstance(network, NotConvertible):
        return network.code
    return network.model_dump(exclude={"title", "comment"})


__all__ = [
    "EdgeContact",
    "Invert",
    "Midline",
    "box",
    "c",
    "coil",
    "lift",
    "nc",
    "net",
    "ob1",
    "out",
    "par",
    "plain",
    "s",
    "st",
]
