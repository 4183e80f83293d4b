"""The console on a 1024×600 shop-floor panel: it fits with the default docks and the chart."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import QEvent, QPoint, QRect, QSize, Qt
from PySide6.QtGui import QFont
from PySide6.QtWidgets import QApplication, QTabBar, QWidget
from pytestqt.qtbot import QtBot

from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.paths import EXAMPLES

PANEL = QSize(1024, 600)


def minimum(window: MainWindow) -> QSize:
    """The smallest size the window's layout allows, once the pending layouts are done."""
    for _level in range(4):  # a label's change goes up through the dock to the window
        QApplication.sendPostedEvents(None, QEvent.Type.LayoutRequest)
    return window.minimumSizeHint().expandedTo(window.minimumSize())


def inside(window: MainWindow, widget: QWidget) -> bool:
    """True when `widget` is shown and wholly inside the window."""
    top_left = widget.mapTo(window, QPoint(0, 0))
    return widget.isVisible() and window.rect().contains(QRect(top_left, widget.size()))


def on_the_panel(window: MainWindow, qtbot: QtBot) -> None:
    window.resize(PANEL)
    qtbot.waitUntil(lambda: window.size() == PANEL)


@pytest.fixture(params=[None, 11.0], ids=["default font", "11 pt font"])
def font_size(request: pytest.FixtureRequest) -> Iterator[float | None]:
    """The application font as the offscreen platform gives it, or a desktop's 11 pt."""
    saved = QApplication.font()
    if request.param is not None:
        font = QFont(saved)
        font.setPointSizeF(request.param)
        QApplication.setFont(font)
    yield request.param
    QApplication.setFont(saved)


@pytest.mark.parametrize("language", ["en", "tr"])
def test_the_default_docks_fit_1024_by_600(window: MainWindow, qtbot: QtBot, language: str,
                                           font_size: float | None) -> None:
    window.set_language(language)
    assert minimum(window).boundedTo(PANEL) == minimum(window), minimum(window)
    on_the_panel(window, qtbot)
    for widget in (window.statusBar(), window.errors, window.plc_docks.alarms,
                   window.tool_palette, window.menus.toolbar, window.editor):
        assert inside(window, widget), widget.objectName()
    assert window.editor.viewport().height() >= 200  # the ladder keeps most of the room
    window.set_language("en")


@pytest.mark.parametrize("language", ["en", "tr"])
def test_the_time_chart_opens_as_a_tab_and_still_fits(window: MainWindow, qtbot: QtBot,
                                                      language: str,
                                                      font_size: float | None) -> None:
    window.set_language(language)
    on_the_panel(window, qtbot)
    chart = window.plc_docks.time_chart
    window.actions_by_name["action_dock_time_chart"].trigger()
    qtbot.waitUntil(chart.isVisible)
    assert window.plc_docks.alarms in window.tabifiedDockWidgets(chart)  # behind it, a tab
    # the error list too (issue 31): beside the chart it took half the bottom row
    assert window.errors in window.tabifiedDockWidgets(chart)
    assert minimum(window).boundedTo(PANEL) == minimum(window), minimum(window)
    assert window.size() == PANEL
    for widget in (window.statusBar(), chart.plot, chart.signals_edit, window.editor):
        assert inside(window, widget), widget.objectName()
    assert not chart.toolbar.hidden_buttons()
    # a third at most, unless its smallest size is more (an 11 pt font)
    qtbot.waitUntil(lambda: chart.height() <= max(PANEL.height() // 3,
                                                  chart.minimumSizeHint().height()))
    assert window.editor.viewport().height() >= 200, window.editor.viewport().size()
    window.set_language("en")


def test_the_plc_control_screen_fits_and_leaves_the_ladder_room(window: MainWindow,
                                                                  qtbot: QtBot) -> None:
    window.set_language("tr")  # the longer scan figures
    assert window.load(EXAMPLES / "spindle_override.LAD")
    on_the_panel(window, qtbot)
    control = window.plc_docks.control
    window.actions_by_name["action_dock_plc_control"].trigger()
    qtbot.waitUntil(control.isVisible)
    window.actions_by_name["action_compile"].trigger()
    qtbot.waitUntil(lambda: control.figures.text() != "")  # the scan figures wrap
    # the docks' minimum widths leave the ladder 250 px of the panel
    assert minimum(window).width() <= PANEL.width() - 250, minimum(window)
    assert minimum(window).height() <= PANEL.height(), minimum(window)
    assert inside(window, control) and inside(window, window.statusBar())
    assert window.editor.viewport().width() >= 250
    window.set_language("en")


def test_a_new_window_shown_at_1024_by_600_keeps_that_size(qtbot: QtBot,
                                                           settings: Settings) -> None:
    """The hidden PLC docks wait in their tab groups without widening the first layout."""
    from ladderworks.gui.translation import UiLanguage

    language = UiLanguage()
    language.apply("en")
    fresh = MainWindow(settings, language)
    qtbot.addWidget(fresh)
    fresh.resize(PANEL)
    fresh.show()
    qtbot.waitExposed(fresh)
    assert fresh.size() == PANEL
    # the bottom docks stay low: the ladder keeps more than half the panel's height
    qtbot.wait(100)
    assert fresh.editor.height() > PANEL.height() * 6 // 10  # 344 px with 170-px docks


@pytest.mark.parametrize("language", ["en", "tr"])
def test_every_plc_dock_opened_at_once_still_fits(window: MainWindow, qtbot: QtBot,
                                                  language: str,
                                                  font_size: float | None) -> None:
    """A technician opens every PLC screen from the View menu on the panel: the two tab
    groups hold them, the window stays 1024×600 and the status bar stays in view."""
    window.set_language(language)
    assert window.load(EXAMPLES / "spindle_override.LAD")
    on_the_panel(window, qtbot)
    docks = window.plc_docks
    for name, dock in (("action_dock_plc_control", docks.control),
                       ("action_dock_plc_diagnostic", docks.diagnostic),
                       ("action_dock_bit_display", docks.bit_display),
                       ("action_dock_plc_tables", docks.tables),
                       ("action_dock_time_chart", docks.time_chart),
                       ("action_dock_scenario", docks.scenario),
                       ("action_dock_force_list", docks.force_list),
                       ("action_dock_cross_reference", window.cross_reference)):
        window.actions_by_name[name].trigger()
        qtbot.waitUntil(dock.isVisible)
        assert minimum(window).boundedTo(PANEL) == minimum(window), (name, minimum(window))
    docks.control.raise_()  # in front of its tab group, the chart in front of the other
    docks.time_chart.raise_()
    window.actions_by_name["action_compile"].trigger()
    qtbot.waitUntil(lambda: docks.control.figures.text() != "")
    assert minimum(window).boundedTo(PANEL) == minimum(window), minimum(window)
    assert window.size() == PANEL
    for widget in (window.statusBar(), docks.control.toolbar,
                   docks.time_chart.plot, window.editor):
        assert inside(window, widget), widget.objectName()
    window.set_language("en")


def test_tabbed_docks_show_their_whole_titles(window: MainWindow, qtbot: QtBot) -> None:
    """Four PLC screens in the bottom group on the panel, in Turkish: each tab reads its whole
    title (the tabs scroll) rather than 'ALAR...' and 'PLC ZAMAN ...'."""
    window.set_language("tr")
    on_the_panel(window, qtbot)
    docks = window.plc_docks
    for name, dock in (("action_dock_plc_tables", docks.tables),
                       ("action_dock_time_chart", docks.time_chart),
                       ("action_dock_scenario", docks.scenario),
                       ("action_dock_force_list", docks.force_list)):
        window.actions_by_name[name].trigger()
        qtbot.waitUntil(dock.isVisible)
    # the error list joined the group on the panel (issue 31); beside it again, as a user
    # drags it, it leaves the group narrow
    window.removeDockWidget(window.errors)
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, window.errors,
                         Qt.Orientation.Horizontal)
    window.errors.show()
    docks.time_chart.raise_()
    qtbot.waitUntil(lambda: docks.time_chart.width() < PANEL.width())
    window.resizeDocks([docks.time_chart, window.errors], [300, PANEL.width() - 300],
                       Qt.Orientation.Horizontal)  # its narrowest
    qtbot.waitUntil(lambda: docks.time_chart.width() < 480)
    titles = {dock.windowTitle() for dock in (docks.alarms, docks.time_chart, docks.scenario,
                                              docks.force_list)}
    bars = [bar for bar in window.findChildren(QTabBar)
            if bar.isVisible() and titles <= {bar.tabText(i) for i in range(bar.count())}]
    assert len(bars) == 1
    bar = bars[0]
    for index in range(bar.count()):
        text = bar.tabText(index)
        # the style pads a whole title by some 20 px; a squeezed tab has 2 px and cuts it
        assert bar.tabRect(index).width() >= bar.fontMetrics().horizontalAdvance(text) + 16, text
    window.set_language("en")


def test_a_long_status_ends_in_an_ellipsis_with_the_whole_text_as_tooltip(
        window: MainWindow, qtbot: QtBot, tmp_path) -> None:
    """A long symbol comment and element comment under the cursor on the panel: the status
    bar says it was cut ('…'), the tooltip has it whole, the window does not widen."""
    window.set_language("tr")
    on_the_panel(window, qtbot)
    path = tmp_path / "long.LAD"
    comment = "ACİL STOP BUTONU BASILI DEĞİL VE KAPI KİLİTLİ İSE MAKİNE HAREKETİNE İZİN " * 2
    path.write_text(f"%@2-C\nX0.0   UZUN_SEMBOL  {comment}\n%\n%@3\nN00001:\n"
                    "RD X0.0  // bu kontağın kendi yorumu\nWRT Y0.0\n%\n", "utf-8")
    assert window.load(path)
    window.editor.move_cursor(0, 0, 0)
    label = window.cell_label
    qtbot.waitUntil(lambda: label.toolTip() == label.text() and "kendi yorumu" in label.text())
    assert minimum(window).boundedTo(PANEL) == minimum(window)
    assert window.size() == PANEL and inside(window, label)
    assert label.shown_text().endswith("…")
    assert label.fontMetrics().horizontalAdvance(label.shown_text()) <= label.width()
    window.set_language("en")


def test_a_long_status_leaves_room_for_the_compile_message(window: MainWindow,
                                                           qtbot: QtBot, tmp_path) -> None:
    """The cell text takes at most 60 % of the status bar: F9's result stays readable on the
    left even with a long comment under the cursor."""
    window.set_language("tr")
    on_the_panel(window, qtbot)
    path = tmp_path / "long.LAD"
    comment = "ACİL STOP BUTONU BASILI DEĞİL VE KAPI KİLİTLİ İSE HAREKETE İZİN VERİLİR " * 3
    path.write_text(f"%@2-C\nX0.0   UZUN_SEMBOL  {comment}\n%\n%@3\nN00001:\n"
                    "RD X0.0\nWRT Y0.0\n%\n", "utf-8")
    assert window.load(path)
    window.editor.move_cursor(0, 0, 0)
    window.actions_by_name["action_compile"].trigger()
    bar = window.statusBar()
    message = bar.currentMessage()
    assert message.startswith("Derleme bitti")
    label = window.cell_label
    qtbot.waitUntil(lambda: label.geometry().left() > 0)
    room = label.geometry().left()
    assert room >= bar.width() * 0.35
    assert room >= bar.fontMetrics().horizontalAdvance(message)
    window.set_language("en")
