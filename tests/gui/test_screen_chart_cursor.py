"""Issue 31 item 6: a click on the time chart moves its cursor there, the readout follows, and
before the time-travel history begins the readout and the diagnostic say so."""

from __future__ import annotations

from PySide6.QtCore import QPointF, Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks

LATCH = "%@3\nRD X2.1\nOR Y0.0\nAND.NOT X2.2\nWRT Y0.0\n%\n"


def click_at(qtbot: QtBot, chart: TimeChartDock, time_ms: float) -> None:
    """A left click in the chart's plot at `time_ms`, half-way up."""
    view = chart.plot.getPlotItem().getViewBox()
    low, high = view.viewRange()[1]
    scene = view.mapViewToScene(QPointF(time_ms, (low + high) / 2))
    point = chart.plot.mapFromScene(scene)
    qtbot.mouseClick(chart.plot.viewport(), Qt.MouseButton.LeftButton, pos=point)


def test_a_click_moves_the_cursor_and_before_the_history_it_says_so(qtbot: QtBot,
                                                                     window: MainWindow) -> None:
    docks = plc_docks(window)
    session, diagnostic = docks.session, docks.diagnostic
    assert session.load_program(parse(LATCH).program).ok
    window.resize(1200, 800)
    chart = docks.time_chart
    chart.show()
    diagnostic.show()
    chart.signals_edit.setText("X2.1 Y0.0")
    assert chart.start()
    session.start()
    session.step(40)  # scans at 0 … 32 ms: before the history is kept
    docks.time_travel.action.trigger()
    session.set_bit(parse_address("X2.1"), 1)
    session.step(40)
    session.set_bit(parse_address("X2.1"), 0)
    session.step(40)
    qtbot.waitUntil(lambda: len(chart.record) >= 15)
    chart.fit()
    qtbot.wait(50)
    click_at(qtbot, chart, 60)
    assert abs(chart.time_cursor.value() - 60) < 4, chart.time_cursor.value()
    at = round(chart.time_cursor.value())
    assert chart.cursor_label.text().startswith(f"Cursor {at} ms:")
    assert "Y0.0 = 1" in chart.cursor_label.text()
    assert diagnostic.past is not None and 40 <= diagnostic.past.now_ms <= 60
    click_at(qtbot, chart, 10)  # before the history: no scan, and the readout says so
    assert abs(chart.time_cursor.value() - 10) < 4
    assert "before the scan history, which begins at 40 ms" in chart.cursor_label.text()
    assert diagnostic.past is not None and diagnostic.past.now_ms >= 40  # not another scan
    assert diagnostic.message.text().startswith("The cursor is before the scan history")
    window.set_language("tr")
    assert "tarama geçmişinden önce" in chart.cursor_label.text()
    assert diagnostic.message.text().startswith("İmleç tarama geçmişinden önce")
    window.set_language("en")
    click_at(qtbot, chart, 100)
    assert diagnostic.message.text() == ""
    assert "before the scan history" not in chart.cursor_label.text()
