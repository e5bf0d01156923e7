"""Helpers for the LAD → STL tests: build models tersely, lower, compile and run on the CPU."""

from __future__ import annotations

from nasaq.cpu import Cpu
from nasaq.headless.addresses import as_real, encode_value, parse_address, signed
from nasaq.ir import Direct
from nasaq.lang.lad.model import (
    Coil,
    CoilKind,
    Contact,
    Element,
    LadBlock,
    Network,
    Output,
    Parallel,
    Series,
)
from nasaq.lang.lad.to_stl import block_to_stl
from nasaq.lang.stl import SourceFile, compile_sources


def c(operand: str, negated: bool = False) -> Contact:
    return Contact(operand=operand, negated=negated)


def s(*elements: Element) -> Series:
    return Series(elements=list(elements))


def par(*branches: Series | Element) -> Parallel:
    return Parallel(branches=[b if isinstance(b, Series) else s(b) for b in branches])


def coil(operand: str, kind: CoilKind = "=") -> Output:
    return Output(target=Coil(coil=kind, operand=operand))


def net(*logic: Element, outputs: list[Output] | None = None, **kw: object) -> Network:
    return Network(logic=s(*logic), outputs=outputs or [coil("Q 4.0")], **kw)


def ob1(*networks: Network, declarations: str = "") -> LadBlock:
    return LadBlock(kind="OB", name="OB 1", networks=list(networks), declarations=declarations)


def stl_of(network: Network) -> list[str]:
    """The instruction lines of a one-network OB 1, without the block and network headers."""
    text, diagnostics = block_to_stl(ob1(network))
    assert not diagnostics, diagnostics
    lines = text.splitlines()
    return lines[lines.index("NETWORK") + 2 : -1]


def plc(block: LadBlock, *extra: str) -> Cpu:
    """Lowers ``block``, compiles it with ``extra`` STL sources, starts a CPU on it."""
    text, diagnostics = block_to_stl(block)
    assert not diagnostics, diagnostics
    sources = [SourceFile("lad.awl", text)]
    sources += [SourceFile(f"extra{i}.awl", src) for i, src in enumerate(extra)]
    result = compile_sources(sources)
    errors = [f"{d.code} {d.message}" for d in result.diagnostics if d.severity == "error"]
    assert not errors, (errors, text)
    cpu = Cpu(result.program)
    cpu.start()
    assert cpu.mode == "RUN", cpu.stop_reason
    return cpu


def where(address: str) -> Direct:
    found = parse_address(address)
    assert isinstance(found, Direct)
    return found


def put(cpu: Cpu, **values: int | float) -> None:
    """Sets inputs (``I0_1=1``) or memory (``MW0=5``, ``MD4=1.5``) for the next scan."""
    for name, value in values.items():
        address = where(name.replace("_", "."))
        if address.area.name == "I":
            cpu.set_input(address, encode_value(address, value))
        else:
            cpu.write(address, encode_value(address, value))


def get(cpu: Cpu, address: str, real: bool = False) -> int | float:
    found = where(address)
    raw = cpu.read(found)
    return as_real(raw) if real else signed(raw, found.width)


def scan(cpu: Cpu, count: int = 1) -> None:
    cpu.run(count)
    assert cpu.mode == "RUN", cpu.stop_reason
