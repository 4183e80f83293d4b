"""Edit operations on a ladder network; each applies its change and returns the exact inverse."""

from __future__ import annotations

from dataclasses import dataclass, replace

from ladderworks.core.address import Address, AddressError, parse_address
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError, Refused
from ladderworks.core.il.model_check import model_problem
from ladderworks.core.il.program import FANUC, ParamValue
from ladderworks.core.ladder.model import (
    MAX_ROWS,
    WIRE,
    Cell,
    Coil,
    Contact,
    Element,
    FunctionBox,
    LadderNetwork,
    NetworkState,
    Wire,
    flip,
)
from ladderworks.core.ladder.row_contacts import ALWAYS_ON, needs_lead
from ladderworks.core.ladder.wiring import connect, target_cell


class EditRefused(Refused):
    """An edit that cannot be made; `diagnostic` says why (show it, nothing was changed)."""

    def __init__(self, code: str, cell: Cell | None = None, **args: object) -> None:
        DiagnosticError.__init__(self, [Diagnostic(code, dict(args), cell=cell)])


@dataclass(frozen=True, slots=True)
class Edit:
    """A recorded change: `apply(network)` sets the recorded drawing and returns its inverse.

    Every operation below changes the network and returns the Edit that undoes it; applying
    that gives back the Edit that redoes it, and so on (a GUI undo command keeps one of them).
    """

    state: NetworkState

    def apply(self, network: LadderNetwork) -> Edit:
        """Make the change; return the inverse edit."""
        before = network.state()
        network.restore(self.state)
        return Edit(before)


def _change(network: LadderNetwork, work: LadderNetwork) -> Edit:
    """Move `network` to the drawing of `work`; return the undo edit."""
    return Edit(work.state()).apply(network)


def _check_cell(network: LadderNetwork, row: int, col: int) -> None:
    if not (0 <= row < MAX_ROWS and 0 <= col <= network.columns):
        raise EditRefused("edit-outside", (row, col), row=row, col=col)


def _grow(work: LadderNetwork, last_row: int) -> None:
    if last_row >= MAX_ROWS:
        raise EditRefused("edit-outside", (last_row, 0), row=last_row, col=0)
    work.rows = max(work.rows, last_row + 1)


def _clear(work: LadderNetwork, cells: list[Cell]) -> None:
    for cell in cells:
        found = work.element_at(*cell)
        if found is not None:
            del work.cells[found[0]]


def _put(work: LadderNetwork, row: int, col: int, element: Element) -> None:
    """Place an element in `work` (replacing whatever it covers), with the grid rules."""
    _check_cell(work, row, col)
    if isinstance(element, Contact | Wire) and col >= work.columns:
        raise EditRefused("edit-coil-column", (row, col), row=row, col=col)
    if isinstance(element, FunctionBox) and col + element.width > work.columns:
        raise EditRefused("edit-box-room", (row, col), name=element.name)
    cells = work.footprint((row, col), element)
    _grow(work, max(r for r, _ in cells))
    _clear(work, cells)
    work.cells[(row, col)] = element


def place(network: LadderNetwork, row: int, col: int, element: Element) -> Edit:
    """Put an element at a cell (replacing what is there); coils may go anywhere but are
    diagnosed unless in the coil column; contacts and wires only in contact columns."""
    work = network.copy()
    _put(work, row, col, element)
    return _change(network, work)


def place_wired(network: LadderNetwork, row: int, col: int, element: Element) -> Edit:
    """The placing tools: put an element where it belongs (a coil in the coil column, a box
    right-aligned before it; `wiring.target_cell`) and wire it to its neighbours."""
    row, col = target_cell(network, row, col, element)
    work = network.copy()
    _put(work, row, col, element)
    connect(work, (row, col), element)
    return _change(network, work)


def place_row_contact(network: LadderNetwork, row: int, col: int, contact: Contact) -> Edit:
    """Place a dialect's edge/comparison contact; one with only a series form (Fatek's TU)
    clicked on the rail's column goes after a SHORT contact there, as its text reads
    (`ORG TU X2`: SHORT, then TU); EditRefused when the next cell is taken."""
    if col != 0 or not contact.function or not needs_lead(contact.function):
        return place_wired(network, row, col, contact)
    if network.element_at(row, 1) not in (None, ((row, 1), WIRE)):
        raise EditRefused("contact-place", (row, 0), row=row, col=0)
    work = network.copy()
    _put(work, row, 0, Contact(ALWAYS_ON))
    connect(work, (row, 0), work.cells[(row, 0)])
    _put(work, row, 1, contact)
    connect(work, (row, 1), contact)
    return _change(network, work)


def replace_element(network: LadderNetwork, row: int, col: int, element: Element) -> Edit:
    """Replace the element covering a cell with another (same as `place` at its anchor)."""
    found = network.element_at(row, col)
    anchor = found[0] if found else (row, col)
    work = network.copy()
    if found:
        del work.cells[anchor]
    _put(work, anchor[0], anchor[1], element)
    return _change(network, work)


def delete(network: LadderNetwork, row: int, col: int) -> Edit:
    """Remove the element covering a cell (a whole box)."""
    found = network.element_at(row, col)
    if found is None:
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    work = network.copy()
    del work.cells[found[0]]
    return _change(network, work)


def invert(network: LadderNetwork, row: int, col: int) -> Edit:
    """The NOT tool: a normally open contact becomes normally closed (and back); same for coils."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], Contact | Coil):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    if isinstance(found[1], Contact) and found[1].function:  # no NC edge/comparison contact
        raise EditRefused("edit-row-contact", (row, col), row=row, col=col)
    work = network.copy()
    work.cells[found[0]] = flip(found[1])
    return _change(network, work)


def add_parallel(network: LadderNetwork, row: int, col: int,
                 element: Contact | Coil | None = None) -> Edit:
    """The OR tool: a contact (or coil) parallel to the one at the cell, on the row below.

    A row is inserted below when the cell under it is taken. Vertical links join both ends
    (for a coil: its left end only, the right rail joins the other)."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], Contact | Coil):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    (row, col), old = found
    new = element if element is not None else (
        Coil(write=old.write, row=old.row) if isinstance(old, Coil) else Contact())
    work = network.copy()
    if row + 1 < work.rows and work.element_at(row + 1, col) is not None:
        _insert_row(work, row + 1)
    _put(work, row + 1, col, new)
    work.links.add((row, col))
    if isinstance(old, Contact):
        work.links.add((row, col + 1))
    return _change(network, work)


def draw_line(network: LadderNetwork, start: Cell, end: Cell) -> Edit:
    """The line tool between two grid nodes `(row, node)` (node k = left edge of column k).

    Horizontal: wires in the empty cells between the nodes. Vertical: links between the rows.
    """
    (r1, k1), (r2, k2) = start, end
    work = network.copy()
    if r1 == r2:
        lo, hi = sorted((k1, k2))
        for col in range(lo, hi):
            _check_cell(work, r1, col)
            if col >= work.columns:
                raise EditRefused("edit-coil-column", (r1, col), row=r1, col=col)
            if work.element_at(r1, col) is None:
                _grow(work, r1)
                work.cells[(r1, col)] = WIRE
    elif k1 == k2:
        lo, hi = sorted((r1, r2))
        _check_cell(work, hi, k1)
        _grow(work, hi)
        for r in range(lo, hi):
            work.links.add((r, k1))
    else:
        raise EditRefused("edit-line", start)
    return _change(network, work)


def erase_line(network: LadderNetwork, start: Cell, end: Cell) -> Edit:
    """Remove wires (horizontal) or links (vertical) between two nodes; elements stay."""
    (r1, k1), (r2, k2) = start, end
    work = network.copy()
    if r1 == r2:
        lo, hi = sorted((k1, k2))
        for col in range(lo, hi):
            if isinstance(work.cells.get((r1, col)), Wire):
                del work.cells[(r1, col)]
    elif k1 == k2:
        lo, hi = sorted((r1, r2))
        for r in range(lo, hi):
            work.links.discard((r, k1))
    else:
        raise EditRefused("edit-line", start)
    return _change(network, work)


def _insert_row(work: LadderNetwork, at: int) -> None:
    """Shift rows `at`.. down by one; boxes spanning the gap grow, links across it stretch."""
    if work.rows + 1 > MAX_ROWS:
        raise EditRefused("edit-outside", (work.rows, 0), row=work.rows, col=0)
    cells: dict[Cell, Element] = {}
    for (r, c), element in work.cells.items():
        if r >= at:
            cells[(r + 1, c)] = element
        elif isinstance(element, FunctionBox) and r + element.height > at:
            pins = tuple(p + 1 if r + p >= at else p for p in element.pins)
            outputs = tuple((p + 1 if r + p >= at else p, contact)
                            for p, contact in element.outputs)
            cells[(r, c)] = replace(element, pins=pins, height=element.height + 1,
                                    outputs=outputs)
        else:
            cells[(r, c)] = element
    links: set[Cell] = set()
    for r, k in work.links:
        if r >= at:
            links.add((r + 1, k))
        elif r == at - 1:
            links.update({(r, k), (r + 1, k)})
        else:
            links.add((r, k))
    work.cells = cells
    work.links = links
    work.rows += 1


def insert_row(network: LadderNetwork, row: int, after: bool = False) -> Edit:
    """Insert an empty row before (or after) `row`."""
    work = network.copy()
    _insert_row(work, row + 1 if after else row)
    return _change(network, work)


def delete_row(network: LadderNetwork, row: int) -> Edit:
    """Delete a row with everything on it; rows below move up (a box on it loses that row)."""
    if not 0 <= row < network.rows:
        raise EditRefused("edit-outside", (row, 0), row=row, col=0)
    work = network.copy()
    cells: dict[Cell, Element] = {}
    for (r, c), element in work.cells.items():
        if isinstance(element, FunctionBox) and r <= row < r + element.height:
            if element.height == 1 or any(r + p == row for p in element.pins) \
                    or any(r + p == row for p, _ in element.outputs):
                continue  # the box loses a pin row: it goes
            pins = tuple(p - 1 if r + p > row else p for p in element.pins)
            outputs = tuple((p - 1 if r + p > row else p, contact)
                            for p, contact in element.outputs)
            element = replace(element, pins=pins, height=element.height - 1, outputs=outputs)
            cells[(r - 1 if r > row else r, c)] = element
        elif r == row:
            continue
        else:
            cells[(r - 1 if r > row else r, c)] = element
    links: set[Cell] = set()
    for r, k in work.links:
        if r == row or (r == row - 1 and (row, k) not in work.links):
            continue
        links.add((r - 1 if r > row else r, k))
    work.cells = cells
    work.links = links
    work.rows = max(1, work.rows - 1)
    return _change(network, work)


def to_address(text: str | Address, cell: Cell | None = None, *, bit: bool = True,
               dialect: str = FANUC) -> Address:
    """Parse an address typed by the user, in the map of a program of `dialect`; EditRefused
    carries the address diagnostic."""
    if isinstance(text, Address):
        return text
    try:
        address = parse_address(text, want_bit=bit)
    except AddressError as exc:
        raise EditRefused(exc.code, cell, **exc.args_map) from None
    problem = model_problem(address, dialect)  # a seed program: the seed's map
    if problem is not None:
        raise EditRefused(problem.code, cell, **problem.args)
    return address


def set_address(network: LadderNetwork, row: int, col: int, address: str | Address,
                dialect: str = FANUC) -> Edit:
    """Set the address of the contact or coil at a cell (typed text is checked, in the map
    of a program of `dialect`)."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], Contact | Coil):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    value = to_address(address, (row, col), dialect=dialect)
    work = network.copy()
    element = found[1]
    if isinstance(element, Contact) and element.function:  # an address makes it a plain contact
        element = replace(element, function="", params=())
    work.cells[found[0]] = replace(element, address=value, texts=())
    return _change(network, work)


def set_operand(network: LadderNetwork, row: int, col: int, text: str,
                address: Address | None) -> Edit:
    """Set the operand of a contact or coil drawn from a source's own model, as the source
    writes it (`"Start"`) with its engine address (source_model.py checks the text)."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], Contact | Coil):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    work = network.copy()
    element = found[1]
    work.cells[found[0]] = replace(element, address=address,
                                   texts=(text, *element.texts[1:]))
    return _change(network, work)


def set_comment(network: LadderNetwork, row: int, col: int, text: str) -> Edit:
    """Set the comment of the element at a cell (contact, coil or box)."""
    found = network.element_at(row, col)
    if found is None or isinstance(found[1], Wire):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    work = network.copy()
    work.cells[found[0]] = replace(found[1], comment=text.strip())
    return _change(network, work)


def set_lead(network: LadderNetwork, row: int, col: int, lines: list[str]) -> Edit:
    """Set the comment lines written just before an element's instruction."""
    found = network.element_at(row, col)
    if found is None or isinstance(found[1], Wire):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    work = network.copy()
    work.cells[found[0]] = replace(found[1], lead=tuple(lines))
    return _change(network, work)


def set_network_comments(network: LadderNetwork, lines: list[str]) -> Edit:
    """Set the comment lines above the network (the comment tool)."""
    work = network.copy()
    work.comments = list(lines)
    return _change(network, work)


def set_label(network: LadderNetwork, label: str) -> Edit:
    """Set the network's jump label ("" removes it; the source model checks the name)."""
    work = network.copy()
    work.label = label.strip()
    return _change(network, work)


def set_params(network: LadderNetwork, row: int, col: int,
               params: tuple[ParamValue, ...] | list[str]) -> Edit:
    """Set a function box's parameters: values, or texts checked like the instruction list."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], FunctionBox):
        raise EditRefused("edit-no-element", (row, col), row=row, col=col)
    box = found[1]
    if params and all(isinstance(p, str) for p in params):
        values, problems = function_params(box.name, [str(p) for p in params])
        if values is None:
            first = problems[0]
            raise EditRefused(first.code, (row, col), **first.args)
        params = values
    work = network.copy()
    work.cells[found[0]] = replace(box, params=tuple(params))  # type: ignore[arg-type]
    return _change(network, work)


def function_params(name: str, texts: list[str], dialect: str = "seed"
                    ) -> tuple[tuple[ParamValue, ...] | None, list[Diagnostic]]:
    """Check parameter texts for a functional instruction exactly as the parser would, with
    the ranges of a program of `dialect` ("fanuc": the 30i ranges of a LADDER-III program)."""
    from ladderworks.core.il import parse
    from ladderworks.core.il.printer import print_instruction
    from ladderworks.core.il.program import Instruction

    head = print_instruction(Instruction(name))  # as the text names it (`AND` for LOGAND)
    text = "%@3\n" + " ".join([head, *texts]) + "\n%\n"
    result = parse(text, dialect)
    if not result.ok:
        return None, [d for d in result.diagnostics if d.is_error]
    instructions = result.program.instructions()
    return instructions[0].params, []


def set_drawing(network: LadderNetwork, other: LadderNetwork) -> Edit:
    """Replace the whole drawing with another network's (e.g. after converting text)."""
    return _change(network, other)
