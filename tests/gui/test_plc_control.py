"""The PLC control screen: open, compile with green stripes, START / STOP, scan figures."""

from __future__ import annotations

import os
from pathlib import Path

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.core.ladder.model import Coil, Contact
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import override_code, plc_docks, set_switch

SPINDLE = paths.EXAMPLES / "spindle_override.LAD"


def shot(widget, name: str) -> None:
    """Save a screenshot when LADDERWORKS_SHOTS names a folder (xvfb runs)."""
    folder = os.environ.get("LADDERWORKS_SHOTS")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        widget.grab().save(str(Path(folder) / name))


def test_spindle_override_compile_start_watch_stop(qtbot: QtBot, window: MainWindow) -> None:
    docks = plc_docks(window)
    session, control, diagnostic = docks.session, docks.control, docks.diagnostic
    window.resize(1500, 950)
    control.show()
    control.raise_()
    assert control.open_file(SPINDLE)
    lines = control.editor.blockCount()
    progress: list[int] = []
    control.compile_progress.connect(progress.append)
    control.stripe_ms = 30
    control.compile()
    qtbot.waitUntil(lambda: len(progress) >= 4, timeout=5000)
    assert control.compiling and 0 < control.editor.converted_lines < lines
    shot(window, "plc_control_compiling.png")
    with qtbot.waitSignal(control.compile_finished, timeout=10000) as finished:
        pass
    assert finished.args[0].ok
    assert progress == sorted(progress) and len(set(progress)) >= 4  # the stripes advance
    assert control.editor.converted_lines == lines
    assert "Compile finished" in control.message.text()
    assert session.run.binary is not None and not session.run.running
    assert control.indicator.text() == "STOPPED"
    shot(window, "plc_control_finished.png")

    control.control_actions["action_plc_start"].trigger()
    assert session.run.running and control.indicator.text() == "RUNNING"
    set_switch(session, 5)
    session.step(16)
    assert session.run.read(parse_address("G30")) == override_code(5)
    assert "scans 2" in control.figures.text()

    diagnostic.show()
    diagnostic.raise_()
    window.resizeDocks([diagnostic], [820], Qt.Orientation.Horizontal)
    qtbot.waitUntil(diagnostic.isVisible)
    assert session.run.engine.monitored
    session.step(8)
    live = diagnostic.view.live
    r102_5 = parse_address("R102.5")
    checked_coils = 0
    for index, network in enumerate(diagnostic.view.networks):
        power = live.overlays[index].power
        for cell, element in network.elements():
            if isinstance(element, Contact) and element.address.area.value == "R":
                diagnostic.view.ensureVisible(diagnostic.view.cell_rect(index, cell))
                qtbot.waitUntil(lambda i=index: bool(live.overlays[i].power.nodes))
                power = live.overlays[index].power
                on = (element.address == r102_5) != element.negated
                assert (cell in power.closed) == on, (index, cell, element)
            if isinstance(element, Coil) and element.address.area.value == "G":
                bit = element.address.bit
                assert (cell in power.coils) == bool(override_code(5) >> bit & 1), element
                checked_coils += 1
    assert checked_coils == 8
    shot(window, "plc_diagnostic_live.png")

    control.control_actions["action_plc_stop"].trigger()
    count = session.run.status().scan_count
    assert not session.run.running and control.indicator.text() == "STOPPED"
    assert session.step(100) == 0 and session.run.status().scan_count == count


def test_compile_errors_are_shown_inline(qtbot: QtBot, window: MainWindow) -> None:
    docks = plc_docks(window)
    control = docks.control
    control.set_text("%@3\nRD X2.1\nWRT Q3.0\nRD R1.0\nWRT Y0.0\n%\n")
    control.stripe_ms = 0
    result = control.compile()
    assert not result.ok
    assert control.editor.diagnostics and control.editor.diagnostics[0].line == 3
    assert control.editor.converted_lines == 2  # converted up to the first error
    assert "Compile failed" in control.message.text()
    assert docks.session.run.binary is None
    control.control_actions["action_plc_start"].trigger()
    assert not docks.session.run.running


def test_take_console_program_and_start_asks_with_forces(qtbot: QtBot,
                                                         window: MainWindow) -> None:
    assert window.load(SPINDLE)
    docks = plc_docks(window)
    control, session = docks.control, docks.session
    assert control.take_console_program()
    assert "RD.NOT" in control.editor.toPlainText()
    control.stripe_ms = 0
    assert control.compile().ok and session.run.binary is not None
    session.force(parse_address("X2.1"), 1)
    asked: list[int] = []
    control.confirm_forces = lambda count: asked.append(count) or False
    assert not control.start() and not session.run.running and asked == [1]
    control.confirm_forces = lambda count: True
    assert control.start() and session.run.running
    session.step(8)
    assert session.run.bit(parse_address("R102.1")) == 1  # the force acts: position 1
