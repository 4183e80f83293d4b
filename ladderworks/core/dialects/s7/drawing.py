"""An S7 network's graph drawn as TIA Portal draws LAD, on the ladder grid (one path for all).

Contacts (NO, NC, P, N, comparisons), coils (=, /, S, R, P, N, PT, RT, JMP, JMPN, RET), boxes
with named pins (`Pin`: TON's IN, PT → Q, ET; CTU's CU, R, PV → Q, CV; MOVE's EN, IN → ENO,
OUT1; calls with their parameters), O branches as parallel rows, a wire to several outputs as
rows joined at the branch point. Each element carries its operands as TIA writes them
(`texts`: "Start", #Timer.Q, T#10s) and the engine row and parameters the lowering made of it
(`emitted`), so the power flow of the running program maps back onto the drawing. A network
that cannot be drawn so (a wire the structures cannot hold) keeps its engine instructions as a
listing, as before.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ladderworks.core.address import Address
from ladderworks.core.dialects.s7 import pins
from ladderworks.core.dialects.s7.drawn_grid import Branch, Clash, Item, place
from ladderworks.core.dialects.s7.graph import End, Operand, Part, S7Network
from ladderworks.core.dialects.s7.stack import PinGraph
from ladderworks.core.il.program import Instruction, ParamValue
from ladderworks.core.instructions import Write
from ladderworks.core.ladder.model import (
    MAX_COLUMNS,
    Coil,
    Contact,
    Element,
    FunctionBox,
    LadderNetwork,
    Pin,
)
from ladderworks.core.plc import typed

Resolve = Callable[[Operand], Address | None]  # an operand's engine address (None: none)
Emitted = dict[tuple[int, str], tuple[object, tuple[Instruction, ...]]]
COILS = {"Coil": Write.OUT, "SCoil": Write.SET, "RCoil": Write.RESET}
COIL_MARKS = {"PCoil": "P", "NCoil": "N", "PTCoil": "PT", "RTCoil": "RT", "Jump": "JMP",
              "JumpN": "JMPN", "Return": "RET"}
COMPARES = {"Eq": "==", "Ne": "<>", "Gt": ">", "Lt": "<", "Ge": ">=", "Le": "<="}
CONTACT_ROWS = {"PContact": "S7.P", "NContact": "S7.N", "Ok": "S7.OK", "NotOk": "S7.NOT_OK",
                **{name: "S7." + name.upper() for name in COMPARES}}
STRUCTURE = ("O", "A", "Label")
MAX_DEPTH = 2 * MAX_COLUMNS  # ends followed at once: a longer series cannot be drawn anyway


class NotDrawn(Exception):
    """The network has a part or wire the drawing cannot hold."""


@dataclass(slots=True)
class Context:
    """What the drawing reads besides the graph: operand addresses, the lowering's record."""

    resolve: Resolve
    emitted: Emitted
    index: int = 0  # the network's number in its block (1-based, as the lowering counts)
    instance_of: dict[str, str] = field(default_factory=dict)  # an instance DB's FB (lower)


def type_name(part: Part) -> str:
    """The data type a generic part works on as its template says ("Time", "Int")."""
    for key, value in part.template.items():
        if key.lower() in pins.TYPE_KEYS:
            return value
    return ""


class Drawer:
    """One network's parts as series/parallel items, then laid out on a LadderNetwork."""

    def __init__(self, network: S7Network, context: Context) -> None:
        self.network = network
        self.context = context
        self.graph = PinGraph(network)
        self.memo: dict[tuple[bool, str, str], list[Item]] = {}
        self.visiting: set[tuple[bool, str, str]] = set()  # ends being followed (loops)
        self.drawn: list[str] = []

    # -- the record of the lowering --------------------------------------------------------
    def instruction(self, part: Part, rows: tuple[str, ...]) -> Instruction | None:
        """The instruction the lowering made of `part` whose row is one of `rows`."""
        result, code = self.context.emitted.get((self.context.index, part.uid), (None, ()))
        if isinstance(result, tuple) and result and result[0] == "box" and result[1] in rows:
            return Instruction(result[1], None, result[2])
        return next((ins for ins in reversed(code) if ins.name in rows), None)

    def operand(self, part: Part, pin: str) -> Operand | None:
        return self.graph.operand_in.get((part.uid, pin)) or next(
            iter(self.graph.operand_out.get((part.uid, pin), [])), None)

    def text(self, part: Part, pin: str) -> str:
        operand = self.operand(part, pin)
        return operand.display() if operand is not None else ""

    def bit(self, operand: Operand | None) -> Address | None:
        found = self.context.resolve(operand) if operand is not None else None
        return found if found is not None and found.bit is not None else None

    # -- elements ------------------------------------------------------------------------
    def element(self, part: Part) -> Element:
        name = part.name
        operand = self.operand(part, "operand")
        shown = operand.display() if operand is not None else ""
        if name == "Contact":
            return Contact(self.bit(operand), "operand" in part.negated, texts=(shown,))
        if name in CONTACT_ROWS:
            found = self.instruction(part, (CONTACT_ROWS[name],))
            params: tuple[ParamValue, ...] = found.params if found is not None else ()
            if name in COMPARES:
                mark = COMPARES[name] + ("\n" + type_name(part) if type_name(part) else "")
                return Contact(None, function=CONTACT_ROWS[name], params=params, mark=mark,
                               texts=(self.text(part, "in1"), self.text(part, "in2")))
            mark = {"PContact": "P", "NContact": "N", "Ok": "OK", "NotOk": "NOT_OK"}[name]
            texts = (shown or self.text(part, "in"),) + ((self.text(part, "bit"),)
                                                         if name in ("PContact", "NContact")
                                                         else ())
            return Contact(None, function=CONTACT_ROWS[name], params=params, mark=mark,
                           texts=texts)
        if name in COILS:
            return Coil(self.bit(operand), "operand" in part.negated, write=COILS[name],
                        texts=(shown,))
        if name in COIL_MARKS:
            texts = {"PCoil": (shown, self.text(part, "bit")),
                     "NCoil": (shown, self.text(part, "bit")),
                     "PTCoil": (self.instance(part), self.text(part, "pt")),
                     "RTCoil": (self.instance(part),),
                     "Return": (shown,)}.get(name, (part.label,))
            address = self.bit(operand) if name in ("PCoil", "NCoil") else None
            return Coil(address, mark=COIL_MARKS[name], texts=texts)
        if name in pins.BOXES or name == "Call":
            return self.box(part)
        raise NotDrawn(name)

    def instance(self, part: Part) -> str:
        operand = part.instance or self.operand(part, "timer") or self.operand(part, "operand")
        return operand.display() if operand is not None else ""

    def box(self, part: Part) -> FunctionBox:
        layout = pins.box_pins(part, self.graph)
        rows = pins.rows_of(part.name)
        found = self.instruction(part, rows) if rows else None
        name = found.name if found is not None else "S7." + part.name.upper()
        instance = self.instance(part) if part.name in pins.INSTANCED or (
            part.name == "Call" and part.instance is not None) else ""
        if part.name in ("Sr", "Rs", "PTrig", "NTrig"):
            instance = self.text(part, "operand") or self.text(part, "bit") or instance
        shown = pins.title(part)
        fb = self.context.instance_of.get(part.call.lower(), "") if part.call else ""
        if fb:  # an FB called by its instance DB ("Gecikme_DB"(…)): the FB in the box
            shown, instance = fb, f'"{part.call}"'

        power = tuple(pin.row for pin in layout if not pin.output and not pin.text)
        height = max(pin.row for pin in layout) + 1 if layout else 1
        origin = (("part", part.name), *sorted(part.template.items()))
        if part.call:
            origin += (("call", part.call), ("call_kind", part.call_kind))
        if part.dests:
            origin += (("dests", ",".join(part.dests)),)
        return FunctionBox(name, found.params if found is not None else (), pins=power,
                           height=height, named=tuple(layout), title=shown,
                           type_name=type_name(part), instance=instance, origin=origin)

    # -- structure -----------------------------------------------------------------------
    def sources(self, part: Part, pin: str) -> list[End]:
        return self.graph.power_in.get((part.uid, pin), [])

    def upstream(self, ends: list[End]) -> list[Item]:
        """The series of items that brings power to a pin fed by `ends`."""
        if not ends:
            return []
        if len(ends) > 1:
            return factor([self.from_end(end) for end in ends])
        return self.from_end(ends[0])

    def from_end(self, end: End) -> list[Item]:
        key = (end.powerrail, end.part, end.pin)
        if key in self.memo:
            return self.memo[key]
        if key in self.visiting or len(self.visiting) > MAX_DEPTH:
            raise NotDrawn("a loop of wires, or a series longer than a network is wide")
        self.visiting.add(key)
        if end.powerrail:
            found: list[Item] = []
        else:
            part = self.graph.parts.get(end.part)
            if part is None or end.pin not in pins.MAIN_OUT:
                raise NotDrawn(end.part)
            found = self.chain(part)
        self.visiting.discard(key)
        self.memo[key] = found
        return found

    def chain(self, part: Part) -> list[Item]:
        """The items up to and including `part` (its power output)."""
        if part.name == "O":
            branches = [self.upstream(self.sources(part, pin)) for pin in pins.gate_pins(
                part, self.graph)]
            return factor(branches)
        if part.name == "A":  # FBD's AND: its inputs in series (each chain starts at the rail)
            items: list[Item] = []
            for pin in pins.gate_pins(part, self.graph):
                operand = self.graph.operand_in.get((part.uid, pin))
                if operand is not None:
                    items.append(Item(Contact(self.bit(operand), pin in part.negated,
                                              texts=(operand.display(),))))
                elif pin in part.negated:
                    raise NotDrawn(part.uid)  # a negated chain: no LAD picture
                else:
                    items += self.upstream(self.sources(part, pin))
            return items
        return [*self.upstream(self.sources(part, pins.main_in(part, self.graph))),
                self.item(part)]

    def take(self, part: Part, item: Item) -> Item:
        self.drawn.append(part.uid)
        return item

    def item(self, part: Part) -> Item:
        element = self.element(part)
        item = Item(element)
        if isinstance(element, FunctionBox):
            main = pins.main_in(part, self.graph)
            for pin in element.named:
                key = pin.name.lower()
                if not pin.output and not pin.text and key != main and pin.row:
                    item.sides[pin.row] = self.upstream(self.sources(part, key))
            item.lead = 1 if any(p.text and not p.output for p in element.named) else 0
            item.trail = 1 if any(p.text and p.output for p in element.named) else 0
            item.wired = self.graph.used(part.uid)
        return self.take(part, item)

    def terminals(self) -> list[Part]:
        return [p for p in self.network.parts
                if p.name not in STRUCTURE and not self.graph.used(p.uid)]

    def draw(self) -> LadderNetwork:
        paths: list[list[Item]] = []
        for part in self.terminals():
            paths.append(self.chain(part))
        net = LadderNetwork()
        labels = [p.label for p in self.network.parts if p.name == "Label"]
        net.label = labels[0] if labels else ""
        drawn = [p.uid for p in self.network.parts if p.name not in STRUCTURE]
        if sorted(set(self.drawn)) != sorted(drawn) or len(self.drawn) != len(set(self.drawn)):
            raise NotDrawn("a part drawn twice or not at all")
        if paths:
            try:
                place(fan_out(paths), net)
            except Clash as error:
                raise NotDrawn(str(error)) from None
        return net


def factor(branches: list[list[Item]]) -> list[Item]:
    """Parallel branches as items: their common first items in series, then the parallel
    block of the rest (one branch: itself)."""
    if len(branches) == 1:
        return branches[0]
    common: list[Item] = []
    while all(len(b) > len(common) for b in branches) and all(
            b[len(common)] is branches[0][len(common)] for b in branches):
        common.append(branches[0][len(common)])
    rest = [b[len(common):] for b in branches]
    return [*common, Item(branches=rest)] if rest else common


def fan_out(paths: list[list[Item]]) -> Branch:
    """The paths of the outputs as one tree: a shared start, then a branch per output."""
    prefix: list[Item] = []
    while all(len(p) > 1 for p in paths) and all(p[0] is paths[0][0] for p in paths):
        prefix.append(paths[0][0])
        paths = [p[1:] for p in paths]
    if len(paths) == 1:
        *items, last = paths[0] or [Item()]
        if isinstance(last.element, Coil):
            return Branch([*prefix, *items], [], last.element)
        return Branch([*prefix, *items, last] if last.element is not None or last.branches
                      else [*prefix, *items])
    groups: list[list[list[Item]]] = []
    for path in paths:
        group = next((g for g in groups if g[0][0] is path[0]), None)
        if group is None:
            groups.append([path])
        else:
            group.append(path)
    return Branch(prefix, [fan_out(group) for group in groups])


def draw_network(network: S7Network, context: Context) -> LadderNetwork:
    """The network drawn as TIA draws it; NotDrawn when it cannot be (the caller keeps its
    listing)."""
    if network.language.upper() not in ("LAD", "FBD"):
        raise NotDrawn(network.language)
    return Drawer(network, context).draw()


def value_type_name(params: tuple[ParamValue, ...]) -> str:
    """The data type a typed row's first parameter names ("Time"), "" when none."""
    if params and isinstance(params[0], int) and params[0] in set(typed.ValueType):
        return typed.ValueType(params[0]).name.capitalize()
    return ""


__all__ = ["Context", "NotDrawn", "Pin", "draw_network"]
