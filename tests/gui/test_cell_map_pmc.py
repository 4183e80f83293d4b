"""cell_map on SET/RST coils, output chains and PMC boxes: the core's coding, power on coils."""

from __future__ import annotations

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Coil, FunctionBox, LadderNetwork
from ladderworks.gui.docks.cell_map import network_power, standard_cells


def _network(text: str) -> LadderNetwork:
    return layout_network(parse(f"%@3\n{text}\n%\n").program.instructions())


def test_standard_cells_follow_the_output_chain_and_set_reset_coils() -> None:
    text = "RD X0.0\nSET R1.0\nAND X0.1\nRST R1.1\nWRT R1.2"
    network = _network(text)
    coded = standard_cells(network)
    assert [ins.name for _, ins in coded] == ["RD", "SET", "AND", "RST", "WRT"]
    for cell, ins in coded:
        assert cell is not None
        element = network.cells[cell]
        assert getattr(element, "address", None) == ins.operand


def test_standard_cells_of_a_box_give_the_box_and_its_coils() -> None:
    network = _network("RD X0.0\nDIFU 3\nSET R1.0\nRST R1.1")
    coded = standard_cells(network)
    assert [ins.name for _, ins in coded] == ["RD", "DIFU", "SET", "RST"]
    box_cell = coded[1][0]
    assert box_cell is not None and isinstance(network.cells[box_cell], FunctionBox)
    assert all(isinstance(network.cells[c], Coil) for c, _ in coded[2:] if c is not None)


def test_set_and_reset_coils_are_live_when_power_reaches_them() -> None:
    network = _network("RD X0.0\nSET R1.0\nRST R1.1\nWRT R1.2")
    column = network.coil_column

    for on in (False, True):
        bits = {parse_address("X0.0"): int(on)}
        power = network_power(network, lambda a, b=bits: b.get(a, 0))
        assert ((0, column) in power.coils) is on  # SET acts
        assert ((1, column) in power.coils) is on  # RST acts (its bit is 0 either way)
        assert (2, column) not in power.coils  # WRT shows its bit, 0 here
