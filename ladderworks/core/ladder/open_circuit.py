"""Where a network's circuit is broken: the cells to mark while the user is still drawing."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.ladder.decompose import NodeNets
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.ladder.power import powered_nets


@dataclass(frozen=True, slots=True)
class OpenEnd:
    """A break in the circuit at a cell.

    `side` is "gap" for an empty cell the circuit should cross (a wire or an element is
    missing there); otherwise the element in the cell is open on that side ("left": nothing
    feeds it, "right": it leads nowhere)."""

    cell: Cell
    side: str

    @property
    def gap(self) -> bool:
        """True for an empty cell where the circuit breaks."""
        return self.side == "gap"


def _nodes_by_net(network: LadderNetwork, nets: NodeNets) -> dict[int, list[Cell]]:
    found: dict[int, list[Cell]] = {}
    for row in range(network.used_rows()):
        for node in range(network.columns + 1):
            found.setdefault(nets.net((row, node)), []).append((row, node))
    return found


def open_ends(network: LadderNetwork) -> list[OpenEnd]:
    """The breaks of a drawn network, one per broken place, in reading order.

    Power comes from the left rail (and from a box's W1 output and output pins); it is wanted
    by coils and by a box's control inputs. A chain of contacts that gets no power is marked
    once, left of its first element; a chain that leads to no coil or box input is marked once,
    right of its last element: on the empty cell there (a gap), or on the element's side when
    the next cell is taken. A network kept as a listing has none."""
    if network.listing is not None or not network.cells:
        return []
    nets = NodeNets(network)
    sources = {nets.net((0, 0))}
    sinks: set[int] = set()
    edges: list[tuple[int, int]] = []
    wants: set[int] = set()  # nets something must feed (coils, box inputs)
    for (row, col), element in network.elements():
        if isinstance(element, Contact):
            src, dst = nets.net((row, col)), nets.net((row, col + 1))
            if src != dst:
                edges.append((src, dst))
        elif isinstance(element, Coil):
            sinks.add(nets.net((row, col)))
            wants.add(nets.net((row, col)))
        elif isinstance(element, FunctionBox):
            for pin in element.pins:
                sinks.add(nets.net((row + pin, col)))
                wants.add(nets.net((row + pin, col)))
            if element.has_output and col + element.width <= network.columns:
                sources.add(nets.net((row, col + element.width)))
            for offset, _reads in element.outputs:  # its further output pins (Fatek's FO1 …)
                if col + element.width <= network.columns:
                    sources.add(nets.net((row + offset, col + element.width)))
    fed = set().union(*(powered_nets(source, edges) for source in sources))
    backwards = [(dst, src) for src, dst in edges]
    feeding = set().union(*(powered_nets(sink, backwards) for sink in sinks))
    entered = {dst for _, dst in edges}
    left = {src for src, _ in edges}
    unfed = {net for net in left | wants if net not in fed and net not in entered}
    dead = {dst for _, dst in edges if dst not in feeding and dst not in left}
    if not unfed and not dead:
        return []
    nodes = _nodes_by_net(network, nets)
    marks: list[OpenEnd] = []
    for net in unfed:
        row, node = min(nodes[net], key=lambda n: (n[1], n[0]))
        if node >= 1 and network.element_at(row, node - 1) is None:
            marks.append(OpenEnd((row, node - 1), "gap"))
        else:
            marks.append(OpenEnd((row, node), "left"))
    for net in dead:
        row, node = min(nodes[net], key=lambda n: (-n[1], n[0]))
        if node <= network.coil_column and network.element_at(row, node) is None:
            marks.append(OpenEnd((row, node), "gap"))
        else:
            marks.append(OpenEnd((row, node - 1), "right"))
    return sorted(set(marks), key=lambda mark: mark.cell)


def open_cells(network: LadderNetwork) -> set[Cell]:
    """The cells that break the network's circuit (see `open_ends`)."""
    return {mark.cell for mark in open_ends(network)}
