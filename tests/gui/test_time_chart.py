"""The PLC time chart dock: engine-sampled step traces, timer-relay edges, CSV/PNG, no loss."""

from __future__ import annotations

import csv
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_session

R1_4 = parse_address("R1.4")
PRESET_MS = 1000
EFFECTIVE_MS = 960  # timer 1 ticks every 48 ms: 1000 ms rounds down to 20 ticks


@pytest.fixture
def relay(qtbot: QtBot) -> Iterator[tuple[PlcSession, TimeChartDock]]:
    """The timer-relay example on the virtual clock, timer 1 preset 1000 ms, and a time chart."""
    UiLanguage().apply("en")
    session = running_session("timer_relay.LAD")
    session.set_timer_preset(1, PRESET_MS)
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    dock.show()
    yield session, dock
    session.stop()


def switch_on_after(session: PlcSession, scans: int) -> int:
    """Run `scans` scans, then turn R1.4 on; returns the time of the first scan that sees it."""
    session.run_scans(scans)
    assert session.run.engine is not None
    at = session.run.engine.now_ms
    session.set_bit(R1_4, 1)
    return at


def test_timer_relay_edges_one_preset_apart(
        qtbot: QtBot, relay: tuple[PlcSession, TimeChartDock], tmp_path: Path) -> None:
    session, dock = relay
    dock.signals_edit.setText("R1.4, R1.7")
    dock.period_spin.setValue(8)
    assert dock.start()
    on_at = switch_on_after(session, 10)
    session.run_scans(150)
    qtbot.waitUntil(lambda: len(dock.record) == 160)
    dock.stop()
    assert dock.record.rising_edges(0) == [on_at]
    assert dock.record.rising_edges(1) == [on_at + EFFECTIVE_MS]
    # drawn as steps: the R1.7 lane goes up exactly at its edge, no point in between
    xs, ys = dock.lane_points(1)
    base = dock.lane_base(1)
    assert xs[:2] == [0.0, float(on_at + EFFECTIVE_MS)]
    assert ys == [base, base + 1]
    assert dock._curves[1].opts["stepMode"] == "center"
    # the cursor reads every lane
    dock.set_cursor(on_at + EFFECTIVE_MS - 1)
    assert dock.cursor_values() == {"R1.4": 1, "R1.7": 0}
    dock.set_cursor(on_at + EFFECTIVE_MS)
    assert dock.cursor_values() == {"R1.4": 1, "R1.7": 1}
    assert f"Cursor {on_at + EFFECTIVE_MS} ms" in dock.cursor_label.text()
    dock.set_cursor(on_at - 1)
    assert dock.cursor_values() == {"R1.4": 0, "R1.7": 0}
    # the CSV has the same edges at the same times
    path = tmp_path / "trace.csv"
    assert dock.export_csv(path)
    rows = list(csv.reader(path.read_text().splitlines()))
    assert rows[0] == ["time_ms", "R1.4", "R1.7"]
    table = [[int(cell) for cell in row] for row in rows[1:]]
    assert len(table) == 160
    first_on = {name: next(row[0] for row in table if row[index])
                for index, name in ((1, "R1.4"), (2, "R1.7"))}
    assert first_on == {"R1.4": on_at, "R1.7": on_at + EFFECTIVE_MS}
    assert [row[0] for row in table] == [8 * i for i in range(160)]


def test_period_longer_than_the_scan(qtbot: QtBot,
                                     relay: tuple[PlcSession, TimeChartDock]) -> None:
    session, dock = relay
    dock.signals_edit.setText("R1.4 R1.7")
    dock.period_spin.setValue(48)
    assert dock.start()
    on_at = switch_on_after(session, 12)  # 96 ms: a sampling time
    session.run_scans(200)
    dock.stop()
    times = list(dock.record.times)
    assert times == list(range(0, times[-1] + 1, 48))
    assert dock.record.rising_edges(0) == [on_at]
    assert dock.record.rising_edges(1) == [on_at + EFFECTIVE_MS]


def test_no_sample_is_lost(relay: tuple[PlcSession, TimeChartDock]) -> None:
    session, dock = relay
    dock.signals_edit.setText("R1.4 R1.7 R9091.5")
    dock.period_spin.setValue(8)
    assert dock.start()
    session.run_scans(4000)  # one big batch between two publishes
    for _ in range(60):
        session.run_scans(100)  # and many small ones
    dock.stop()
    record = dock.record
    assert len(record) == 10_000
    assert list(record.seqs) == list(range(10_000))
    assert list(record.times) == [8 * i for i in range(10_000)]
    assert session.run.trace is not None and session.run.trace.dropped == 0
    # the 200 ms clock relay R9091.5 toggles every 104/96 ms: 100 rising edges in 80 s
    assert len(record.rising_edges(2)) == 80_000 // 200 - 1


def test_changing_the_preset_in_the_session_changes_the_delay(
        relay: tuple[PlcSession, TimeChartDock]) -> None:
    session, dock = relay
    session.set_timer_preset(1, 500)  # 480 ms effective
    dock.signals_edit.setText("R1.4 R1.7")
    assert dock.start()
    on_at = switch_on_after(session, 5)
    session.run_scans(100)
    dock.stop()
    assert dock.record.rising_edges(1) == [on_at + 480]


def test_values_clear_zoom_and_png(qtbot: QtBot, relay: tuple[PlcSession, TimeChartDock],
                                   tmp_path: Path) -> None:
    session, dock = relay
    dock.signals_edit.setText("R1.4 D10:2")
    assert dock.start()
    for value in (0, 300, 7):
        session.write(Address(Area.D, 10), value, 2)
        session.run_scans(5)
    assert dock.record.edges(1) == [(0, 0), (40, 300), (80, 7)]
    assert dock.lane_name(dock.record.signals[1]) == "D10:2"
    dock.set_cursor(45)
    assert dock.cursor_values()["D10:2"] == 300
    dock.fit()
    low, high = dock.time_range()
    assert low <= 0 and high >= 112
    dock.set_time_range(0, 100)
    dock.zoom(0.5)
    low, high = dock.time_range()
    assert (low, high) == pytest.approx((25, 75))
    png = tmp_path / "chart.png"
    assert dock.export_png(png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    dock.clear()
    assert len(dock.record) == 0
    session.run_scans(3)
    assert len(dock.record) == 3  # sampling goes on after CLEAR
    dock.stop()
    session.run_scans(3)
    assert len(dock.record) == 3


def test_errors_are_translated_messages(relay: tuple[PlcSession, TimeChartDock]) -> None:
    _session, dock = relay
    dock.signals_edit.setText("")
    assert not dock.start()
    assert "Type the bits" in dock.message.text()
    dock.signals_edit.setText("R1.4 Q7.1")
    assert not dock.start()
    assert "unknown area" in dock.message.text()
    dock.signals_edit.setText("R1.4:2")
    assert not dock.start()
    assert "takes no width" in dock.message.text()
    dock.signals_edit.setText("D10:3")
    assert not dock.start()
    assert "must be 1, 2 or 4" in dock.message.text()
    assert not dock.sampling


def test_named_signals_label_their_lanes(qtbot: QtBot) -> None:
    session = running_session("spindle_override.LAD")
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    dock.signals_edit.setText("G30.0 X2.1")
    assert dock.start()
    assert [dock.lane_name(s) for s in dock.record.signals] == ["G30.0 SOV0", "X2.1 FP_Din_1"]
    ticks = dock.plot.getPlotItem().getAxis("left")._tickLevels[0]
    assert [label for _y, label in ticks] == ["G30.0 SOV0", "X2.1 FP_Din_1"]
    session.stop()


def test_real_time_samples_arrive_in_order(qtbot: QtBot) -> None:
    from ladderworks.core.il import parse_file
    from ladderworks.paths import EXAMPLES

    session = PlcSession(realtime=True)
    session.load_program(parse_file(EXAMPLES / "timer_relay.LAD").program)
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    dock.signals_edit.setText("R9091.5")
    assert session.start()
    try:
        assert dock.start()
        qtbot.waitUntil(lambda: len(dock.record) >= 60, timeout=10_000)
        dock.stop()
    finally:
        session.stop()
    count = len(dock.record)
    assert list(dock.record.seqs) == list(range(count))
    times = list(dock.record.times)
    assert times == list(range(times[0], times[0] + 8 * count, 8))  # virtual ms, every scan


def test_a_value_lane_writes_its_values_like_a_bus(
        qtbot: QtBot, relay: tuple[PlcSession, TimeChartDock]) -> None:
    session, dock = relay
    dock.resize(900, 400)
    dock.signals_edit.setText("R1.4 D10:2")
    assert dock.start()
    d10 = parse_address("D10")
    for value in (0, 148, 4660):
        session.write(d10, value, 2)
        session.run_scans(40)
    qtbot.waitUntil(lambda: len(dock.record) == 120)
    dock.stop()
    dock.fit()
    qtbot.waitUntil(lambda: len(dock.lane_texts(1)) == 3)
    texts = dock.lane_texts(1)
    assert [text for _time, text in texts] == ["0 (0000h)", "148 (0094h)", "4660 (1234h)"]
    assert [time for time, _text in texts] == [0.0, 320.0, 640.0]
    assert dock.lane_texts(0) == []  # a bit lane is a step trace, no text
    # zoomed out until a segment is narrower than its text, the value is not written over
    dock.set_time_range(-100_000, 100_000)
    qtbot.waitUntil(lambda: dock.lane_texts(1) == [])


def test_every_chart_button_is_in_view_in_a_narrow_dock(
        qtbot: QtBot, relay: tuple[PlcSession, TimeChartDock]) -> None:
    _session, dock = relay
    UiLanguage().apply("tr")  # the longer words
    try:
        narrowest = dock.minimumSizeHint().width()  # what a dock at 1024 px gets
        assert narrowest <= 400
        dock.resize(narrowest, 420)
        qtbot.waitUntil(lambda: dock.width() == narrowest)
        for name in ("action_time_chart_csv", "action_time_chart_png",
                     "action_time_chart_ladder3"):
            button = dock.toolbar.buttons[name]
            assert button.isVisible(), name
        assert dock.toolbar.hidden_buttons() == []
        # the buttons wrap below each other instead of hiding
        buttons = dock.toolbar.buttons
        assert buttons["action_time_chart_png"].y() > buttons["action_time_chart_start"].y()
    finally:
        UiLanguage().apply("en")


def test_the_time_axis_label_stays_above_the_cursor_readout(
        qtbot: QtBot, relay: tuple[PlcSession, TimeChartDock]) -> None:
    session, dock = relay
    dock.signals_edit.setText("R1.4 R1.7 D10:2 D12:4 R2.0 R2.1 R2.2 R2.3")
    assert dock.start()
    session.run_scans(20)
    qtbot.waitUntil(lambda: len(dock.record) == 20)
    dock.stop()
    readout = dock.cursor_label
    line = readout.fontMetrics().height()
    dock.resize(380, 600)
    # eight lanes' values wrap onto a second line, and the readout asks for its height
    qtbot.waitUntil(lambda: readout.minimumHeight() >= 2 * line)
    dock.resize(380, 200)  # smaller than the chart needs: the dock keeps its minimum
    qtbot.waitUntil(lambda: dock.height() >= dock.minimumSizeHint().height())
    qtbot.waitUntil(lambda: readout.height() >= 2 * line)
    axis = dock.plot.getPlotItem().getAxis("bottom")
    label = axis.label.mapRectToScene(axis.label.boundingRect())
    label_bottom = dock.plot.mapTo(dock.widget(), dock.plot.mapFromScene(label.bottomLeft()))
    assert dock.plot.geometry().bottom() < readout.geometry().top()
    assert label_bottom.y() <= readout.geometry().top()
    assert readout.geometry().bottom() <= dock.widget().height()


def _left_axis_texts(dock: TimeChartDock) -> list[str]:
    """The texts the chart's left axis draws (its tick labels)."""
    from PySide6.QtGui import QImage, QPainter

    axis = dock.plot.getPlotItem().getAxis("left")
    image = QImage(200, 200, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    try:
        specs = axis.generateDrawSpecs(painter)
    finally:
        painter.end()
    return [] if specs is None else [text for _rect, _flags, text in specs[2]]


def test_an_empty_chart_has_no_numbered_lanes(qtbot: QtBot) -> None:
    """Before any signal is sampled the left axis names no lane: no meaningless 0 … 1.0
    written with a decimal point on a Turkish screen."""
    language = UiLanguage()
    language.apply("tr")
    try:
        session = running_session("spindle_override.LAD")
        dock = TimeChartDock(session)
        qtbot.addWidget(dock)
        dock.resize(420, 300)
        dock.show()
        qtbot.waitExposed(dock)
        qtbot.wait(50)
        assert _left_axis_texts(dock) == []
        dock.signals_edit.setText("G30.0 X2.1")
        assert dock.start()
        names = ["G30.0 SOV0", "X2.1 FP_Din_1"]
        qtbot.waitUntil(lambda: _left_axis_texts(dock) == names)  # once the axis is laid out
        session.stop()
    finally:
        language.apply("en")
