"""Time travel: the time chart's cursor shows an earlier scan in the PLC diagnostic."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.docks.time_travel import TimeTravel
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks, set_switch

LATCH = "%@3\nRD X2.1\nOR Y0.0\nAND.NOT X2.2\nWRT Y0.0\n%\n"


def test_cursor_back_shows_the_earlier_state_then_live_and_why(qtbot: QtBot,
                                                               window: MainWindow) -> None:
    docks = plc_docks(window)
    session, dock = docks.session, docks.diagnostic
    assert session.load_program(parse(LATCH).program).ok
    session.start()
    dock.show()
    travel = time_travel(window)
    travel.action.trigger()
    assert travel.history is not None and dock.why_button.isVisible()
    chart = docks.others["time_chart"]
    assert isinstance(chart, TimeChartDock)
    chart.signals_edit.setText("X2.1 Y0.0")
    assert chart.start()
    session.step(40)
    session.set_bit(parse_address("X2.1"), 1)
    session.step(16)  # the push button is pressed for two scans: 40 and 48 ms
    session.set_bit(parse_address("X2.1"), 0)
    session.step(40)
    qtbot.waitUntil(lambda: len(chart.record) == 12)
    assert engine_ops(session)[0] == "RD X2.1"
    contact = dock.view.live.cell_of(0)  # RD X2.1
    assert contact is not None
    network, cell = contact
    overlay = dock.view.live.overlays[network]
    dock._repaint()
    assert cell not in overlay.power.closed  # X2.1 is released now (Y0.0 holds itself)
    chart.set_cursor(44)  # back to the scan at 40 ms
    assert dock.past is not None and dock.past.scan_count == 5
    assert "PAST" in dock.state.text() and dock.live_button.isVisible()
    assert cell in overlay.power.closed  # the contact as it was then
    session.step(8)  # live scans do not move the past view
    assert cell in overlay.power.closed
    dock.live_button.click()
    assert dock.past is None and not dock.live_button.isVisible()
    assert cell not in overlay.power.closed
    dock.search.setText("Y0.0")
    dock.why_button.click()
    assert dock.past is not None and dock.past.scan_count == 5
    assert "Y0.0 went to 1 in scan 5 at 40 ms" in dock.message.text()
    assert (network, cell) in dock.hits and cell in overlay.marked
    assert round(chart.time_cursor.value()) == 40
    slider = travel.slider
    assert slider.isVisible() and (slider.minimum(), slider.maximum()) == (0, 12)
    dock.back_to_live()
    qtbot.keyClick(slider, Qt.Key.Key_Home)  # the slider: to the first scan kept
    assert dock.past is not None and dock.past.scan_count == 0
    travel.action.trigger()
    assert not slider.isVisible()
    assert travel.history is None and dock.past is None and session.run.engine is not None
    assert session.run.engine.history is None


def engine_ops(session: object) -> list[str]:
    engine = session.run.engine  # type: ignore[attr-defined]
    return [f"{op.name} {op.operand}" for op in engine.program.ops]


def test_online_drawing_shows_the_past_too(qtbot: QtBot, window: MainWindow) -> None:
    from tests.gui.test_online import online_window

    docks = online_window(window)
    session, online = docks.session, docks.online
    time_travel(window).enable(True)
    set_switch(session, 0)
    session.step(16)  # scans at 0 and 8 ms: position 0, R102.0 on
    set_switch(session, 1)
    session.step(8)
    assert time_travel(window).show_time(8)
    assert online.past is not None and online.past.now_ms == 8
    assert window.editor.networks[0].coil_column is not None
    assert online.live.overlays[0].power.coils == {(0, window.editor.networks[0].coil_column)}
    docks.diagnostic.show_past(docks.diagnostic.session.run.snapshot())
    docks.diagnostic.back_to_live()
    assert online.past is None and online.live.overlays[0].power.coils == set()


def time_travel(window: MainWindow) -> TimeTravel:
    travel = plc_docks(window).time_travel
    assert isinstance(travel, TimeTravel)
    return travel
