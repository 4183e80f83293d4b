"""View › Fit width keeps the coil column and right rail in view; the zoom is remembered."""

from __future__ import annotations

from PySide6.QtCore import QPointF, Qt
from PySide6.QtWidgets import QDockWidget
from pytestqt.qtbot import QtBot

from ladderworks.gui.editor.geometry import CELL_W, LEFT
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES


def _rail_x(window: MainWindow) -> int:
    """The viewport x of the right rail of the widest network."""
    view = window.editor
    widest = max(net.columns for net in view.networks)
    return view.mapFromScene(QPointF(LEFT + (widest + 1) * CELL_W, 0)).x()


def test_fit_width_keeps_the_rail_in_view_with_a_dock_open(window: MainWindow,
                                                           qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    window.resize(1600, 900)  # issue 18: with a PLC dock, the rail was out of view at 1600 px
    diagnostic = window.findChild(QDockWidget, "plcDiagnosticDock")
    assert diagnostic is not None
    diagnostic.show()
    window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, diagnostic)
    qtbot.waitUntil(lambda: diagnostic.isVisible() and diagnostic.width() > 50)
    window.resizeDocks([diagnostic], [560], Qt.Orientation.Horizontal)  # a wide PLC dock
    qtbot.waitUntil(lambda: diagnostic.width() >= 500)
    view = window.editor
    view.zoom_reset()
    assert _rail_x(window) > view.viewport().width()  # at 100 % the rail is out of view
    window.actions_by_name["action_zoom_fit_width"].trigger()
    assert window.actions_by_name["action_zoom_fit_width"].isChecked()
    assert 0 < _rail_x(window) <= view.viewport().width()
    assert _rail_x(window) > view.viewport().width() * 0.85  # fits, not just smaller
    narrower = view.width()
    window.resizeDocks([diagnostic], [diagnostic.width() + 150], Qt.Orientation.Horizontal)
    qtbot.waitUntil(lambda: view.width() < narrower - 50)
    assert 0 < _rail_x(window) <= view.viewport().width()  # fitted again
    window.actions_by_name["action_zoom_in"].trigger()  # a zoom step turns fit width off
    assert not window.actions_by_name["action_zoom_fit_width"].isChecked()


def test_zoom_is_remembered_across_sessions(window: MainWindow, settings: Settings,
                                            qtbot: QtBot) -> None:
    window.actions_by_name["action_zoom_in"].trigger()
    window.actions_by_name["action_zoom_in"].trigger()
    zoom = window.editor.zoom()
    assert zoom > 1.3
    window.close()
    language = UiLanguage()
    again = MainWindow(settings, language)
    qtbot.addWidget(again)
    assert abs(again.editor.zoom() - zoom) < 1e-6
    assert not again.actions_by_name["action_zoom_fit_width"].isChecked()
    again.actions_by_name["action_zoom_fit_width"].trigger()
    again.close()
    third = MainWindow(settings, language)
    qtbot.addWidget(third)
    assert third.actions_by_name["action_zoom_fit_width"].isChecked()
    assert third.fit_width.enabled
