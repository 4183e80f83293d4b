"""Series, parallel and fan-out structures of drawn parts placed on a ladder grid.

`drawing.py` turns an S7 network's graph into these structures; this module only places them:
an `Item` is one element (a contact, a coil in line, a box with the chains feeding its other
pins) or a parallel block of series branches; a `Branch` is a series of items that ends in a
coil at the coil column or fans out into further branches (one wire to several outputs).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.ladder.model import (
    DEFAULT_COLUMNS,
    MAX_COLUMNS,
    MAX_ROWS,
    WIRE,
    Cell,
    Coil,
    Element,
    FunctionBox,
    LadderNetwork,
)


class Clash(Exception):
    """The structure does not fit the grid (two elements in one cell, too wide, too tall)."""


@dataclass(eq=False, slots=True)
class Item:
    """One element in series, or (`branches`) a parallel block of series branches."""

    element: Element | None = None
    branches: list[list[Item]] = field(default_factory=list)
    sides: dict[int, list[Item]] = field(default_factory=dict)  # a box's pin row -> its chain
    lead: int = 0  # wire columns before a box (its input operands are written there)
    trail: int = 0  # wire columns after a box (its output operands)
    wired: bool = True  # a box's output goes on to further elements


@dataclass(eq=False, slots=True)
class Branch:
    """A series of items, then a coil at the coil column or further branches."""

    items: list[Item] = field(default_factory=list)
    children: list[Branch] = field(default_factory=list)
    coil: Coil | None = None


def seq_size(items: list[Item]) -> tuple[int, int]:
    """(columns, rows) a series of items takes."""
    sizes = [item_size(item) for item in items]
    return sum(w for w, _ in sizes), max([1, *(h for _, h in sizes)])


def item_size(item: Item) -> tuple[int, int]:
    """(columns, rows) one item takes."""
    if item.element is None:
        sizes = [seq_size(branch) for branch in item.branches]
        return max([0, *(w for w, _ in sizes)]), sum(h for _, h in sizes) or 1
    if isinstance(item.element, FunctionBox):
        box = item.element
        side = max([0, *(seq_size(chain)[0] for chain in item.sides.values())])
        lead = max(item.lead, side)
        item.lead = lead
        return lead + box.width + item.trail, box.height
    return 1, 1


def branch_width(branch: Branch) -> int:
    """Columns the widest path of a branch takes before its coil."""
    own = seq_size(branch.items)[0]
    return own + max([0, *(branch_width(child) for child in branch.children)])


class Placer:
    """Puts items on a network's grid, refusing a cell taken twice."""

    def __init__(self, network: LadderNetwork) -> None:
        self.net = network

    def put(self, cell: Cell, element: Element) -> None:
        row, col = cell
        if row >= MAX_ROWS or col > self.net.columns:
            raise Clash(cell)
        cells = [cell] if not isinstance(element, FunctionBox) else \
            [(row + r, col + c) for r in range(element.height) for c in range(element.width)]
        if any(self.net.element_at(*c) is not None for c in cells):
            raise Clash(cell)
        self.net.cells[cell] = element

    def wires(self, row: int, first: int, last: int) -> None:
        """Wires in the cells first … last-1 of a row."""
        for col in range(first, last):
            self.put((row, col), WIRE)

    def link(self, node: int, top: int, bottom: int) -> None:
        """A vertical link at `node` from row `top` down to row `bottom` (none on the rail)."""
        if node == 0:
            return
        for row in range(top, bottom):
            self.net.links.add((row, node))

    def seq(self, items: list[Item], row: int, col: int) -> tuple[int, int]:
        """Place a series; (the node after it, the row below it)."""
        bottom = row + 1
        for item in items:
            width, height = item_size(item)
            self.item(item, row, col)
            col += width
            bottom = max(bottom, row + height)
        return col, bottom

    def item(self, item: Item, row: int, col: int) -> None:
        element = item.element
        if element is None:
            width = item_size(item)[0]
            rows: list[int] = []
            at = row
            for branch in item.branches:
                rows.append(at)
                end, at = self.seq(branch, at, col)
                self.wires(rows[-1], end, col + width)
            self.link(col, row, rows[-1])
            self.link(col + width, row, rows[-1])
            return
        if not isinstance(element, FunctionBox):
            self.put((row, col), element)
            return
        self.wires(row, col, col + item.lead)
        self.put((row, col + item.lead), element)
        if element.has_output and item.wired:  # its output goes on along the rung
            self.wires(row, col + item.lead + element.width,
                       col + item.lead + element.width + item.trail)
        for offset, chain in item.sides.items():
            width = seq_size(chain)[0]
            start = col + item.lead - width
            self.wires(row + offset, 0, start)
            self.seq(chain, row + offset, start)

    def branch(self, branch: Branch, row: int, col: int) -> int:
        """Place a branch; the row below it."""
        end, bottom = self.seq(branch.items, row, col)
        if branch.coil is not None:
            self.wires(row, end, self.net.columns)
            self.put((row, self.net.columns), branch.coil)
            return bottom
        at = row
        for index, child in enumerate(branch.children):
            if index:
                self.link(end, row, at)
            at = self.branch(child, at, end)
        return max(bottom, at)


def place(root: Branch, network: LadderNetwork) -> None:
    """Lay a rung out on `network` (its columns widened to fit); Clash when it cannot be."""
    needed = branch_width(root) + 1
    if needed > MAX_COLUMNS:
        raise Clash("too wide")
    network.columns = max(DEFAULT_COLUMNS, needed)
    bottom = Placer(network).branch(root, 0, 0)
    network.rows = max(1, bottom, network.used_rows())
