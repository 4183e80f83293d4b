"""Rungs that wire themselves: where a placed element goes and the wires that join it up."""

from __future__ import annotations

from ladderworks.core.ladder.model import (
    WIRE,
    Cell,
    Coil,
    Contact,
    Element,
    FunctionBox,
    LadderNetwork,
    Wire,
)


def target_cell(network: LadderNetwork, row: int, col: int, element: Element) -> Cell:
    """Where a placing tool puts `element` clicked at (row, col).

    A coil goes to the coil column; a box with control inputs is right-aligned before it (its
    W1 at the coil column, as the layout draws boxes); a box without inputs (END1, JMPE, …)
    sits on the left rail. Contacts and wires stay where they are clicked."""
    if isinstance(element, Coil):
        return row, network.coil_column
    if isinstance(element, FunctionBox):
        return row, (network.columns - element.width if element.inputs else 0)
    return row, col


def _touches_link(network: LadderNetwork, row: int, node: int) -> bool:
    """True when a vertical link meets node (row, node) from above or below."""
    return (row, node) in network.links or (row - 1, node) in network.links


def _joins_right(network: LadderNetwork, row: int, col: int) -> bool | None:
    """Whether what covers cell (row, col) has a terminal on its right edge at `row`
    (None: the cell is empty)."""
    found = network.element_at(row, col)
    if found is None:
        return None
    (r, c), element = found
    if isinstance(element, FunctionBox):
        return c + element.width - 1 == col and (
            (r == row and element.has_output)
            or any(r + offset == row for offset, _ in element.outputs))
    return isinstance(element, Contact | Wire)


def _joins_left(network: LadderNetwork, row: int, col: int) -> bool | None:
    """Whether what covers cell (row, col) has a terminal on its left edge at `row`
    (None: the cell is empty)."""
    found = network.element_at(row, col)
    if found is None:
        return None
    (r, c), element = found
    if isinstance(element, FunctionBox):
        return c == col and (row - r) in element.pins
    return True


def _fill(network: LadderNetwork, row: int, first: int, last: int) -> None:
    """Wires in the cells first..last (inclusive) of a row."""
    for col in range(first, last + 1):
        network.cells[(row, col)] = WIRE


def _reach_left(network: LadderNetwork, row: int, node: int, to_rail: bool) -> bool:
    """Wire node (row, node) leftwards to the nearest element or link on its row (or to the
    rail when `to_rail`); True when it got joined to something."""
    for k in range(node, 0, -1):
        if _touches_link(network, row, k):
            _fill(network, row, k, node - 1)
            return True
        joins = _joins_right(network, row, k - 1)
        if joins is not None:
            if joins:
                _fill(network, row, k, node - 1)
            return joins
    if node == 0 or to_rail:
        _fill(network, row, 0, node - 1)
        return True
    return False


def _reach_right(network: LadderNetwork, row: int, node: int) -> bool:
    """Wire node (row, node) rightwards to the nearest element or link on its row; True when
    it got joined to something (nothing is drawn when the row is empty to the coil column)."""
    for k in range(node, network.coil_column + 1):
        if _touches_link(network, row, k):
            _fill(network, row, node, k - 1)
            return True
        joins = _joins_left(network, row, k)
        if joins is not None:
            if joins:
                _fill(network, row, node, k - 1)
            return joins
    return False


def _extend_branch(network: LadderNetwork, row: int, col: int) -> None:
    """A contact placed just after the end of a parallel branch lengthens the branch: its
    closing vertical moves from the contact's left end to its right end (when the row above
    runs on past it, so the branch still closes on something)."""
    if row == 0 or col + 1 > network.columns:
        return
    if (row - 1, col) not in network.links or (row, col) in network.links:
        return
    if (row - 1, col + 1) in network.links or (row, col + 1) in network.links:
        return
    before = network.cells.get((row, col - 1)) if col else None
    above = network.cells.get((row - 1, col))
    if not isinstance(before, Contact | Wire) or not isinstance(above, Contact | Wire):
        return
    network.links.discard((row - 1, col))
    network.links.add((row - 1, col + 1))


def connect(network: LadderNetwork, anchor: Cell, element: Element) -> None:
    """Join a just-placed element to its neighbours on its rows with wires.

    A contact is wired to the nearest element or vertical link on its left and right (and to
    the left rail on the first row, or when it leads to something on its right); a coil to
    the logic on its left; a box's control inputs to the logic on their rows. Only empty cells
    are filled, so nothing drawn is ever replaced."""
    row, col = anchor
    if isinstance(element, Contact):
        _extend_branch(network, row, col)
        right = _reach_right(network, row, col + 1)
        _reach_left(network, row, col, to_rail=row == 0 or right)
    elif isinstance(element, Coil):
        _reach_left(network, row, col, to_rail=False)
    elif isinstance(element, FunctionBox) and element.inputs:
        for pin in element.pins:
            _reach_left(network, row + pin, col, to_rail=False)
        if element.has_output and col + element.width < network.coil_column:
            _reach_right(network, row, col + element.width)
