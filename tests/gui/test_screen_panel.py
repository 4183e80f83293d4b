"""The screen at 1024×600 (issue 38, item 11): fit width shows the coils beside the PLC docks,
a layout from a large screen leaves the ladder its room, whole tabs and placeholders, an
address error in view, and another program opened at its top."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QApplication, QDockWidget, QLabel, QTabBar
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from tests.gui.conftest import Drawer
from tests.gui.test_new_program import file_new
from tests.gui.test_screen_fit_width import rail_x
from tests.gui.test_small_screen import PANEL, on_the_panel

DELTA = paths.EXAMPLES / "delta" / "counter_reset.txt"


def test_fit_width_beside_the_plc_docks_shows_the_coils(window: MainWindow,
                                                         qtbot: QtBot) -> None:
    assert window.load(DELTA)
    on_the_panel(window, qtbot)
    for name, dock in (("action_dock_plc_control", window.plc_docks.control),
                       ("action_dock_time_chart", window.plc_docks.time_chart)):
        window.actions_by_name[name].trigger()
        qtbot.waitUntil(dock.isVisible)
    qtbot.wait(20)
    view = window.editor
    assert view.viewport().width() >= 440  # the control screen takes a third (was 312-490)
    window.actions_by_name["action_zoom_fit_width"].trigger()
    for network in range(len(view.networks) - 1):  # every rail, so every coil, in view
        assert 0 < rail_x(window, network) <= view.viewport().width()
    assert "0 of" not in window.zoom_label.toolTip()
    assert window.zoom_label.toolTip().startswith("Fit width: every network fits at ")
    file_new(qtbot, window, None)  # File › New, OK  # an empty program fits: no "0 of 1"
    assert "of 1 networks" not in window.zoom_label.toolTip()


def test_a_layout_saved_on_a_large_screen_leaves_the_ladder_its_room(
        qtbot: QtBot, settings: Settings) -> None:
    language = UiLanguage()
    language.apply("en")
    large = MainWindow(settings, language)
    qtbot.addWidget(large)
    large.resize(QSize(1920, 1080))
    large.show()
    qtbot.waitExposed(large)
    chart = large.plc_docks.time_chart
    large.actions_by_name["action_dock_time_chart"].trigger()
    qtbot.waitUntil(chart.isVisible)
    large.resizeDocks([chart], [640], Qt.Orientation.Vertical)  # a tall chart on a large screen
    qtbot.wait(20)
    large.close()  # the layout is saved
    small = MainWindow(settings, language)
    qtbot.addWidget(small)
    small.resize(PANEL)
    small.show()
    qtbot.waitExposed(small)
    # the chart's own least height (237 px) bounds the bottom row: 152 px of ladder before
    qtbot.waitUntil(lambda: small.editor.viewport().height() >= 220)
    assert small.plc_docks.time_chart.isVisible()  # the user's docks kept


def test_turkish_tabs_placeholders_and_an_error_at_the_coil_stay_whole(
        window: MainWindow, qtbot: QtBot, drawer: Drawer) -> None:
    window.set_language("tr")  # the longer "Ana takım çantası" and "Sinyaller"
    window.resize(QSize(1100, 640))
    palette = window.tool_palette
    window.resizeDocks([palette], [150], Qt.Orientation.Horizontal)  # as narrow as it goes
    qtbot.wait(20)
    on_the_panel(window, qtbot)  # maximised on the panel
    bars = [bar for bar in window.findChildren(QTabBar) if bar.parent() is window
            and bar.isVisible() and "Sinyaller" in [bar.tabText(k) for k in range(bar.count())]]
    assert bars
    qtbot.waitUntil(lambda: bars[0].sizeHint().width() <= bars[0].width())  # no arrows
    window.actions_by_name["action_dock_modbus"].trigger()
    modbus = window.plc_docks.modbus
    qtbot.waitUntil(modbus.isVisible)
    qtbot.wait(20)
    field = modbus.map_file
    placeholder = field.placeholderText()
    assert field.fontMetrics().horizontalAdvance(placeholder) < field.width() - 8, placeholder
    window.set_language("en")
    coil = window.editor.networks[0].coil_column
    drawer.element(0, 0, coil, "O", "QQ9")  # not an address: the reason under the edit
    message = window.editor.viewport().findChild(QLabel, "inline_message")
    assert message is not None and message.isVisible()
    assert message.geometry().right() <= window.editor.viewport().width()
    assert message.geometry().left() >= 0
    QApplication.sendPostedEvents()


def test_another_program_opens_at_its_top(window: MainWindow, qtbot: QtBot,
                                          tmp_path: Path) -> None:
    long = tmp_path / "long.LAD"
    long.write_text("%@3\n" + "".join(f"RD X{k}.0\nWRT Y{k}.0\n" for k in range(60)) + "%\n",
                    "utf-8")
    assert window.load(long)
    bar = window.editor.verticalScrollBar()
    qtbot.waitUntil(lambda: bar.maximum() > 0)
    bar.setValue(bar.maximum())
    assert window.load(DELTA)
    assert bar.value() == 0
    assert not [d for d in window.findChildren(QDockWidget) if d.isFloating()]
