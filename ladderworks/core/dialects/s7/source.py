"""The S7 program's own model kept with its Program (`Program.model`): the graph, the memory
layout, the entry block lowered, each network's engine networks, the lowering's record and the
entry block's file as read (as_read.py: its bytes, form and networks' shapes, for Save).

It draws the entry block's networks as TIA draws LAD (drawing.py) and rebuilds the Program
from a changed drawing: each changed network read back from the grid (from_grid.py) naming the
file's network it replaces by its lines, the block's networks replaced and lowered again with
the same layout (core/ladder/source_model.py is the contract); saving.py writes the changed
networks into the file.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from difflib import SequenceMatcher
from pathlib import Path

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7 import palette
from ladderworks.core.dialects.s7.as_read import AsRead
from ladderworks.core.dialects.s7.drawing import Context, Emitted, NotDrawn, draw_network
from ladderworks.core.dialects.s7.graph import Block, Operand, OperandKind, S7Network, S7Program
from ladderworks.core.dialects.s7.layout import Layout
from ladderworks.core.dialects.s7.lowering import BlockLowering, start_values
from ladderworks.core.il.program import Network, Program
from ladderworks.core.ladder.model import Coil, Contact, Element, LadderNetwork

Finish = Callable[[Program, S7Program, Layout, Block], None]  # names the program's symbols
LABEL_NAME = re.compile(r"[^\W\d]\w*")  # a jump label: an identifier (letters, digits, _)


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
    """An S7 program's model of its source (the SourceModel of core/ladder/source_model.py):
    `read` is the entry block's file as read (None: built in memory), `unfinished` the indexes
    of the networks whose drawing is no S7 network yet (Save refuses them)."""

    graph: S7Program
    layout: Layout
    entry: Block
    lowered: Lowered
    finish: Finish | None = None
    drawn: list[LadderNetwork] = field(default_factory=list)  # as first drawn, to compare
    read: AsRead | None = None
    unfinished: tuple[int, ...] = ()

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

    def titles(self) -> list[str]:
        """The title of each S7 network of the entry block ("" for none)."""
        return [network.title for network in self.entry.networks]

    def spans(self) -> list[range]:
        """The engine networks of each drawn network."""
        return [self.span(i) for i in range(len(self.entry.networks))]

    def label(self, text: str) -> str | Diagnostic:
        """A jump label typed for a network (`Kucuk`, `AA_1`; "" none): an identifier as the
        SD text writes `Label( x )`, else `s7-label-name`."""
        text = text.strip()
        if not text or LABEL_NAME.fullmatch(text):
            return text
        return Diagnostic("s7-label-name", {"text": text}, 0, 0)

    def source_file(self) -> Path | None:
        """The entry block's file (None: read from a text or built in memory)."""
        return self.read.path if self.read is not None else None

    def changed(self) -> list[int]:
        """The indexes of the entry block's networks that are new or differ from the file's."""
        return self.read.changed(self.entry) if self.read is not None else \
            list(range(len(self.entry.networks)))

    def unchanged(self) -> bool:
        """True when the entry block holds its file's networks as read, in their order."""
        return self.read is not None and self.read.unchanged(self.entry)

    def rebuild(self, networks: list[LadderNetwork]) -> tuple[Program, list[Diagnostic]]:
        """The program of a drawing: unchanged networks as read, changed ones from the grid
        (each naming the network it replaces by its lines), the block lowered again with the
        same layout (so every address stays put)."""
        from ladderworks.core.dialects.s7.from_grid import GridError, network_from_grid

        new: list[S7Network] = []
        problems: list[Diagnostic] = []
        unfinished: list[int] = []
        old = self.entry.networks
        same, replaces = match_drawn(self.drawn[:len(old)], networks)
        for net, kept, replaced in zip(networks, same, replaces, strict=True):
            if kept is not None:
                new.append(old[kept])
                continue
            try:
                found = network_from_grid(net, self.entry, len(new) + 1)
            except GridError as error:
                problems.append(error.diagnostic)
                unfinished.append(len(new))
                found = S7Network(title=net.comments[0] if net.comments else "")
            if replaced is not None:  # the file's network it replaces (sd_save, xml_save)
                found.line, found.end_line = old[replaced].line, old[replaced].end_line
            new.append(found)
        block = replace(self.entry, networks=new)
        blocks = [block if b is self.entry else b for b in self.graph.blocks]
        graph = S7Program(blocks, self.graph.tags)
        program, found_problems = program_of(graph, self.layout, block, self.finish, self.read)
        if isinstance(program.model, S7Model):
            program.model.unfinished = tuple(unfinished)
        return program, problems + found_problems


def _key(network: LadderNetwork) -> object:
    """A network's drawing (and label) as a hashable value: equal drawings, equal keys."""
    state = network.state()
    try:
        hash(state)
    except TypeError:  # an element holding an unhashable value: its text form
        return repr(state)
    return state


def _opcodes(old: list[object], new: list[object]) -> list[tuple[str, int, int, int, int]]:
    """difflib's opcodes between two key lists, the common head and tail taken first."""
    head, limit = 0, min(len(old), len(new))
    while head < limit and old[head] == new[head]:
        head += 1
    tail = 0
    while tail < limit - head and old[-1 - tail] == new[-1 - tail]:
        tail += 1
    middle = SequenceMatcher(None, old[head:len(old) - tail], new[head:len(new) - tail],
                             autojunk=False).get_opcodes()
    codes = [("equal", 0, head, 0, head)] if head else []
    codes += [(tag, i1 + head, i2 + head, j1 + head, j2 + head)
              for tag, i1, i2, j1, j2 in middle]
    if tail:
        codes.append(("equal", len(old) - tail, len(old), len(new) - tail, len(new)))
    return codes


def match_drawn(old: list[LadderNetwork], new: list[LadderNetwork]
                ) -> tuple[list[int | None], list[int | None]]:
    """For each network of a drawing: the index of the network first drawn it still equals
    (None: changed or new) — in order, a moved one too — and for a changed one the first-drawn
    network it replaces: the one at its place among those changed (None: a new network)."""
    keys_old, keys_new = [_key(n) for n in old], [_key(n) for n in new]
    same: list[int | None] = [None] * len(new)
    pairs: list[tuple[int, int]] = []  # (new, old) at the same place of a changed stretch
    for tag, i1, i2, j1, j2 in _opcodes(keys_old, keys_new):
        if tag == "equal":
            same[j1:j2] = range(i1, i2)
        elif tag == "replace":
            pairs += [(j1 + k, i1 + k) for k in range(min(i2 - i1, j2 - j1))]
    used = {i for i in same if i is not None}
    free = [i for i in range(len(old)) if i not in used]
    for j, key in enumerate(keys_new):  # a network moved: still the one first drawn
        if same[j] is None:
            index = next((i for i in free if keys_old[i] == key), None)
            if index is not None:
                same[j] = index
                free.remove(index)
    replaces: list[int | None] = [None] * len(new)
    for j, i in pairs:
        if same[j] is None and i in free:
            replaces[j] = i
            free.remove(i)
    return same, replaces


def program_of(graph: S7Program, layout: Layout, entry: Block | None,
               finish: Finish | None = None, read: AsRead | None = None
               ) -> tuple[Program, list[Diagnostic]]:
    """The Program of the entry block of `graph`, with its model (S7Model) kept; `read`: the
    entry block's file as read."""
    program = Program(dialect="s7")
    if entry is None:
        return program, []
    lowered = lower(entry, layout)
    program.networks = lowered.networks
    program.title = {1: entry.name}
    if finish is not None:
        finish(program, graph, layout, entry)
    program.model = S7Model(graph, layout, entry, lowered, finish, read=read)
    return program, lowered.diagnostics
