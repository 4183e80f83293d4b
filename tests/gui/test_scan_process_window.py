"""The main window's real-time PLC scans in its own process: START, live values, the
diagnostic's power flow, forces and STOP work as they did on a thread, and the PLC control
says where the scans run, in both languages."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.core.plc.process_runner import ProcessRunner
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_docks_help import override_code, set_switch

SPINDLE = paths.EXAMPLES / "spindle_override.LAD"


def test_start_scans_in_the_scan_process_and_the_window_sees_it(qtbot: QtBot,
                                                               window: MainWindow) -> None:
    docks = window.plc_docks
    session, control, diagnostic = docks.session, docks.control, docks.diagnostic
    assert session.run.realtime and session.run.scan_process
    window.load(SPINDLE)
    qtbot.waitUntil(lambda: not window.editor.loading, timeout=10000)
    assert window.compile() is not None
    control.show()
    control.raise_()
    control.control_actions["action_plc_start"].trigger()
    assert session.run.running  # on a thread until the scan process has built the program
    qtbot.waitUntil(lambda: isinstance(session.run._runner, ProcessRunner), timeout=20000)
    set_switch(session, 5)
    g30 = parse_address("G30")
    qtbot.waitUntil(lambda: session.run.read(g30) == override_code(5), timeout=10000)
    qtbot.waitUntil(lambda: "scans in a process of their own" in control.figures.text(),
                    timeout=10000)

    diagnostic.show()
    diagnostic.raise_()
    window.resizeDocks([diagnostic], [820], Qt.Orientation.Horizontal)
    qtbot.waitUntil(diagnostic.isVisible)
    qtbot.waitUntil(lambda: any(session.run.snapshot().power_flow), timeout=10000)
    # a monitored snapshot is a frame at most 8 scans old (docs/engine.md)
    qtbot.waitUntil(lambda: session.run.snapshot().read(g30) == override_code(5),
                    timeout=10000)
    assert session.run.snapshot().monitored

    session.force(parse_address("X2.1"), 0)  # position 5 is 0b101: bit 0 held off
    qtbot.waitUntil(lambda: session.run.read(g30) == override_code(4), timeout=10000)
    session.release(parse_address("X2.1"))
    qtbot.waitUntil(lambda: session.run.read(g30) == override_code(5), timeout=10000)

    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: "taramalar kendi süreçlerinde" in control.figures.text(),
                        timeout=10000)
    finally:
        language.apply("en")

    control.control_actions["action_plc_stop"].trigger()
    assert not session.run.running and control.indicator.text() == "STOPPED"
    assert session.run.read(parse_address("Y0")) == 0
    assert all(isinstance(data, bytearray) for data in session.run.memory.areas.values())
    window.close()
    assert session.run._slot.process is None  # closing the window ends the scan process
