"""Docks paced around the real-time scan thread (issue 30 item 6): an update waits for the gap
after a scan, the time chart redraws at most a few times a second and sets the span it follows
itself (one repaint, not a second one when the view's auto-range moves it)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.plc.session import PlcRun
from ladderworks.gui.docks import snapshot_gate
from ladderworks.gui.docks.bit_display import BitDisplayDock
from ladderworks.gui.docks.snapshot_gate import UpdateBudget
from ladderworks.gui.docks.time_chart import REDRAW_INTERVAL, TimeChartDock
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_text

PROGRAM = "%@3\nRD X2.1\nWRT R1.0\nRD K5.0\nWRT R4.0\nRD R9091.1\nMOVB X40 D10\n%\n"


@pytest.fixture
def session() -> Iterator[PlcSession]:
    UiLanguage().apply("en")
    plc = running_text(PROGRAM)
    yield plc
    plc.stop()


def threaded(monkeypatch: pytest.MonkeyPatch, due: list[float]) -> None:
    """The session as while its thread scans, the next scan due in `due[0]` seconds."""
    monkeypatch.setattr(PlcRun, "threaded", property(lambda _self: True))
    monkeypatch.setattr(PlcRun, "due_in", lambda _self: due[0])


def test_a_least_interval_between_updates_only_when_paced(
        monkeypatch: pytest.MonkeyPatch) -> None:
    wall = [0.0]
    budget = UpdateBudget(0.25, clock=lambda: wall[0], cpu=lambda: 0.0, interval=0.25)
    budget.run(lambda: None)
    wall[0] = 0.1
    assert budget.wait() == pytest.approx(0.15)
    monkeypatch.setattr(snapshot_gate, "PACED", False)
    assert budget.wait() == 0


def bit_display(qtbot: QtBot, session: PlcSession) -> BitDisplayDock:
    dock = BitDisplayDock(session)
    qtbot.addWidget(dock)
    dock.show()
    qtbot.waitExposed(dock)
    dock.set_address(0, "X40")
    dock.start()
    return dock


def test_an_update_waits_for_the_gap_after_a_scan(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = bit_display(qtbot, session)
    due = [0.001]  # the next scan is due in 1 ms: an update now would keep it waiting
    threaded(monkeypatch, due)
    before = dock.gate.updates
    session.write(parse_address("X40"), 5)
    dock.gate.offer(session.run.snapshot())
    assert dock.gate.updates == before and dock.gate.pending and dock.gate.deferred == 1
    due[0] = 0.006  # the scan is done: 6 ms before the next one
    dock.gate.flush()  # what its timer does
    assert dock.gate.updates == before + 1 and dock.rows[0].value == 5


def test_an_update_waits_for_the_gap_only_so_often(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = bit_display(qtbot, session)
    threaded(monkeypatch, [0.0])  # scans that never leave a gap (each one late)
    before = dock.gate.updates
    dock.gate.offer(session.run.snapshot())
    for _ in range(snapshot_gate.TRIES - 1):
        dock.gate.flush()
    assert dock.gate.updates == before
    dock.gate.flush()
    assert dock.gate.updates == before + 1 and dock.gate.deferred == snapshot_gate.TRIES


def test_without_pacing_an_update_does_not_wait_for_the_gap(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = bit_display(qtbot, session)
    threaded(monkeypatch, [0.001])
    monkeypatch.setattr(snapshot_gate, "PACED", False)
    before = dock.gate.updates
    dock.gate.offer(session.run.snapshot())
    assert dock.gate.updates == before + 1 and dock.gate.deferred == 0


def chart(qtbot: QtBot, session: PlcSession) -> TimeChartDock:
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    dock.show()
    qtbot.waitExposed(dock)
    dock.signals_edit.setText("X2.1 R1.0 R9091.1")
    assert dock.start()
    return dock


def test_the_time_chart_redraws_at_most_a_few_times_a_second(
        qtbot: QtBot, session: PlcSession) -> None:
    dock = chart(qtbot, session)
    assert dock.gate.budget.interval == REDRAW_INTERVAL <= 0.5
    assert 1 / REDRAW_INTERVAL >= 2  # still follows a running machine


def test_the_following_chart_sets_its_span_when_it_redraws(
        qtbot: QtBot, session: PlcSession) -> None:
    dock = chart(qtbot, session)
    session.run_scans(30)
    follows = dock.follows
    dock.gate.flush()
    dock._redraw()
    assert dock.follows > follows
    view = dock.plot.getPlotItem().getViewBox()
    low, high = dock.time_range()
    assert low <= dock.record.times[0] and high >= (dock.record.end_ms or 0)
    assert dock.following and not view.autoRangeEnabled()[0]  # follows by its span set
    dock.set_time_range(10, 20)  # the user zooms: the chart stops following
    follows = dock.follows
    session.run_scans(5)
    dock._redraw()
    assert dock.follows == follows and dock.time_range() == pytest.approx((10, 20))
    dock.fit()  # follows again
    session.run_scans(5)
    dock._redraw()
    assert dock.follows > follows and dock.time_range()[1] >= (dock.record.end_ms or 0)
    dock.stop()


def test_a_mouse_zoom_stops_the_following(qtbot: QtBot, session: PlcSession) -> None:
    dock = chart(qtbot, session)
    session.run_scans(30)
    dock._redraw()
    view = dock.plot.getPlotItem().getViewBox()
    view.sigRangeChangedManually.emit([True, False])  # as a wheel or drag in the chart does
    assert not dock.following
    low, high = dock.time_range()
    session.run_scans(20)
    dock._redraw()
    assert dock.time_range() == pytest.approx((low, high))
    dock.stop()


def test_the_following_chart_paints_without_the_views_auto_range(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = chart(qtbot, session)
    view = dock.plot.getPlotItem().getViewBox()
    calls: list[int] = []
    original = view.childrenBounds  # the auto-range's walk over every curve's data
    monkeypatch.setattr(view, "childrenBounds",
                        lambda *args, **kwargs: (calls.append(1), original(*args, **kwargs))[1])
    session.run_scans(30)  # the first span set turns the view's auto-range off (one walk)
    calls.clear()
    for _ in range(3):
        session.run_scans(10)
        dock._redraw()
        dock.plot.grab()  # a paint
    assert calls == [] and dock.following
    monkeypatch.setattr(snapshot_gate, "SPAN_SET", False)  # before: the view's auto-range
    dock.fit()
    session.run_scans(5)
    dock._redraw()
    dock.plot.grab()
    assert calls
    dock.stop()


def test_before_pacing_the_chart_left_its_span_to_the_view(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(snapshot_gate, "PACED", False)
    dock = chart(qtbot, session)
    session.run_scans(10)
    dock._redraw()
    assert dock.follows == 0
    dock.stop()


def test_the_charts_paint_lets_a_due_scan_go_first(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = chart(qtbot, session)
    session.run_scans(30)
    dock._redraw()
    due = [0.05]
    threaded(monkeypatch, due)
    sleeps: list[float] = []
    monkeypatch.setattr(snapshot_gate.time, "sleep", sleeps.append)
    dock.plot.grab()  # no scan due within the paint: it never pauses
    assert dock.gate.yields == 0 and sleeps == []
    due[0] = 0.0  # a scan running, or waiting for the interpreter
    dock.plot.grab()
    # each lane, its fill and both axes paused once: the scan goes first at each of them
    assert dock.gate.yields >= 2 * len(dock.record.signals) + 2
    assert sleeps and all(0 < pause < 0.002 for pause in sleeps)
    monkeypatch.setattr(snapshot_gate, "YIELD", False)  # before: the paint went straight on
    yields = dock.gate.yields
    dock.plot.grab()
    assert dock.gate.yields == yields
    dock.stop()
