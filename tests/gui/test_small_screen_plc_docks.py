"""The PLC docks on a 1024×600 panel (issue 31 item 1): the error list joins the bottom PLC
docks' tab group and the tool palette narrows to its names only on a small screen, and the
time chart's signals keep the row's width."""

from __future__ import annotations

from PySide6.QtCore import QSize
from pytestqt.qtbot import QtBot

from ladderworks.gui.docks.time_chart import SHORT_PLOT
from ladderworks.gui.main_window import MainWindow
from tests.gui.test_small_screen import PANEL, on_the_panel


def open_chart(window: MainWindow, qtbot: QtBot) -> None:
    window.errors.show()
    window.actions_by_name["action_dock_time_chart"].trigger()
    qtbot.waitUntil(window.plc_docks.time_chart.isVisible)


def test_on_a_large_screen_the_error_list_stays_beside_the_chart(window: MainWindow,
                                                                 qtbot: QtBot) -> None:
    window.resize(QSize(1536, 832))
    qtbot.waitUntil(lambda: window.height() == 832)
    open_chart(window, qtbot)
    chart = window.plc_docks.time_chart
    assert window.errors not in window.tabifiedDockWidgets(chart)
    assert window.errors.isVisible() and not window.errors.visibleRegion().isEmpty()


def test_on_the_panel_the_error_list_is_a_tab_one_click_away(window: MainWindow,
                                                             qtbot: QtBot) -> None:
    on_the_panel(window, qtbot)
    open_chart(window, qtbot)
    chart = window.plc_docks.time_chart
    assert window.errors in window.tabifiedDockWidgets(chart)
    assert window.size() == PANEL
    window.errors.raise_()
    qtbot.waitUntil(lambda: not window.errors.visibleRegion().isEmpty())


def test_the_turkish_sampling_time_leaves_the_signals_the_row(window: MainWindow,
                                                             qtbot: QtBot) -> None:
    """'ÖRNEKLEME ZAMANI:' beside the field left it a few characters at 1024 px: it sits before
    START, in the row of buttons that wraps."""
    window.set_language("tr")
    on_the_panel(window, qtbot)
    open_chart(window, qtbot)
    chart = window.plc_docks.time_chart
    qtbot.waitUntil(lambda: chart.width() > 600)
    edit = chart.signals_edit
    assert edit.width() >= chart.width() - chart.signals_label.width() - 40
    assert chart.period_spin.parent().parent() is chart.toolbar
    assert not chart.toolbar.hidden_buttons()
    window.set_language("en")


def test_a_short_chart_gives_its_lanes_the_axis_titles_line(window: MainWindow,
                                                            qtbot: QtBot) -> None:
    on_the_panel(window, qtbot)
    open_chart(window, qtbot)
    chart = window.plc_docks.time_chart
    axis = chart.plot.getPlotItem().getAxis("bottom")
    qtbot.waitUntil(lambda: chart.plot.height() < SHORT_PLOT)
    assert not axis.label.isVisible()
    # a language switch sets the title again: still hidden
    window.set_language("tr")
    assert not axis.label.isVisible()
    window.set_language("en")
    chart.plot.setMinimumHeight(SHORT_PLOT)  # a taller chart names its axis
    qtbot.waitUntil(lambda: chart.plot.height() >= SHORT_PLOT)
    qtbot.waitUntil(axis.label.isVisible)


def test_on_the_panel_a_right_hand_plc_dock_narrows_the_tools_to_their_names(
        window: MainWindow, qtbot: QtBot) -> None:
    window.set_language("tr")  # the longer tool names
    on_the_panel(window, qtbot)
    palette = window.tool_palette
    before = palette.width()
    window.actions_by_name["action_dock_plc_control"].trigger()
    qtbot.waitUntil(window.plc_docks.control.isVisible)
    qtbot.waitUntil(lambda: palette.width() < before)
    for button in palette.buttons:  # every tool's name still whole
        assert button.width() >= button.sizeHint().width(), button.text()
    assert window.size() == PANEL
    assert window.editor.viewport().width() >= 300
    window.set_language("en")


def test_on_a_large_screen_the_tools_keep_their_width(window: MainWindow,
                                                      qtbot: QtBot) -> None:
    window.resize(QSize(1536, 832))
    qtbot.waitUntil(lambda: window.height() == 832)
    palette = window.tool_palette
    before = palette.width()
    window.actions_by_name["action_dock_plc_control"].trigger()
    qtbot.waitUntil(window.plc_docks.control.isVisible)
    qtbot.wait(50)
    assert palette.width() == before
