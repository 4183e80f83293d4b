"""A drawn ladder network read back as an S7 network graph (the inverse of drawing.py).

The grid's nodes joined by wires and links are the network's power junctions: the rail, each
element's input and output. An element becomes a part (a contact, a coil, a box with its named
pins), each junction a wire from its one source to its targets; a junction fed by several
elements (parallel branches meeting) gets an O part, as TIA writes it. Operands are read from
the texts the elements show ("Start", #Timer.Q, T#10s), or from the address typed.
"""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7 import pins
from ladderworks.core.dialects.s7.drawing import COIL_MARKS, COILS, COMPARES, CONTACT_ROWS
from ladderworks.core.dialects.s7.graph import (
    Block,
    End,
    Operand,
    OperandKind,
    Part,
    S7Network,
    Wire,
)
from ladderworks.core.dialects.s7.sd_lexer import LexError, tokens
from ladderworks.core.dialects.s7.sd_parser import ParseError, _Parser
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.ladder.decompose import NodeNets
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.ladder.model import Wire as Line

UNWIRED = "..."  # an optional output wired to nothing, as TIA shows it


class GridError(Exception):
    """A drawing that is no S7 network; `diagnostic` names the network's cell."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message())
        self.diagnostic = diagnostic


def operand_from_text(text: str) -> Operand:
    """An operand as TIA writes it: "Start", "DB".a.b, #Timer.Q, %MW2, T#10s, 5, TRUE."""
    text = text.strip()
    try:
        toks = tokens(text)
        parser = _Parser(toks, [text])
        found = parser.value("an operand")
        if isinstance(found, Operand) and parser.tok.kind == "end":
            return found
    except (LexError, ParseError, IndexError):
        pass
    return Operand(OperandKind.CONSTANT, (), text)


def _address_operand(address: Address | None) -> Operand | None:
    if address is None:
        return None
    text = spelling("s7").address(address)
    return Operand(OperandKind.ABSOLUTE, (text,), text)


class _Reader:
    def __init__(self, network: LadderNetwork, index: int) -> None:
        self.net = network
        self.index = index
        self.nets = NodeNets(network)
        self.rail = self.nets.net((0, 0))
        self.parts: list[Part] = []
        self.wires: list[Wire] = []
        self.sources: dict[int, list[End]] = {self.rail: [End(powerrail=True)]}
        self.targets: dict[int, list[End]] = {}

    def fail(self, cell: tuple[int, int], name: str = "") -> GridError:
        """The element at `cell` is no S7 element (`name`), or has no operand (no name)."""
        where: dict[str, object] = {"network": self.index, "row": cell[0] + 1,
                                    "column": cell[1] + 1}
        network = self.index - 1 if self.index else None  # the drawn network, its cell
        if not name:
            return GridError(Diagnostic("s7-grid-operand", where, 0, 0, Severity.ERROR, network,
                                        cell))
        return GridError(Diagnostic("s7-grid-element", {**where, "name": name}, 0, 0,
                                    Severity.ERROR, network, cell))

    def new_part(self, name: str, **fields: object) -> Part:
        part = Part(str(len(self.parts) + 1), name, **fields)  # type: ignore[arg-type]
        self.parts.append(part)
        return part

    def operand_wire(self, part: Part, pin: str, operand: Operand | None, out: bool = False
                     ) -> None:
        if operand is None:
            return
        if out:
            self.wires.append(Wire(End(part=part.uid, pin=pin), [End(operand=operand)]))
        else:
            self.wires.append(Wire(End(operand=operand), [End(part=part.uid, pin=pin)]))

    def power(self, part: Part, pin_in: str | None, left: tuple[int, int],
              pin_out: str | None, right: tuple[int, int]) -> None:
        if pin_in is not None:
            self.targets.setdefault(self.nets.net(left), []).append(End(part=part.uid,
                                                                        pin=pin_in))
        if pin_out is not None:
            self.sources.setdefault(self.nets.net(right), []).append(End(part=part.uid,
                                                                         pin=pin_out))

    def operand(self, element: Contact | Coil, at: int = 0) -> Operand | None:
        if len(element.texts) > at and element.texts[at]:
            return operand_from_text(element.texts[at])
        return _address_operand(element.address) if at == 0 else None

    def contact(self, cell: tuple[int, int], contact: Contact) -> None:
        row, col = cell
        if not contact.function:
            operand = self.operand(contact)
            if operand is None:
                raise self.fail(cell)
            part = self.new_part("Contact", negated=frozenset({"operand"} if contact.negated
                                                              else ()))
            self.operand_wire(part, "operand", operand)
        else:
            name = next((n for n, row_name in CONTACT_ROWS.items()
                         if row_name == contact.function), None)
            if name is None:
                raise self.fail(cell, contact.function)
            type_name = contact.mark.partition("\n")[2]
            part = self.new_part(name, template={"SrcType": type_name} if type_name else {})
            if name in COMPARES:
                self.operand_wire(part, "in1", self.operand(contact, 0))
                self.operand_wire(part, "in2", self.operand(contact, 1))
            elif name in ("PContact", "NContact"):
                self.operand_wire(part, "operand", self.operand(contact, 0))
                self.operand_wire(part, "bit", self.operand(contact, 1))
            else:
                self.operand_wire(part, "in", self.operand(contact, 0))
        self.power(part, "in", (row, col), "out", (row, col + 1))

    def coil(self, cell: tuple[int, int], coil: Coil) -> None:
        row, col = cell
        mark = coil.mark
        if not mark:
            name = next(n for n, write in COILS.items() if write is coil.write)
            operand = self.operand(coil)
            if operand is None:
                raise self.fail(cell)
            part = self.new_part(name, negated=frozenset({"operand"} if coil.negated else ()))
            self.operand_wire(part, "operand", operand)
        else:
            name = next((n for n, m in COIL_MARKS.items() if m == mark), "")
            if not name:
                raise self.fail(cell, mark)
            first = coil.texts[0] if coil.texts else ""
            part = self.new_part(name, label=first if name in ("Jump", "JumpN") else "")
            if name in ("PCoil", "NCoil"):
                self.operand_wire(part, "operand", self.operand(coil, 0))
                self.operand_wire(part, "bit", self.operand(coil, 1))
            elif name == "Return" and first:  # its value (the block's ENO)
                self.operand_wire(part, "operand", self.operand(coil, 0))
            elif name in ("PTCoil", "RTCoil"):
                part.instance = operand_from_text(first) if first else None
                if name == "PTCoil":
                    self.operand_wire(part, "pt", self.operand(coil, 1))
        self.power(part, "in", (row, col), "out", (row, col + 1))

    def box(self, cell: tuple[int, int], box: FunctionBox) -> None:
        row, col = cell
        origin = dict(box.origin)
        name = origin.pop("part", "")
        if name not in pins.BOXES and name != "Call":
            raise self.fail(cell, box.title or box.name)
        call, call_kind = origin.pop("call", ""), origin.pop("call_kind", "")
        dests = tuple(d for d in origin.pop("dests", "").split(",") if d)
        part = self.new_part(name, template=origin, call=call, call_kind=call_kind,
                             dests=dests)
        called_by_db = box.instance.strip('"') == call  # an FB called by its instance DB
        if box.instance and (name in pins.INSTANCED or name == "Call") and not called_by_db:
            part.instance = operand_from_text(box.instance)
        if box.instance and name in ("Sr", "Rs"):
            self.operand_wire(part, "operand", operand_from_text(box.instance))
        if box.instance and name in ("PTrig", "NTrig"):
            self.operand_wire(part, "bit", operand_from_text(box.instance))
        ins, outs = pins.LAYOUTS.get(name, ((), ()))
        for pin in box.named:
            if (pin.output and pin.name.startswith(("DEST", "ELSE"))) or pin.text == UNWIRED:
                continue  # the jump table's labels are its `dests`; an output left unwired
            key = _key(name, pin.name, ins if not pin.output else outs, pin.row)
            if pin.negated:
                part.negated = part.negated | {key}
            if pin.text:
                self.operand_wire(part, key, operand_from_text(pin.text), pin.output)
            elif pin.output:
                self.power(part, None, (0, 0), key, (row + pin.row, col + box.width))
            else:
                self.power(part, key, (row + pin.row, col), None, (0, 0))

    def read(self) -> S7Network:
        for (row, col), element in self.net.elements():
            if isinstance(element, Contact):
                self.contact((row, col), element)
            elif isinstance(element, Coil):
                self.coil((row, col), element)
            elif isinstance(element, FunctionBox):
                self.box((row, col), element)
            elif not isinstance(element, Line):
                raise self.fail((row, col), type(element).__name__)
        for net, targets in self.targets.items():
            ends = self.sources.get(net, [])
            if not ends:
                continue  # an input no power reaches: left open, as TIA would
            if len(ends) > 1:  # branches meeting: an O
                ends = [self.merge(ends)]
            self.wires.append(Wire(ends[0], list(targets)))
        network = S7Network(parts=self.parts, wires=self.wires)
        if self.net.label:
            self.parts.insert(0, Part("L", "Label", label=self.net.label))
        return network

    def merge(self, ends: list[End]) -> End:
        part = self.new_part("O")
        for n, end in enumerate(ends, start=1):
            self.wires.append(Wire(end, [End(part=part.uid, pin=f"in{n}")]))
        return End(part=part.uid, pin="out")


def _key(part: str, shown: str, specs: tuple[pins.PinSpec, ...], row: int) -> str:
    """The graph's pin name of a box pin drawn as `shown` (a call's parameter as written)."""
    if part == "Call":
        return shown if shown not in ("EN", "ENO") else shown.lower()
    for name, keys in specs:
        if name == shown:
            return keys[0]
    if part == "Switch":  # a case's comparison: ==, <> … numbered from 1
        relation = next((k for k, v in pins.RELATIONS.items() if v == shown), "EQ")
        return f"{relation.lower()}{row - 1}"
    if shown.startswith("OUT") and shown[3:].isdigit():
        return shown.lower()
    return shown.lower()


def network_from_grid(network: LadderNetwork, block: Block, index: int = 0) -> S7Network:
    """The S7 network a drawing shows (for the SD/XML writers and the lowering); GridError
    names the cell of a drawing S7 cannot hold."""
    del block  # the operands are read as written; the block resolves them when lowered
    found = _Reader(network, index).read()
    comments = list(network.comments)
    found.title = comments[0] if comments else ""
    found.comment = "\n".join(comments[1:])
    return found
