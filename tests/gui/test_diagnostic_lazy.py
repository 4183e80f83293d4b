"""The live ladder of a large program: items, overlays and op → cell maps made only for the
networks shown, and the same drawing, power and highlighting as if all were made at once."""

from __future__ import annotations

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.plc.session import PlcRun
from ladderworks.gui.docks import snapshot_gate
from ladderworks.gui.docks.cell_map import cell_ops, network_power, standard_cells
from ladderworks.gui.docks.diagnostic import DiagnosticDock
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks

COUNT = 240  # networks: far more than a dock shows at once


def network_text(index: int, changed: bool = False) -> str:
    """One network of four kinds: series, parallel, a box, a non-standard coding."""
    kind = index % 4
    coil = f"R{index}.{6 if changed else 2}"
    if kind == 0:
        return f"RD X0.0\nAND R{index}.1\nWRT {coil}\n"
    if kind == 1:
        return f"RD X0.1\nOR R{index}.3\nAND.NOT X0.2\nWRT {coil}\n"
    if kind == 2:
        return "RD X0.0\nSUB 8\n1111\n1111\nR0100\nR0300\n"
    return f"RD X0.0\nRD.STK X0.1\nAND.STK\nWRT {coil}\n"


def program_text(changed: int | None = None) -> str:
    """COUNT networks; network `changed` writes another coil bit."""
    body = "".join(network_text(i, i == changed) for i in range(COUNT))
    return f"%@3\n{body}%\n"


def shown_dock(window: MainWindow, text: str) -> DiagnosticDock:
    """The diagnostic dock, 500 px tall, with `text` compiled, loaded and running."""
    docks = plc_docks(window)
    assert docks.session.load_program(parse(text).program).ok
    docks.session.start()
    dock = docks.diagnostic
    dock.show()
    dock.raise_()
    dock.view.resize(600, 500)
    dock.view.grab()  # paints: makes the items of the networks on screen
    return dock


def test_only_the_networks_on_screen_are_made(window: MainWindow) -> None:
    dock = shown_dock(window, program_text())
    view = dock.view
    assert len(view.networks) == len(view.network_items) == len(view.live.overlays) == COUNT
    made = [index for index, _item in view.network_items.made()]
    assert made and made[0] == 0 and len(made) < 40
    overlays = [index for index, _overlay in view.live.overlays.made()]
    assert overlays and len(overlays) < 40
    assert COUNT - 1 not in made and COUNT - 1 not in overlays


def test_scrolling_to_the_last_network_makes_it_with_its_power(window: MainWindow) -> None:
    dock = shown_dock(window, program_text())
    view, session = dock.view, dock.session
    last = COUNT - 1  # kind 3: RD X0.0 / RD.STK X0.1 / AND.STK / WRT R239.2
    session.set_bit(parse_address("X0.0"), 1)
    session.set_bit(parse_address("X0.1"), 1)
    session.run_scans(2)
    view.centerOn(view.cell_rect(last, (0, 0)).center())
    dock._repaint()
    view.grab()
    item = view.network_items[last]
    assert item.network is view.networks[last] and item.number == COUNT
    assert item.pos().y() == view.layout_.tops[last]
    overlay = view.live.overlays[last]
    assert overlay.pos().y() == view.layout_.tops[last]
    snapshot = session.run.snapshot()
    network = view.networks[last]
    binary = session.run.binary
    assert binary is not None
    expected = network_power(network, snapshot.bit,
                             cell_ops(network, view.live.ops[last], binary),
                             snapshot.disabled,
                             snapshot.power_flow if snapshot.monitored else b"", {})
    assert overlay.power == expected
    assert overlay.power.coils  # both contacts closed: the coil is on
    assert len(expected.closed) == 2


def test_op_cells_are_the_standard_coding_and_cell_of_finds_every_op(
        window: MainWindow) -> None:
    dock = shown_dock(window, program_text())
    live = dock.view.live
    binary = dock.session.run.binary
    assert binary is not None
    for index, network in enumerate(dock.view.networks):
        cells = live.cells(index)
        assert cells == cell_ops(network, live.ops[index], binary)
        if index % 4 != 3:  # standard coding: the op of each cell in coding order
            coded = standard_cells(network)
            assert cells == {cell: op for (cell, _ins), op in
                             zip(coded, live.ops[index], strict=True) if cell is not None}
    for op in range(len(binary.ops)):  # as the search over every network found it
        expected = next(((index, cell) for index in range(COUNT)
                         for cell, found in live.cells(index).items() if found == op), None)
        assert live.cell_of(op) == expected
    assert live.cell_of(len(binary.ops)) is None and live.cell_of(-1) is None


def test_a_search_marks_a_network_off_screen(window: MainWindow) -> None:
    dock = shown_dock(window, program_text())
    dock.search.setText(f"R{COUNT - 3}.2")  # the coil of network COUNT - 3, far down
    dock.where_written()
    view = dock.view
    network, cell = dock.hits[0]
    assert network == COUNT - 3 and cell in view.live.overlays[network].marked
    view.grab()
    assert network in dict(view.network_items.made())  # centred on it: drawn


def test_compiling_again_lays_out_only_the_changed_networks(window: MainWindow) -> None:
    dock = shown_dock(window, program_text())
    before = list(dock.view.networks)
    changed = 5
    shown_dock(window, program_text(changed))
    after = dock.view.networks
    assert after[changed] is not before[changed]
    assert all(after[i] is before[i] for i in range(COUNT) if i != changed)
    program = parse(program_text(changed)).program
    assert after == [layout_network(net.instructions, net.comments)
                     for net in program.networks]


def test_each_network_lets_a_due_scan_go_first_before_it_paints(
        window: MainWindow, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = shown_dock(window, program_text())
    due = [0.05]
    monkeypatch.setattr(PlcRun, "threaded", property(lambda _self: True))
    monkeypatch.setattr(PlcRun, "due_in", lambda _self: due[0])
    sleeps: list[float] = []
    monkeypatch.setattr(snapshot_gate.time, "sleep", sleeps.append)
    dock.view.grab()  # no scan due within the paint: it never pauses
    assert dock.gate.yields == 0 and sleeps == []
    due[0] = 0.0  # a scan running, or waiting for the interpreter
    dock.view.grab()
    made = len(list(dock.view.network_items.made()))
    assert dock.gate.yields >= made > 3  # the view, then each network on screen
    assert all(0 < pause < 0.002 for pause in sleeps)
