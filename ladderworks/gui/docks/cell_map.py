"""Binary ops ⇄ ladder cells: which op a drawn element runs as, and live power on the grid.

No Qt here: the diagnostic view and on-line mode both paint what these functions compute.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryProgram, Op
from ladderworks.core.il.program import Instruction, LabelRef, Network, Program, ProgramRef
from ladderworks.core.instructions import Combine, Write, lookup
from ladderworks.core.ladder.decompose import NodeNets, read_grid
from ladderworks.core.ladder.logic import code_rung
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork, Wire
from ladderworks.core.ladder.power import powered_nets
from ladderworks.core.ladder.row_contacts import contact_combine

OpKey = tuple[str, object, tuple[object, ...]]


def op_key(name: str, operand: object, params: Sequence[object]) -> OpKey:
    """What an op does, without where it came from (compares source with binary): a
    subprogram or label reference as its number, as the binary holds it (`P44` is 44)."""
    return (name, operand, tuple(p.number if isinstance(p, ProgramRef | LabelRef) else p
                                 for p in params))


def binary_networks(binary: BinaryProgram) -> list[list[int]]:
    """Op indices of each network of a binary, in network order."""
    networks: list[list[int]] = []
    current = None
    for index, op in enumerate(binary.ops):
        if op.source.network != current or not networks:
            networks.append([])
            current = op.source.network
        networks[-1].append(index)
    return networks


def program_of(binary: BinaryProgram) -> Program:
    """The program held in a binary (no comments), network by network."""
    return Program(networks=[
        Network([Instruction(binary.ops[i].name, binary.ops[i].operand, binary.ops[i].params,
                             line=binary.ops[i].source.line) for i in ops])
        for ops in binary_networks(binary)])


def program_matches(program: Program, binary: BinaryProgram) -> bool:
    """True when `program` compiles to exactly the ops of `binary` (same order, same code)."""
    keys = [op_key(ins.name, ins.operand, ins.params)
            for net in program.networks for ins in net.instructions]
    return keys == [op_key(op.name, op.operand, op.params) for op in binary.ops]


def stack_dialect(binary: BinaryProgram) -> str:
    """The dialect a drawing is read in to match the binary, the one it was compiled in: a
    registered dialect's own (its MPS/MRD/MPP branches code in it), "fanuc" for a LADDER-III
    program (its 30i map: G1010 is in range there, not in the seed's), else "seed"."""
    return binary.dialect or "seed"


def standard_cells(network: LadderNetwork, dialect: str = "seed"
                   ) -> list[tuple[Cell | None, Instruction]]:
    """The core's standard coding of a drawn network (output chains included), each
    instruction with the cell it comes from (None for stack operations); [] when the network
    cannot be coded."""
    rung, _ = read_grid(network, dialect=dialect)  # a Delta MPS branch codes in Delta
    if rung is None:
        return []
    cells: list[Cell | None] = []
    code = code_rung(rung, cells)
    return list(zip(cells, code, strict=True))


def _same_element(element: object, op: Op) -> bool:
    spec = op.spec
    if isinstance(element, Contact) and element.function:  # an edge / comparison contact
        row = lookup(element.function)
        return (row is not None and contact_combine(spec) is not None
                and spec.operation is row.operation and tuple(op.params) == element.params)
    if isinstance(element, Contact):
        return (spec.is_contact and op.operand == element.address
                and spec.negated == element.negated)
    if isinstance(element, Coil):
        return (spec.is_coil and op.operand == element.address and spec.write is element.write
                and spec.negated == element.negated)
    if isinstance(element, FunctionBox):
        return op.name == element.name and tuple(op.params) == tuple(element.params)
    return False


def cell_ops(network: LadderNetwork, ops: Sequence[int], binary: BinaryProgram) -> dict[Cell, int]:
    """Op index of each element cell of a drawn network whose ops are `ops` in `binary`.

    The standard coding is matched op for op; a network kept in another coding (its original
    text) is matched element by element in drawing order (same kind, address and NOT)."""
    if network.listing is not None:
        return {}
    coded = standard_cells(network, stack_dialect(binary))
    keys = [op_key(ins.name, ins.operand, ins.params) for _, ins in coded]
    mine = [binary.ops[i] for i in ops]
    if keys == [op_key(op.name, op.operand, op.params) for op in mine]:
        return {cell: index for (cell, _), index in zip(coded, ops, strict=True)
                if cell is not None}
    found: dict[Cell, int] = {}
    free = list(ops)
    for cell, element in network.elements():
        for index in free:
            if _same_element(element, binary.ops[index]):
                found[cell] = index
                free.remove(index)
                break
    return found


def _contact_passed(element: Contact, index: int | None, flow: bytes) -> bool:
    """An edge / comparison contact is shown closed when the engine's recorded result of its
    op is on and that result is the test itself or the test in series (its READ / AND form);
    an OR form's result may come from the branch above it, so it is not shown closed."""
    row = lookup(element.function)
    return (row is not None and contact_combine(row) is not Combine.OR
            and index is not None and index < len(flow) and bool(flow[index]))


@dataclass(slots=True)
class NetworkPower:
    """What to paint green in one network: closed contacts, powered nodes, energised coils,
    box inputs and output; disabled and forced elements are listed for their tags."""

    closed: set[Cell] = field(default_factory=set)
    nodes: set[Cell] = field(default_factory=set)  # (row, node) carrying power
    coils: set[Cell] = field(default_factory=set)
    box_pins: dict[Cell, list[bool]] = field(default_factory=dict)
    box_out: set[Cell] = field(default_factory=set)
    disabled: set[Cell] = field(default_factory=set)
    forced: dict[Cell, int] = field(default_factory=dict)


def network_power(network: LadderNetwork, value: Callable[[Address], int],
                  cells: dict[Cell, int] | None = None, disabled: frozenset[int] = frozenset(),
                  flow: bytes = b"", forced: dict[Address, bool] | None = None) -> NetworkPower:
    """Power through a drawn network for the bit values `value` (memory after a scan).

    A contact passes power left to right when closed; a disabled contact is open, as the
    engine runs it. A WRT / WRT.NOT coil is energised when its bit is 1; a SET or RST coil
    when power reaches it (that is when it acts). A box's output is the engine's recorded
    result of its op (`flow`, when monitored), else the bit of its first WRT coil."""
    cells = cells or {}
    forced = forced or {}
    power = NetworkPower()
    if network.listing is not None:
        return power
    off = {cell for cell, op in cells.items() if op in disabled}
    power.disabled = off
    nets = NodeNets(network)
    edges: list[tuple[int, int]] = []
    boxes: list[tuple[Cell, FunctionBox]] = []
    for (r, c), element in network.cells.items():
        if (isinstance(element, Contact | Coil) and element.address is not None
                and element.address in forced):
            power.forced[(r, c)] = int(forced[element.address])
        if isinstance(element, Contact) and element.function:
            if (r, c) not in off and _contact_passed(element, cells.get((r, c)), flow):
                power.closed.add((r, c))
        elif isinstance(element, Contact) and element.address is not None:
            if (r, c) not in off and bool(value(element.address)) != element.negated:
                power.closed.add((r, c))
        elif isinstance(element, FunctionBox):
            boxes.append(((r, c), element))
    for anchor, box in boxes:
        index = cells.get(anchor)
        out = None
        if box.has_output:
            if index is not None and flow and index < len(flow):
                out = bool(flow[index])
            else:
                coil = next((e for e in network.cells.values() if isinstance(e, Coil)
                             and e.address is not None and e.write is Write.OUT), None)
                out = (coil is not None and coil.address is not None
                       and bool(value(coil.address)) != coil.negated)
            if out and index not in disabled:
                power.box_out.add(anchor)
    for r, c in power.closed:
        edges.append((nets.net((r, c)), nets.net((r, c + 1))))
    for anchor in power.box_out:
        powered_box = network.cells[anchor]
        assert isinstance(powered_box, FunctionBox)
        edges.append((nets.net((0, 0)), nets.net((anchor[0], anchor[1] + powered_box.width))))
    powered = powered_nets(nets.net((0, 0)), edges)
    for r in range(network.rows):
        for k in range(network.columns + 1):
            if nets.net((r, k)) in powered:
                power.nodes.add((r, k))
    for anchor, box in boxes:
        power.box_pins[anchor] = [(anchor[0] + p, anchor[1]) in power.nodes for p in box.pins]
    for (r, c), element in network.cells.items():
        if not isinstance(element, Coil) or element.address is None or (r, c) in off:
            continue
        on = bool(value(element.address)) if element.write is Write.OUT else (r, c) in power.nodes
        if on:
            power.coils.add((r, c))
    return power


def wire_powered(power: NetworkPower, cell: Cell, element: object) -> bool:
    """True when the wire in `cell` carries power (its left node is powered)."""
    return isinstance(element, Wire) and cell in power.nodes
