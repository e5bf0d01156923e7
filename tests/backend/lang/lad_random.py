"""Random LAD networks for property tests of the LAD views (FBD, layout): seeded, so a failure
names the seed that reproduces it. Every shape of the model appears: contacts, status bits, NOT,
edges, midlines, boxes with logic in their pins, parallels nested in parallels, empty branches,
several outputs with their own conditions."""

from __future__ import annotations

from random import Random

from nasaq.lang.lad.model import (
    Box,
    Coil,
    Contact,
    EdgeContact,
    Element,
    Final,
    Invert,
    Jump,
    Midline,
    Network,
    OpenDb,
    Output,
    Parallel,
    Return,
    Series,
    StatusContact,
)


class RandomNetworks:
    def __init__(self, seed: int, pure: bool = False) -> None:
        """``pure``: only contacts, NOT and parallels, whose truth value a test can compute."""
        self.rng = Random(seed)
        self.pure = pure
        self.count = 0

    def ident(self) -> str:
        self.count += 1
        return f"e{self.count}"

    def operand(self) -> str:
        return self.rng.choice(["I 0.0", "I 0.1", "I 0.2", "M 1.0", "#run", '"Stop"'])

    def series(self, depth: int, longest: int = 4) -> Series:
        return Series(elements=[self.element(depth) for _ in range(self.rng.randint(0, longest))])

    def element(self, depth: int) -> Element:
        kinds = ["contact", "contact", "contact", "not", "parallel"]
        if not self.pure:
            kinds += ["status", "edge", "midline", "box"]
        kind = self.rng.choice(kinds if depth < 3 else ["contact", "not"])
        ident = self.ident()
        if kind == "contact":
            return Contact(id=ident, operand=self.operand(), negated=self.rng.random() < 0.3)
        if kind == "not":
            return Invert(id=ident)
        if kind == "parallel":
            count = self.rng.randint(2, 3)
            return Parallel(id=ident, branches=[self.series(depth + 1, 3) for _ in range(count)])
        if kind == "status":
            return StatusContact(id=ident, bit=self.rng.choice(["OV", "==0", "BR"]))
        if kind == "edge":
            return EdgeContact(id=ident, edge=self.rng.choice(["P", "N"]), memory="M 9.0")
        if kind == "midline":
            return Midline(id=ident, operand="M 2.0")
        return self.box(ident, depth)

    def box(self, ident: str, depth: int) -> Box:
        name = self.rng.choice(["MOVE", "S_ODT", "SR", "ADD_I", "CMP>=I", "POS", "FC 10"])
        inputs: dict[str, str | Series] = {"IN": "MW 10"}
        if name in ("S_ODT", "SR") and depth < 3:
            inputs["R"] = self.series(depth + 1, 2)
        outputs = {"OUT": "MW 12", "Q": "M 3.0"} if self.rng.random() < 0.5 else {}
        return Box(
            id=ident,
            name=name,
            instance="T 1" if name == "S_ODT" else None,
            inputs=inputs,
            outputs=outputs,
        )

    def target(self) -> Final:
        ident = self.ident()
        kind = self.rng.choice(
            ["coil", "coil", "coil"] if self.pure else ["coil", "coil", "jump", "ret", "opn", "box"]
        )
        if kind == "coil":
            coil = self.rng.choice(["=", "S", "R"] if self.pure else ["=", "S", "R", "SD", "SAVE"])
            value = "S5T#2S" if coil == "SD" else None
            operand = "" if coil == "SAVE" else self.rng.choice(["Q 4.0", "Q 4.1", "M 5.0"])
            return Coil(id=ident, coil=coil, operand=operand, value=value)
        if kind == "jump":
            return Jump(id=ident, label="NEXT", negated=self.rng.random() < 0.5)
        if kind == "ret":
            return Return(id=ident)
        if kind == "opn":
            return OpenDb(id=ident, block="DB 5")
        return self.box(ident, 1)

    def network(self) -> Network:
        logic = self.series(0)
        count = self.rng.randint(1, 3)
        outputs = [Output(conditions=self.series(1, 2), target=self.target()) for _ in range(count)]
        return Network(
            title="random", label=self.rng.choice([None, "M001"]), logic=logic, outputs=outputs
        )


def element_ids(network: Network) -> list[str]:
    """Every element id of the network, targets included, in reading order."""
    found: list[str] = []

    def series(items: Series) -> None:
        for element in items.elements:
            found.append(element.id)
            if isinstance(element, Parallel):
                for branch in element.branches:
                    series(branch)
            if isinstance(element, Box):
                box(element)

    def box(element: Box) -> None:
        for value in element.inputs.values():
            if isinstance(value, Series):
                series(value)

    series(network.logic)
    for output in network.outputs:
        series(output.conditions)
        found.append(output.target.id)
        if isinstance(output.target, Box):
            box(output.target)
    return found
