"""A dialect's own model of its source, kept with the Program it lowered to (`Program.model`).

A family whose source is not an instruction list (S7's network graph) draws its networks from
that model, one drawn network per source network, instead of laying out the engine's
instructions; a changed drawing is turned back into the model and lowered again, and Save
writes it into the file it was read from (the dialect's writer). One ladder model serves every
family: the drawn networks are LadderNetworks (named box pins, operand texts).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

if TYPE_CHECKING:
    from pathlib import Path

    from ladderworks.core.address import Address
    from ladderworks.core.diagnostics import Diagnostic
    from ladderworks.core.il.program import Program
    from ladderworks.core.ladder.model import Element, LadderNetwork


@runtime_checkable
class SourceModel(Protocol):
    """What the console asks of a dialect's model of its source."""

    def draw(self) -> list[LadderNetwork]:
        """One drawn network per source network, in order."""
        ...

    def spans(self) -> list[range]:
        """The program's engine networks each drawn network lowered to (same order)."""
        ...

    def titles(self) -> list[str]:
        """The title of each source network ("" for none), in order."""
        ...

    def rebuild(self, networks: list[LadderNetwork]) -> tuple[Program, list[Diagnostic]]:
        """The program of a drawing (networks changed, added or removed), lowered again; its
        `model` is the model of the new drawing."""
        ...

    def operand(self, text: str) -> tuple[str, Address | None] | Diagnostic:
        """A bit operand typed on a contact or coil: as the source writes it and its engine
        address, or why it is none."""
        ...

    def palette(self, name: str) -> Element | None:
        """The element a palette row places in this program (None: the row's own box)."""
        ...

    def operands(self, element: Element) -> list[tuple[str, str]]:
        """An element's operands to edit: (name, text as written) in order."""
        ...

    def with_operands(self, element: Element, texts: list[str]) -> Element:
        """The element with its operands (in the order of `operands`) set."""
        ...

    def label(self, text: str) -> str | Diagnostic:
        """A jump label typed for a network, as the source writes it, or why it is none."""
        ...

    def source_file(self) -> Path | None:
        """The file the drawn source was read from (a folder's entry block's), else None."""
        ...


def source_model(program: Program | None) -> SourceModel | None:
    """The program's model of its source when its dialect keeps one that draws, else None."""
    model = program.model if program is not None else None
    return model if isinstance(model, SourceModel) else None


def source_networks(program: Program) -> list[tuple[int, str]] | None:
    """The source network each engine network of `program` lowers from, as (number from 1,
    title): a block called from a network and lowered inline there counts as that network;
    (0, "") before the first (the start values); None when the program keeps no source model."""
    model = source_model(program)
    if model is None:
        return None
    titles = model.titles()
    found: list[tuple[int, str] | None] = [None] * len(program.networks)
    for number, span in enumerate(model.spans(), start=1):
        title = titles[number - 1] if number <= len(titles) else ""
        for index in span:
            if index < len(found):
                found[index] = (number, title)
    last = (0, "")  # a network in no span: the start values, a label after the last network
    for index, here in enumerate(found):
        last = here or last
        found[index] = last
    return [here or (0, "") for here in found]


def source_file(program: Program | None) -> Path | None:
    """The file a program drawn from its model was read from (a folder's entry block's)."""
    model = source_model(program)
    return model.source_file() if model is not None else None
