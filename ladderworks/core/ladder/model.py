"""The ladder grid: networks of cells between the rails with contacts, coils, wires, boxes."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field, replace

from ladderworks.core.address import Address
from ladderworks.core.il.program import Instruction, ParamValue, Program, Section
from ladderworks.core.instructions import InstructionSpec, Kind, Write, lookup, spec_for

# Grid limits (FANUC-like). A network has `columns` contact columns (0 .. columns-1) and one
# coil column (index `columns`) at the right. New networks get DEFAULT_COLUMNS; a network laid
# out from a long instruction list may be wider, up to MAX_COLUMNS. Rows grow as needed.
DEFAULT_COLUMNS = 10
MAX_COLUMNS = 32
MAX_ROWS = 64
PAGE_ROWS = 16  # rows a console page shows; networks may be taller (they scroll)
BOX_WIDTH = 2  # a function box is two contact columns wide
# a box parameter naming the box's output byte (Fatek's FO: FO0 is W1, FO1, FO2 … more pins)
OUTPUT_BYTE = "fo"

Cell = tuple[int, int]  # (row, column)


@dataclass(frozen=True, slots=True)
class Contact:
    """A contact: normally open (RD/AND/OR) or normally closed (`negated`, the .NOT forms).

    A dialect's edge or comparison contact (`row_contacts.py`) has `function`, the row it was
    read with (`DVP.LD=`, `FBS.TU`), and `params`, its operands; its `address` is None."""

    address: Address | None = None  # None while the user has not typed it yet
    negated: bool = False
    comment: str = ""  # the element's comment (trailing `// ...` of its instruction)
    lead: tuple[str, ...] = ()  # comment lines written just before its instruction
    function: str = ""  # a functional row drawn as a contact ("" for RD/AND/OR)
    params: tuple[ParamValue, ...] = ()  # its operands
    # its operands as the source writes them (an S7 symbol: "Start", #Timer.Q), shown
    # instead of the address: the first above the contact, the others below
    texts: tuple[str, ...] = ()
    mark: str = ""  # what it shows in its middle when the source says (S7's P, N, >= Time)


@dataclass(frozen=True, slots=True)
class Coil:
    """An output coil in the coil column: WRT (WRT.NOT when `negated`), SET or RST (`write`)."""

    address: Address | None = None
    negated: bool = False  # WRT.NOT; SET and RST have no inverted form
    comment: str = ""
    lead: tuple[str, ...] = ()
    write: Write = Write.OUT  # what the coil does with ST0: OUT (WRT), SET, RESET (RST)
    row: str = ""  # a dialect's own coil row it was read with (Fatek's OUT L), "" for the table's
    texts: tuple[str, ...] = ()  # its operands as the source writes them (see Contact.texts)
    mark: str = ""  # what it shows inside when the source says (S7's P, N, PT, RT, JMP)


@dataclass(frozen=True, slots=True)
class Wire:
    """A horizontal wire through one cell."""


WIRE = Wire()


@dataclass(frozen=True, slots=True)
class Pin:
    """A named pin of a box as its source draws it (S7's IN, PT → Q, ET).

    `row` is its row offset in the box; `text` the operand wired to it as the source writes
    it ("T#10s", "Geçen Süre"), "" when power (a wire) comes in or goes out there."""

    name: str
    row: int
    output: bool = False
    text: str = ""
    negated: bool = False


@dataclass(frozen=True, slots=True)
class FunctionBox:
    """A functional instruction drawn as a box anchored at its top-left cell.

    It is BOX_WIDTH columns wide and `height` rows high. Control input i (spec order, ACT last)
    enters the box's left edge at row offset `pins[i]`; the W1 output (if the instruction has
    one) leaves the right edge at the box's top row. `outputs`: its further output pins (bits
    of its OUTPUT_BYTE parameter, Fatek's FO1, FO2 …), each the row offset where it leaves the
    right edge and the contact that reads it in the code (`RD` of that bit).

    A box drawn from a dialect's own graph (S7) names its pins: `named` holds every pin with
    its operand; `title` is the name shown ("TON", a called block's), `type_name` the data type
    under it ("Time"), `instance` the instance shown above it ("IEC_Timer_0_DB"), and
    `origin` the dialect's own words for the part (key, value pairs) to write it back. Its
    `name` is the row it runs as, when one row does (else `spec` is a shown-only row).
    """

    name: str
    params: tuple[ParamValue, ...] = ()
    comment: str = ""
    lead: tuple[str, ...] = ()
    pins: tuple[int, ...] = ()
    height: int = 1
    outputs: tuple[tuple[int, Contact], ...] = ()
    named: tuple[Pin, ...] = ()
    title: str = ""
    type_name: str = ""
    instance: str = ""
    origin: tuple[tuple[str, str], ...] = ()

    @classmethod
    def new(cls, name: str, params: tuple[ParamValue, ...] = (), comment: str = "",
            lead: tuple[str, ...] = ()) -> FunctionBox:
        """A box with one row per control input (at least one row)."""
        spec = spec_for(name.upper(), len(params))
        count = len(spec.inputs) if spec is not None else 0
        return cls(name.upper(), params, comment, lead, tuple(range(count)), max(1, count))

    @property
    def spec(self) -> InstructionSpec:
        """The instruction table row (`spec_for`: a `SUB.n` the table lacks has RAW params)."""
        spec = spec_for(self.name, len(self.params))
        if spec is None and self.named:  # drawn from a graph, no row of its own: shown only
            return InstructionSpec(self.name, Kind.FUNCTION, inputs=self.inputs,
                                   title=self.title, title_tr=self.title)
        assert spec is not None, self.name
        return spec

    @property
    def inputs(self) -> tuple[str, ...]:
        """Control input names, first to last (ACT last); a named box's power inputs."""
        if self.named:
            return tuple(pin.name for pin in self.named if not pin.output and not pin.text)
        return self.spec.inputs

    @property
    def has_output(self) -> bool:
        """True when the box has a W1 output on its right (a named box: a power output on its
        top row)."""
        if self.named:
            return any(pin.output and not pin.text and pin.row == 0 for pin in self.named)
        return self.spec.w1

    @property
    def width(self) -> int:
        """Columns the box covers."""
        return BOX_WIDTH

    def output_byte(self) -> Address | None:
        """The value of its OUTPUT_BYTE parameter (None when it has none)."""
        for param, value in zip(self.spec.params, self.params, strict=False):
            if param.name == OUTPUT_BYTE and isinstance(value, Address):
                return value
        return None

    def output_label(self, contact: Contact) -> str:
        """An output pin's name: the output byte's parameter and the bit (`FO1`)."""
        bit = contact.address.bit if contact.address is not None else None
        return f"{OUTPUT_BYTE.upper()}{bit}"


Element = Contact | Coil | Wire | FunctionBox


def is_element(value: object) -> bool:
    """True for anything a cell can hold."""
    return isinstance(value, Contact | Coil | Wire | FunctionBox)


@dataclass(eq=False, slots=True)
class LadderNetwork:
    """One network (rung): a grid of cells, vertical links, and comment lines above it.

    `cells` maps an anchor cell to its element (a box is stored at its top-left cell only; use
    `element_at` to find what covers any cell). `links` holds vertical links: `(row, node)` joins
    node `node` of `row` with the same node of `row + 1`; node k is the left edge of column k,
    node 0 is the left rail, node `columns` is the left edge of the coil column.

    `listing` is set when the network is kept as instruction-list text because it cannot be
    drawn faithfully (then the grid is empty). `source` is the original coding of a network read
    from text: it is written back instead of the standard coding as long as the drawing still
    means exactly the same logic (same standard coding), so unusual stack code round-trips.
    """

    columns: int = DEFAULT_COLUMNS
    rows: int = 1
    cells: dict[Cell, Element] = field(default_factory=dict)
    links: set[Cell] = field(default_factory=set)
    comments: list[str] = field(default_factory=list)
    listing: tuple[Instruction, ...] | None = None
    source: tuple[Instruction, ...] | None = None
    label: str = ""  # the LADDER-III network label it was read with (`N00012`), kept on save

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, LadderNetwork):
            return NotImplemented
        # what state() compares, without sorting the cells: dict and set equality ignore
        # order, and a copy shares its elements, so Save compares 10,000 networks quickly
        return (self.columns == other.columns and self.rows == other.rows
                and self.cells == other.cells and self.links == other.links
                and self.comments == other.comments and self.listing == other.listing)

    @property
    def coil_column(self) -> int:
        """Index of the coil column (the rightmost)."""
        return self.columns

    def state(self) -> NetworkState:
        """An immutable snapshot of the drawing (used by edits and comparisons)."""
        return NetworkState(self.columns, self.rows, tuple(sorted(self.cells.items(),
                                                                  key=lambda kv: kv[0])),
                            frozenset(self.links), tuple(self.comments), self.listing,
                            self.label)

    def restore(self, state: NetworkState) -> None:
        """Make the network equal to a snapshot."""
        self.columns = state.columns
        self.rows = state.rows
        self.cells = dict(state.cells)
        self.links = set(state.links)
        self.comments = list(state.comments)
        self.listing = state.listing
        self.label = state.label

    def copy(self) -> LadderNetwork:
        """An independent copy (elements are immutable and shared)."""
        return LadderNetwork(self.columns, self.rows, dict(self.cells), set(self.links),
                             list(self.comments), self.listing, self.source, self.label)

    def elements(self) -> Iterator[tuple[Cell, Element]]:
        """Anchor cell and element, top to bottom then left to right."""
        yield from sorted(self.cells.items(), key=lambda kv: kv[0])

    def footprint(self, cell: Cell, element: Element) -> list[Cell]:
        """Cells covered by `element` anchored at `cell`."""
        row, col = cell
        if isinstance(element, FunctionBox):
            return [(row + r, col + c) for r in range(element.height)
                    for c in range(element.width)]
        return [cell]

    def element_at(self, row: int, col: int) -> tuple[Cell, Element] | None:
        """The element covering a cell and its anchor, or None."""
        element = self.cells.get((row, col))
        if element is not None:
            return (row, col), element
        for anchor, item in self.cells.items():
            if isinstance(item, FunctionBox) and (row, col) in self.footprint(anchor, item):
                return anchor, item
        return None

    def used_rows(self) -> int:
        """Rows the drawing really spans: `rows`, or more if an element or link reaches further
        (a network built directly in code may not have grown `rows`)."""
        last = self.rows
        for (r, c), element in self.cells.items():
            last = max(last, max(cell[0] for cell in self.footprint((r, c), element)) + 1)
        for r, _ in self.links:
            last = max(last, r + 2)
        return last

    def has_link(self, row: int, node: int) -> bool:
        """True when a vertical link joins `row` and `row + 1` at node `node`."""
        return (row, node) in self.links

    def is_empty(self) -> bool:
        """True when nothing is drawn (and nothing is kept as a listing)."""
        return not self.cells and not self.links and self.listing is None

    def row_is_empty(self, row: int) -> bool:
        """True when no element covers the row and no link touches it."""
        if any(self.element_at(row, c) for c in range(self.columns + 1)):
            return False
        return not any(r in (row, row - 1) for r, _ in self.links)

    def with_element(self, cell: Cell, element: Element) -> LadderNetwork:
        """A copy with one more element (a convenience for building networks in code)."""
        net = self.copy()
        net.cells[cell] = element
        net.rows = max(net.rows, cell[0] + (element.height if isinstance(element, FunctionBox)
                                           else 1))
        return net


@dataclass(frozen=True, slots=True)
class NetworkState:
    """Immutable snapshot of a LadderNetwork's drawing."""

    columns: int
    rows: int
    cells: tuple[tuple[Cell, Element], ...]
    links: frozenset[Cell]
    comments: tuple[str, ...]
    listing: tuple[Instruction, ...] | None
    label: str = ""


@dataclass(eq=False, slots=True)
class LadderDocument:
    """A whole program as ladder: its networks plus the text parts that are not drawn."""

    networks: list[LadderNetwork] = field(default_factory=list)
    header: list[str] = field(default_factory=list)
    trailer: list[str] = field(default_factory=list)
    footer: list[str] = field(default_factory=list)
    before: list[Section] = field(default_factory=list)  # other FANUC sections, verbatim
    after: list[Section] = field(default_factory=list)
    origin: Program | None = None  # the program it was laid out from: its file, form, symbols


def flip(element: Contact | Coil) -> Contact | Coil:
    """The NOT tool: contact NO⇄NC, coil WRT⇄WRT.NOT, SET⇄RST (they have no inverted form);
    a dialect's own coil row (Fatek's OUT L) becomes the table's inverted coil."""
    if isinstance(element, Coil) and element.write is not Write.OUT:
        return replace(element, write=Write.RESET if element.write is Write.SET else Write.SET,
                       row="")
    if isinstance(element, Coil):
        return replace(element, negated=not element.negated, row="")
    return replace(element, negated=not element.negated)


def coil_mark(coil: Coil) -> str:
    """What a coil shows inside: S / R for SET / RST, the last word of a dialect's own coil
    row's spelling (`L` for Fatek's OUT L), the source's own mark (S7's P, PT), "" for WRT."""
    if coil.mark:
        return coil.mark
    own = lookup(coil.row) if coil.row else None
    if own is not None:
        return own.text_name.split()[-1]
    return {Write.SET: "S", Write.RESET: "R"}.get(coil.write, "")


def is_end(name: str) -> bool:
    """True for END1 / END2 / END3 / END."""
    spec = lookup(name)
    return spec is not None and spec.kind is Kind.END
