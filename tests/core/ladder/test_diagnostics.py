"""Each grid diagnostic, triggered by a drawn network, reported at the right cell."""

from __future__ import annotations

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.diagnostics import MESSAGES
from ladderworks.core.ladder.decompose import network_to_instructions, read_grid
from ladderworks.core.ladder.layout import draw_rung
from ladderworks.core.ladder.logic import Leaf, Logic, Parallel, Rung, Series
from ladderworks.core.ladder.model import WIRE, Coil, Contact, FunctionBox, LadderNetwork


def _c(text: str, negated: bool = False) -> Contact:
    return Contact(parse_address(text), negated)


def _coil(text: str) -> Coil:
    return Coil(parse_address(text))


def _net(columns: int, rows: int, cells: dict, links: set | None = None) -> LadderNetwork:
    return LadderNetwork(columns, rows, dict(cells), set(links or ()))


def _wires(row: int, first: int, last: int) -> dict:
    return {(row, c): WIRE for c in range(first, last + 1)}


def _found(network: LadderNetwork) -> set[tuple[str, tuple[int, int] | None]]:
    code, diagnostics = network_to_instructions(network, 0)
    assert code is None
    assert all(d.network == 0 and d.code in MESSAGES for d in diagnostics)
    return {(d.code, d.cell) for d in diagnostics}


def _rung_row(columns: int = 4) -> dict:
    """X0.0 then wires to the coil Y0.0: a working row 0."""
    return {(0, 0): _c("X0.0"), **_wires(0, 1, columns - 1), (0, columns): _coil("Y0.0")}


def test_a_working_network_has_no_diagnostic() -> None:
    code, diagnostics = network_to_instructions(_net(4, 1, _rung_row()))
    assert diagnostics == [] and [i.name for i in code or []] == ["RD", "WRT"]


def test_open_circuit_at_the_contact_that_leads_nowhere() -> None:
    network = _net(4, 2, {**_rung_row(), (1, 0): _c("X0.1")})
    assert ("open-circuit", (1, 0)) in _found(network)


def test_element_not_connected_to_the_left_rail() -> None:
    network = _net(4, 2, {**_rung_row(), (1, 2): _c("X0.1"), (1, 3): WIRE}, {(0, 4)})
    assert ("not-connected", (1, 2)) in _found(network)


def test_coil_not_at_the_right_end() -> None:
    network = _net(4, 1, {(0, 0): _c("X0.0"), (0, 1): WIRE, (0, 2): _coil("Y0.0")})
    assert ("coil-not-right", (0, 2)) in _found(network)


def test_coil_straight_on_the_left_rail() -> None:
    wired = _net(4, 1, {**_wires(0, 0, 3), (0, 4): _coil("Y0.0")})
    assert _found(wired) == {("coil-on-rail", (0, 4))}
    at_rail = _net(4, 1, {(0, 0): _coil("Y0.0")})
    assert ("coil-on-rail", (0, 0)) in _found(at_rail)


def test_bridge_circuit_at_the_element_in_the_middle() -> None:
    # a─P─b─┐        a: rail→P, b: P→out, x: P→Q (the bridge), c: rail→Q, d: Q→out
    #   └x─Q │
    # c──Q─d─┘
    cells = {(0, 0): _c("X0.0"), (0, 1): _c("X0.1"), (0, 2): WIRE, (0, 3): WIRE,
             (1, 1): _c("X0.2"),
             (2, 0): _c("X0.3"), (2, 1): WIRE, (2, 2): _c("X0.4"),
             (0, 4): _coil("Y0.0")}
    network = _net(4, 3, cells, {(0, 1), (1, 2), (0, 3), (1, 3)})
    assert _found(network) == {("bridge", (1, 1))}


def test_short_circuit_at_the_bypassed_contact() -> None:
    cells = {**_rung_row(), (0, 1): _c("X0.1"), (1, 1): WIRE}
    network = _net(4, 2, cells, {(0, 1), (0, 2)})
    assert _found(network) == {("short-circuit", (0, 1))}


def _nest(levels: int) -> Logic:
    logic: Logic = Leaf(Contact(Address(Area.R, 0, 0)))
    for i in range(1, levels + 1):
        logic = Series((Leaf(Contact(Address(Area.X, i, 0))),
                        Parallel((logic, Leaf(Contact(Address(Area.X, i, 1)))))))
    return logic


def test_stack_deeper_than_st8_at_the_contact_that_overflows() -> None:
    fits = draw_rung(Rung(logic=_nest(8), coils=[_coil("Y0.0")]))
    assert read_grid(fits)[1] == []
    network = draw_rung(Rung(logic=_nest(9), coils=[_coil("Y0.0")]))
    innermost = next(cell for cell, e in network.elements()
                     if isinstance(e, Contact) and e.address == Address(Area.R, 0, 0))
    assert _found(network) == {("stack-depth", innermost)}


def test_right_to_left_flow_at_the_contact_fed_from_the_output_side() -> None:
    # X0.2 sits with its left end on the output and its right end between X0.0 and X0.1:
    # power could only pass it from right to left.
    cells = {(0, 0): _c("X0.0"), (0, 1): WIRE, (0, 2): _c("X0.1"), (0, 3): WIRE,
             (0, 4): _coil("Y0.0"),
             (1, 1): _c("X0.2"),
             (2, 1): WIRE, (2, 2): WIRE, (2, 3): WIRE}
    network = _net(4, 3, cells, {(0, 2), (1, 1), (0, 4), (1, 4)})
    assert ("reverse-flow", (1, 1)) in _found(network)


def test_network_without_coil_or_function() -> None:
    network = _net(4, 1, {(0, 0): _c("X0.0"), (0, 1): _c("X0.1")})
    assert _found(network) == {("empty-network", (0, 0))}


def test_box_with_an_unconnected_control_input() -> None:
    box = FunctionBox.new("CTR", (1,))
    cells = {(3, 0): _c("X0.0"), **_wires(3, 1, 1), (0, 2): box, (0, 4): _coil("R1.0")}
    network = _net(4, 4, cells)
    assert ("box-inputs", (0, 2)) in _found(network)


def test_element_without_an_address() -> None:
    network = _net(4, 1, {**_rung_row(), (0, 1): Contact()})
    assert _found(network) == {("no-address", (0, 1))}


def test_coils_on_different_points() -> None:
    cells = {**_rung_row(), (1, 0): _c("X0.1"), **_wires(1, 1, 3), (1, 4): _coil("Y0.1")}
    network = _net(4, 2, cells)
    assert ("coil-branch", (1, 4)) in _found(network)


def test_only_coils_after_a_function_output() -> None:
    cells = {(0, 0): _c("X0.0"), (0, 1): WIRE, (0, 2): FunctionBox.new("TMR", (1,)),
             (0, 4): _c("X0.1"), (0, 5): WIRE, (0, 6): _coil("Y0.0")}
    network = _net(6, 1, cells)
    assert ("box-output", (0, 4)) in _found(network)


def test_two_boxes_in_one_network() -> None:
    cells = {(0, 0): _c("X0.0"), (0, 2): FunctionBox.new("TMR", (1,)),
             (1, 0): _c("X0.1"), (1, 2): FunctionBox.new("TMR", (2,))}
    assert ("box-twice", (1, 2)) in _found(_net(4, 2, cells))


def test_box_with_wrong_parameters() -> None:
    cells = {(0, 0): _c("X0.0"), (0, 1): WIRE, (0, 2): FunctionBox.new("TMR", (500,)),
             (0, 4): _coil("Y0.0")}
    assert ("param-range", (0, 2)) in _found(_net(4, 1, cells))


def test_an_empty_network_is_no_error() -> None:
    assert network_to_instructions(LadderNetwork()) == (None, [])


def test_a_chain_entered_from_the_side_is_a_coil_branch() -> None:
    # Y0.1 hangs after X0.1 (fed from Y0.0's point) but also after X0.2, straight from the rail.
    cells = {**_rung_row(), (1, 1): _c("X0.1"), (1, 2): WIRE, (1, 3): WIRE,
             (1, 4): _coil("Y0.1"), (2, 0): _c("X0.2"), (2, 1): WIRE}
    network = _net(4, 3, cells, {(0, 1), (1, 2)})
    assert ("coil-branch", (1, 4)) in _found(network)
