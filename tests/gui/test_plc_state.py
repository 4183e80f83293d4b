"""STOP / RUN, the program in the PLC and forcing are always in sight (issue 30, item 4): in
the status bar and on the main toolbar beside START / STOP, in both languages."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtWidgets import QLabel, QStatusBar, QToolBar
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_state import FORCED_STYLE, RUN_STYLE, STOP_STYLE

PROGRAM = "%@3\nRD X0.0\nWRT Y0.0\n%\n"


def _labels(window: MainWindow) -> list[QLabel]:
    status = window.findChild(QLabel, "status_plc_state")
    tool = window.findChild(QLabel, "toolbar_plc_state")
    assert status is not None and tool is not None
    assert isinstance(status.parent(), QStatusBar)
    toolbar = window.findChild(QToolBar, "toolbar_main")
    assert tool.parent() is toolbar
    return [status, tool]


def _f9(qtbot: QtBot, window: MainWindow) -> None:
    with qtbot.waitSignal(window.plc_docks.session.program_loaded, timeout=20_000):
        window.actions_by_name["action_compile"].trigger()


def test_the_state_is_shown_in_the_status_bar_and_beside_start(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    labels = _labels(window)
    toolbar = window.findChild(QToolBar, "toolbar_main")
    names = [a.objectName() for a in toolbar.actions()]
    start = names.index("action_plc_start")
    assert names[start + 1] == "action_plc_stop"
    assert toolbar.widgetForAction(toolbar.actions()[start + 2]) is labels[1]  # beside STOP
    for label in labels:
        assert label.isVisible()  # with the default docks: no dock needed
        assert label.text() == "STOP · no program loaded"
    path = tmp_path / "lamp.LAD"
    path.write_text(PROGRAM, encoding="utf-8")
    assert window.load(path)
    _f9(qtbot, window)
    session = window.plc_docks.session
    qtbot.waitUntil(lambda: labels[0].text() == "STOP · lamp.LAD")
    assert labels[0].styleSheet() == STOP_STYLE
    window.actions_by_name["action_plc_start"].trigger()
    qtbot.waitUntil(lambda: all(lb.text() == "RUN · lamp.LAD" for lb in labels))
    assert labels[1].styleSheet() == RUN_STYLE
    session.force(parse_address("X0.0"), 1)
    qtbot.waitUntil(lambda: all(lb.text() == "RUN · lamp.LAD · 1 forced" for lb in labels))
    assert all(lb.styleSheet() == FORCED_STYLE for lb in labels)  # the warning colour
    assert "forced" in labels[0].toolTip()
    session.release(parse_address("X0.0"))
    window.actions_by_name["action_plc_stop"].trigger()
    qtbot.waitUntil(lambda: all(lb.text() == "STOP · lamp.LAD" for lb in labels))
    assert labels[0].styleSheet() == STOP_STYLE


def test_the_state_follows_a_live_language_switch(qtbot: QtBot, window: MainWindow,
                                                  tmp_path: Path) -> None:
    labels = _labels(window)
    path = tmp_path / "lamp.LAD"
    path.write_text(PROGRAM, encoding="utf-8")
    assert window.load(path)
    _f9(qtbot, window)
    window.actions_by_name["action_plc_start"].trigger()
    window.plc_docks.session.force(parse_address("X0.0"), 1)
    window.set_language("tr")
    qtbot.waitUntil(lambda: all(lb.text() == "ÇALIŞIYOR · lamp.LAD · 1 zorlanmış"
                                for lb in labels))
    window.actions_by_name["action_plc_stop"].trigger()
    qtbot.waitUntil(lambda: labels[0].text() == "DURDU · lamp.LAD · 1 zorlanmış")
    window.plc_docks.session.release(parse_address("X0.0"))
    window.set_language("en")
    qtbot.waitUntil(lambda: labels[1].text() == "STOP · lamp.LAD")


def test_take_the_consoles_program_says_what_it_is_for(window: MainWindow) -> None:
    action = window.plc_docks.control.control_actions["action_plc_take_console"]
    assert action.text() == "Show the console's program as text"
    assert "F9" in action.toolTip()
