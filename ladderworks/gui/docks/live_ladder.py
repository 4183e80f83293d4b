"""Power flow on a scene of network drawings: overlays kept in step with PLC snapshots."""

from __future__ import annotations

from PySide6.QtCore import QRectF
from PySide6.QtWidgets import QGraphicsScene

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.instructions import ParamKind
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.model import Cell, FunctionBox, LadderNetwork
from ladderworks.gui.docks.cell_map import binary_networks, cell_ops, network_power, op_key
from ladderworks.gui.docks.power_overlay import PowerOverlay
from ladderworks.gui.editor.geometry import Layout
from ladderworks.gui.plc_session import PlcSnapshot


def match_networks(networks: list[LadderNetwork], binary: BinaryProgram) -> list[list[int]] | None:
    """The binary's op indices for each drawn network ([] for blank ones), or None when the
    drawing does not code to exactly the binary's ops."""
    groups = binary_networks(binary)
    result: list[list[int]] = []
    next_group = 0
    for network in networks:
        instructions, _ = network_to_instructions(network)
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


def box_values(box: FunctionBox, snapshot: PlcSnapshot) -> list[str]:
    """`R100=12` for each address parameter of a box (its data width read little-endian)."""
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
    """Green power flow over the network items of a scene, from the session's snapshots."""

    def __init__(self, scene: QGraphicsScene) -> None:
        self.scene = scene
        self.networks: list[LadderNetwork] = []
        self.overlays: list[PowerOverlay] = []
        self.cells: list[dict[Cell, int]] = []  # op index of each element cell, per network
        self.ops: list[list[int]] = []
        self.binary: BinaryProgram | None = None
        self.repaints = 0  # overlays repainted since creation (for the benchmark)

    @property
    def attached(self) -> bool:
        """True while overlays are shown."""
        return self.binary is not None

    def attach(self, networks: list[LadderNetwork], layout: Layout, binary: BinaryProgram,
               ops: list[list[int]]) -> None:
        """Put an overlay on each network (where `layout` stacks it, with its rows) for the ops
        of `binary`."""
        self.detach()
        self.networks = list(networks)
        self.binary = binary
        self.ops = ops
        self.cells = [cell_ops(net, group, binary) for net, group in zip(networks, ops,
                                                                          strict=True)]
        for network, top, rows in zip(networks, layout.tops, layout.rows, strict=True):
            overlay = PowerOverlay(network, rows)
            overlay.setPos(0, top)
            self.scene.addItem(overlay)
            self.overlays.append(overlay)

    def restack(self, layout: Layout) -> None:
        """The networks' rows changed height (View › Element names): follow `layout`."""
        for overlay, top, rows in zip(self.overlays, layout.tops, layout.rows, strict=False):
            overlay.set_rows(rows)
            overlay.setPos(0, top)

    def detach(self) -> None:
        """Remove the overlays (off-line)."""
        for overlay in self.overlays:
            self.scene.removeItem(overlay)
        self.overlays = []
        self.networks = []
        self.cells = []
        self.ops = []
        self.binary = None

    def update(self, snapshot: PlcSnapshot, forced: dict[Address, bool],
               visible: QRectF | None = None) -> int:
        """Recompute the power of the networks in `visible` (all when None); returns how many
        overlays changed."""
        changed = 0
        for index, overlay in enumerate(self.overlays):
            if visible is not None and not visible.intersects(overlay.sceneBoundingRect()):
                continue
            network = self.networks[index]
            power = network_power(network, snapshot.bit, self.cells[index], snapshot.disabled,
                                  snapshot.power_flow if snapshot.monitored else b"", forced)
            values = {cell: box_values(element, snapshot)
                      for cell, element in network.cells.items()
                      if isinstance(element, FunctionBox)}
            if overlay.set_state(power, values):
                changed += 1
        self.repaints += changed
        return changed

    def op_at(self, network: int, cell: Cell) -> int | None:
        """The op index of the element anchored at `cell` of network `network`."""
        if not 0 <= network < len(self.cells):
            return None
        return self.cells[network].get(cell)

    def cell_of(self, op: int) -> tuple[int, Cell] | None:
        """(network, cell) where op `op` is drawn."""
        for index, cells in enumerate(self.cells):
            for cell, found in cells.items():
                if found == op:
                    return index, cell
        return None
