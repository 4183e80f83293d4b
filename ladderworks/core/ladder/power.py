"""Power flow through a drawn network, evaluated on the grid itself (left to right only)."""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.instructions import Write
from ladderworks.core.ladder.decompose import NodeNets
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork


def powered_nets(source: int, edges: list[tuple[int, int]]) -> set[int]:
    """The nets power reaches from `source` along one-way edges (closed contacts, boxes)."""
    powered = {source}
    changed = True
    while changed:
        changed = False
        for src, dst in edges:
            if src in powered and dst not in powered:
                powered.add(dst)
                changed = True
    return powered


class PowerFlow:
    """Which nodes of a network carry power for given contact values.

    Power starts at the left rail and passes a contact only from its left end to its right
    end when the contact is closed; wires and vertical links join nodes. A box's W1 output is
    not modelled (it depends on the instruction): `output_node_power` is None there; its further
    output pins (Fatek's FO1 …) carry the bit they read."""

    def __init__(self, network: LadderNetwork, value: Callable[[Address], bool]) -> None:
        self.network = network
        self._nets = NodeNets(network)
        left = self._nets.net((0, 0))
        edges: list[tuple[int, int]] = []
        for (r, c), element in network.cells.items():
            if (isinstance(element, Contact) and element.address is not None
                    and value(element.address) != element.negated):
                edges.append((self._nets.net((r, c)), self._nets.net((r, c + 1))))
            if isinstance(element, FunctionBox):  # an output pin carries its bit (FO1 …)
                edges.extend((left, self._nets.net((r + offset, c + element.width)))
                             for offset, contact in element.outputs
                             if contact.address is not None and value(contact.address))
        self._powered = powered_nets(left, edges)

    def node(self, row: int, node: int) -> bool:
        """True when node (row, k) carries power."""
        return self._nets.net((row, node)) in self._powered

    def coils(self) -> list[tuple[Cell, Coil, bool]]:
        """Each coil with the power it gets (inverted for WRT.NOT): what WRT/WRT.NOT write;
        a SET or RST coil acts only when it is True."""
        out = []
        for (r, c), element in self.network.elements():
            if isinstance(element, Coil):
                out.append(((r, c), element, self.node(r, c) != element.negated))
        return out

    def writes(self) -> list[tuple[Address, bool]]:
        """The bits the coils change, top to bottom: WRT always, SET (→ 1) and RST (→ 0)
        only when they get power."""
        out: list[tuple[Address, bool]] = []
        for _, coil, power in self.coils():
            if coil.address is None:
                continue
            if coil.write is Write.OUT:
                out.append((coil.address, power))
            elif power:
                out.append((coil.address, coil.write is Write.SET))
        return out

    def pins(self, anchor: Cell) -> list[bool]:
        """Power at each control input of the box anchored at `anchor`, first to last."""
        box = self.network.cells[anchor]
        assert isinstance(box, FunctionBox)
        return [self.node(anchor[0] + p, anchor[1]) for p in box.pins]
