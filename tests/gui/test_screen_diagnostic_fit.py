"""Issue 31 item 9: the PLC diagnostic opens with the network's coils in the dock's width."""

from __future__ import annotations

from PySide6.QtCore import QPointF
from pytestqt.qtbot import QtBot

from ladderworks.gui.editor.geometry import network_width
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.gui.test_small_screen import on_the_panel


def rail_in_view(window: MainWindow) -> bool:
    """The right rail of the first network is inside the diagnostic's viewport."""
    view = window.plc_docks.diagnostic.view
    x = view.mapFromScene(QPointF(network_width(view.networks[0]) - 8, 0)).x()
    return 0 < x <= view.viewport().width()


def test_the_diagnostic_opens_with_the_coils_in_view(window: MainWindow, qtbot: QtBot) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    on_the_panel(window, qtbot)
    window.actions_by_name["action_compile"].trigger()
    diagnostic = window.plc_docks.diagnostic
    assert diagnostic.view.networks  # the program is in the PLC
    assert diagnostic.view.zoom() == 0.62  # the default zoom: a 1,000-px network is 620 px
    window.actions_by_name["action_dock_plc_diagnostic"].trigger()
    qtbot.waitUntil(diagnostic.isVisible)
    assert diagnostic.view.viewport().width() < 600
    qtbot.waitUntil(lambda: rail_in_view(window))
    assert diagnostic.view.zoom() < 0.62
    assert diagnostic.zoom_label.text() == f"{round(diagnostic.view.zoom() * 100)} %"
    diagnostic.view.zoom_by(-1)  # the user's zoom below the fit stays when it opens again
    zoom = diagnostic.view.zoom()
    diagnostic.hide()
    window.actions_by_name["action_dock_plc_diagnostic"].trigger()
    qtbot.waitUntil(diagnostic.isVisible)
    qtbot.wait(20)
    assert diagnostic.view.zoom() == zoom


def test_on_a_large_screen_it_opens_a_third_of_the_window_wide(window: MainWindow,
                                                                qtbot: QtBot) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    window.resize(1920, 1000)
    window.actions_by_name["action_compile"].trigger()
    diagnostic = window.plc_docks.diagnostic
    window.actions_by_name["action_dock_plc_diagnostic"].trigger()
    qtbot.waitUntil(diagnostic.isVisible)
    qtbot.wait(20)
    assert diagnostic.width() >= 1920 // 3 - 2
    qtbot.waitUntil(lambda: rail_in_view(window))
    assert diagnostic.view.zoom() >= 0.55  # readable: hardly below the default
