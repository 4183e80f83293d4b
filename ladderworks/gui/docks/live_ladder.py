"""Power flow on a scene of network drawings: overlays kept in step with PLC snapshots."""

from __future__ import annotations

import bisect

from PySide6.QtCore import QRectF
from PySide6.QtWidgets import QGraphicsScene

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.instructions import ParamKind
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.model import Cell, FunctionBox, LadderNetwork
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.watch.pins import PinPlace, pin_places, pin_values
from ladderworks.core.watch.values import Memory
from ladderworks.gui.docks.cell_map import (
    binary_networks,
    cell_ops,
    network_power,
    op_key,
    stack_dialect,
)
from ladderworks.gui.docks.power_overlay import PowerOverlay
from ladderworks.gui.editor.geometry import Layout, RowMetrics
from ladderworks.gui.editor.lazy_items import LazyItems
from ladderworks.gui.plc_session import PlcSnapshot


def match_networks(networks: list[LadderNetwork], binary: BinaryProgram,
                   spans: list[range] | None = None) -> list[list[int]] | None:
    """The binary's op indices for each drawn network ([] for blank ones), or None when the
    drawing does not code to exactly the binary's ops. `spans`: a drawing of a dialect's own
    model (S7's graph, source_model.py) gives the program's networks each drawn network was
    lowered to, the drawing already known to be the program (`spanned_ops`)."""
    if spans is not None:
        return spanned_ops(networks, binary, spans)
    groups = binary_networks(binary)
    result: list[list[int]] = []
    next_group = 0
    for network in networks:
        instructions, _ = network_to_instructions(network, dialect=stack_dialect(binary))
        if not instructions:
            if network.is_empty() and not network.comments:
                result.append([])
                continue
            return None
        if next_group >= len(groups):
            return None
        ops = groups[next_group]
        keys = [op_key(i.name, i.operand, i.params) for i in instructions]
        if keys != [op_key(binary.ops[k].name, binary.ops[k].operand, binary.ops[k].params)
                    for k in ops]:
            return None
        result.append(ops)
        next_group += 1
    return result if next_group == len(groups) else None


def spanned_ops(networks: list[LadderNetwork], binary: BinaryProgram,
                spans: list[range]) -> list[list[int]]:
    """The ops of each drawn network: those of the program's networks in its span (a network
    past the spans, the blank one at the end, has none)."""
    by_network: dict[int, list[int]] = {}
    for index, op in enumerate(binary.ops):
        by_network.setdefault(op.source.network, []).append(index)
    return [[op for n in spans[i] for op in by_network.get(n, [])] if i < len(spans) else []
            for i in range(len(networks))]


def box_values(box: FunctionBox, snapshot: PlcSnapshot) -> list[str]:
    """`R100=12` for each address parameter of a box (its data width read little-endian); a
    box drawn from a source's model (S7) shows its operands by name, not the engine's."""
    if box.named:
        return []
    spec = box.spec
    names = {p.name: value for p, value in zip(spec.params, box.params, strict=False)}
    out: list[str] = []
    for param, value in zip(spec.params, box.params, strict=False):
        if not isinstance(value, Address) or param.kind is ParamKind.TABLE:
            continue
        width = param.width
        if isinstance(width, str):
            given = names.get(width)
            width = given if isinstance(given, int) and given in (1, 2, 4) else 1
        if value.bit is not None:
            out.append(f"{value}={snapshot.bit(value)}")
        else:
            out.append(f"{value}={snapshot.read(value, width)}")
    return out


class LivePower:
    """Green power flow over the network items of a scene, from the session's snapshots.

    An overlay, and the op index of each cell of its network, is made only when first needed
    (its network on screen, or asked for): a real program has 10,000+ networks."""

    def __init__(self, scene: QGraphicsScene) -> None:
        self.scene = scene
        self.networks: list[LadderNetwork] = []
        self.overlays: LazyItems[PowerOverlay] = LazyItems(self._make_overlay)
        self.ops: list[list[int]] = []
        self.binary: BinaryProgram | None = None
        self.repaints = 0  # overlays repainted since creation (for the benchmark)
        self._tops: list[float] = []  # where each network is stacked (copied at attach)
        self._rows: list[RowMetrics] = []
        self._cells: list[dict[Cell, int] | None] = []  # op index of each element cell
        self._firsts: list[int] = []  # first op of each network with ops (cell_of bisects)
        self._owners: list[int] = []  # the network of each entry of _firsts
        self.symbols: SymbolTable | None = None  # a named box's pins resolve with these
        self.dialect: str | None = None
        self._pins: dict[tuple[int, Cell], list[PinPlace]] = {}  # a named box's pin places

    @property
    def attached(self) -> bool:
        """True while overlays are shown."""
        return self.binary is not None

    def attach(self, networks: list[LadderNetwork], layout: Layout, binary: BinaryProgram,
               ops: list[list[int]], symbols: SymbolTable | None = None,
               dialect: str | None = None) -> None:
        """Put an overlay on each network (where `layout` stacks it, with its rows) for the ops
        of `binary`; each is made when first shown. A box with named pins (S7) shows each
        pin's operand value beside it, found with `symbols` in `dialect`."""
        self.detach()
        self.symbols, self.dialect = symbols, dialect
        self._pins = {}
        if not len(ops) == len(networks) == len(layout.tops) == len(layout.rows):
            raise ValueError("one op group and one place per network")
        self.networks = list(networks)
        self.binary = binary
        self.ops = ops
        self._tops = list(layout.tops)
        self._rows = list(layout.rows)
        self._cells = [None] * len(networks)
        self._firsts = [group[0] for group in ops if group]
        self._owners = [index for index, group in enumerate(ops) if group]
        self.overlays.reset(len(networks))

    def _make_overlay(self, index: int) -> PowerOverlay:
        overlay = PowerOverlay(self.networks[index], self._rows[index])
        overlay.setPos(0, self._tops[index])
        self.scene.addItem(overlay)
        return overlay

    def cells(self, network: int) -> dict[Cell, int]:
        """The op index of each element cell of network `network` (worked out once)."""
        found = self._cells[network]
        if found is None:
            assert self.binary is not None
            found = cell_ops(self.networks[network], self.ops[network], self.binary)
            self._cells[network] = found
        return found

    def restack(self, layout: Layout) -> None:
        """The networks' rows changed height (View › Element names): follow `layout`."""
        self._tops = list(layout.tops)
        self._rows = list(layout.rows)
        for index, overlay in self.overlays.made():
            if index < len(self._rows):
                overlay.set_rows(self._rows[index])
                overlay.setPos(0, self._tops[index])

    def detach(self) -> None:
        """Remove the overlays (off-line)."""
        for _index, overlay in self.overlays.made():
            self.scene.removeItem(overlay)
        self.overlays.reset(0)
        self.networks = []
        self._cells = []
        self._firsts = []
        self._owners = []
        self.ops = []
        self.binary = None

    def _shown(self, visible: QRectF | None) -> range:
        """The networks whose bands `visible` reaches (all when None)."""
        count = len(self.networks)
        if visible is None or not self._tops:
            return range(count)
        first = max(bisect.bisect_right(self._tops, visible.top()) - 1, 0)
        last = max(bisect.bisect_right(self._tops, visible.bottom()) - 1, 0)
        return range(min(first, count), min(last + 1, count))

    def update(self, snapshot: PlcSnapshot, forced: dict[Address, bool],
               visible: QRectF | None = None) -> int:
        """Recompute the power of the networks in `visible` (all when None); returns how many
        overlays changed."""
        changed = 0
        for index in self._shown(visible):
            overlay = self.overlays[index]
            if visible is not None and not visible.intersects(overlay.sceneBoundingRect()):
                continue
            network = self.networks[index]
            power = network_power(network, snapshot.bit, self.cells(index), snapshot.disabled,
                                  snapshot.power_flow if snapshot.monitored else b"", forced)
            memory = Memory(snapshot.bit, snapshot.read)
            values = {cell: (self._pin_values(index, cell, element, memory) if element.named
                             else box_values(element, snapshot))
                      for cell, element in network.cells.items()
                      if isinstance(element, FunctionBox)}
            if overlay.set_state(power, values):
                changed += 1
        self.repaints += changed
        return changed

    def _pin_values(self, index: int, cell: Cell, box: FunctionBox,
                    memory: Memory) -> list[str]:
        """One value per named pin of the box at `cell` of network `index` ("" for none)."""
        places = self._pins.get((index, cell))
        if places is None:
            places = self._pins[(index, cell)] = pin_places(box, self.symbols, self.dialect)
        return pin_values(places, memory)

    def op_at(self, network: int, cell: Cell) -> int | None:
        """The op index of the element anchored at `cell` of network `network`."""
        if not 0 <= network < len(self.networks):
            return None
        return self.cells(network).get(cell)

    def cell_of(self, op: int) -> tuple[int, Cell] | None:
        """(network, cell) where op `op` is drawn."""
        # the op groups are consecutive runs of op indices: only one network can hold `op`
        at = bisect.bisect_right(self._firsts, op) - 1
        if at < 0:
            return None
        network = self._owners[at]
        if op not in self.ops[network]:
            return None
        for cell, found in self.cells(network).items():
            if found == op:
                return network, cell
        return None
