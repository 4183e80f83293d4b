"""The S7 program's own model kept with its Program (`Program.model`): the graph, the memory
layout, the entry block lowered, each network's engine networks and the lowering's record.

It draws the entry block's networks as TIA draws LAD (drawing.py) and rebuilds the Program
from a changed drawing: each changed network read back from the grid (from_grid.py), the
block's networks replaced and lowered again (core/ladder/source_model.py is the contract).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7 import palette
from ladderworks.core.dialects.s7.drawing import Context, Emitted, NotDrawn, draw_network
from ladderworks.core.dialects.s7.graph import Block, Operand, OperandKind, S7Network, S7Program
from ladderworks.core.dialects.s7.layout import Layout
from ladderworks.core.dialects.s7.lowering import BlockLowering, start_values
from ladderworks.core.il.program import Network, Program
from ladderworks.core.ladder.model import Coil, Contact, Element, LadderNetwork

Finish = Callable[[Program, S7Program, Layout, Block], None]  # names the program's symbols


@dataclass(slots=True)
class Lowered:
    """A block lowered: the engine's networks, diagnostics, each S7 network's engine networks
    (offset by the start values network) and the record of each part."""

    networks: list[Network]
    diagnostics: list[Diagnostic]
    spans: list[range]
    emitted: Emitted = field(default_factory=dict)


def lower(block: Block, layout: Layout) -> Lowered:
    """A block's networks for the engine (the start values first) with what the drawing maps
    back (`lowering.lower_block` keeps the plain form)."""
    lowering = BlockLowering(block, layout)
    networks = lowering.run()
    first = start_values(layout)
    shift = 1 if first is not None else 0
    spans = [range(s.start + shift, s.stop + shift) for s in lowering.spans]
    return Lowered(([first] if first is not None else []) + networks, lowering.diagnostics,
                   spans, dict(lowering.emitted))


def network_comments(network: S7Network) -> list[str]:
    """The lines shown above a drawn network: its title, then its comment."""
    lines = network.comment.splitlines()
    return [network.title, *lines] if network.title or lines else []


@dataclass(eq=False, slots=True)
class S7Model:
    """An S7 program's model of its source (the SourceModel of core/ladder/source_model.py)."""

    graph: S7Program
    layout: Layout
    entry: Block
    lowered: Lowered
    finish: Finish | None = None
    drawn: list[LadderNetwork] = field(default_factory=list)  # as first drawn, to compare

    @property
    def scope(self) -> tuple[str, ...]:
        return (f"#{self.entry.name.lower()}",)

    def resolve(self, operand: Operand) -> Address | None:
        """The engine address of an operand in the entry block (None when it names none)."""
        place = self.layout.resolve(self.entry, operand, "", self.scope)
        return place.address if place is not None else None

    def operand(self, text: str) -> tuple[str, Address | None] | Diagnostic:
        """A bit operand typed on a contact or coil ("Start", Start, #Run, %I0.1, "DB".x)."""
        from ladderworks.core.dialects.s7.from_grid import operand_from_text

        operand = operand_from_text(text)
        if operand.kind is OperandKind.LOCAL and not text.strip().startswith("#") and \
                self.entry.member(operand.path[0]) is None:  # a bare tag name: "Start"
            operand = Operand(OperandKind.GLOBAL, operand.path, text.strip())
        address = self.resolve(operand)
        if address is None or address.bit is None:
            return Diagnostic("s7-address", {"text": text.strip()}, 0, 0)
        return operand.display(), address

    def palette(self, name: str) -> Element | None:
        """What an S7 palette row places (palette.py)."""
        return palette.new_element(name)

    def operands(self, element: Element) -> list[tuple[str, str]]:
        """The element's operands by name, as written."""
        return list(zip(palette.operand_names(element), palette.operand_texts(element),
                        strict=False))

    def with_operands(self, element: Element, texts: list[str]) -> Element:
        """The element with its operands set (an operand on a contact or coil resolved)."""
        changed = palette.with_operands(element, texts)
        plain = isinstance(changed, Coil) or (isinstance(changed, Contact)
                                              and not changed.function)
        if isinstance(changed, Contact | Coil) and plain and changed.texts and not changed.mark:
            found = self.operand(changed.texts[0])
            if not isinstance(found, Diagnostic):
                changed = replace(changed, texts=(found[0], *changed.texts[1:]),
                                  address=found[1])
        return changed

    def draw(self) -> list[LadderNetwork]:
        """One drawn network per S7 network of the entry block."""
        nets: list[LadderNetwork] = []
        fbs = {b.name.lower(): b.instance_of for b in self.graph.blocks if b.instance_of}
        for index, network in enumerate(self.entry.networks, start=1):
            context = Context(self.resolve, self.lowered.emitted, index, fbs)
            try:
                drawn = draw_network(network, context)
            except NotDrawn:
                span = self.span(index - 1)
                listing = tuple(ins for n in span for ins in self.lowered.networks[n].instructions)
                source = tuple(network.source.splitlines()) if network.source else ()
                drawn = LadderNetwork(listing=listing)
                drawn.comments = list(source)
            drawn.comments = network_comments(network) + drawn.comments
            nets.append(drawn)
        self.drawn = [n.copy() for n in nets]
        for copy, net in zip(self.drawn, nets, strict=True):
            copy.label = net.label
        return nets

    def span(self, index: int) -> range:
        spans = self.lowered.spans
        return spans[index] if index < len(spans) else range(0)

    def spans(self) -> list[range]:
        """The engine networks of each drawn network."""
        return [self.span(i) for i in range(len(self.entry.networks))]

    def rebuild(self, networks: list[LadderNetwork]) -> tuple[Program, list[Diagnostic]]:
        """The program of a drawing: unchanged networks as read, changed ones from the grid,
        the block lowered again."""
        from ladderworks.core.dialects.s7.from_grid import GridError, network_from_grid

        new: list[S7Network] = []
        problems: list[Diagnostic] = []
        free = list(range(len(self.drawn)))
        for net in networks:
            same = next((i for i in free if self.drawn[i] == net
                         and self.drawn[i].label == net.label), None)
            if same is not None and same < len(self.entry.networks):
                free.remove(same)
                new.append(self.entry.networks[same])
            else:
                try:
                    new.append(network_from_grid(net, self.entry, len(new) + 1))
                except GridError as error:
                    problems.append(error.diagnostic)
                    new.append(S7Network(title=net.comments[0] if net.comments else ""))
        block = replace(self.entry, networks=new)
        blocks = [block if b is self.entry else b for b in self.graph.blocks]
        graph = S7Program(blocks, self.graph.tags)
        program, found = program_of(graph, self.layout, block, self.finish)
        return program, problems + found


def program_of(graph: S7Program, layout: Layout, entry: Block | None,
               finish: Finish | None = None) -> tuple[Program, list[Diagnostic]]:
    """The Program of the entry block of `graph`, with its model (S7Model) kept."""
    program = Program(dialect="s7")
    if entry is None:
        return program, []
    lowered = lower(entry, layout)
    program.networks = lowered.networks
    program.title = {1: entry.name}
    if finish is not None:
        finish(program, graph, layout, entry)
    program.model = S7Model(graph, layout, entry, lowered, finish)
    return program, lowered.diagnostics
