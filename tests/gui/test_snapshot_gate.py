"""Docks and the real-time scan thread (issue 30): a hidden dock reads no snapshot, a shown one
keeps within the GUI thread's share while the thread scans, and none holds the engine lock."""

from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.plc.session import PlcRun
from ladderworks.gui.docks import snapshot_gate
from ladderworks.gui.docks.bit_display import BitDisplayDock
from ladderworks.gui.docks.snapshot_gate import UpdateBudget
from ladderworks.gui.docks.table_entries import TableKind
from ladderworks.gui.docks.tables import PlcTablesDock
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_text

PROGRAM = "%@3\nRD X2.1\nWRT R1.0\nRD K5.0\nWRT R4.0\nRD R9091.1\nMOVB X40 D10\n%\n"


class Clocks:
    """A wall clock and a GUI-thread CPU clock the test moves by hand."""

    def __init__(self) -> None:
        self.wall = 0.0
        self.busy = 0.0

    def budget(self) -> UpdateBudget:
        return UpdateBudget(0.25, clock=lambda: self.wall, cpu=lambda: self.busy)


@pytest.fixture
def session() -> Iterator[PlcSession]:
    UiLanguage().apply("en")
    plc = running_text(PROGRAM)
    yield plc
    plc.stop()


def counted(dock: PlcTablesDock) -> dict[TableKind, int]:
    """How often each table model re-reads the memory from now on."""
    calls = dict.fromkeys(dock.models, 0)
    for kind, model in dock.models.items():
        update = model.update

        def wrapped(areas: object = None, kind: TableKind = kind, update: object = update
                    ) -> None:
            calls[kind] += 1
            update(areas)  # type: ignore[operator]

        model.update = wrapped  # type: ignore[method-assign]
    return calls


def test_the_budget_is_the_gui_threads_share_since_the_last_update() -> None:
    clocks = Clocks()
    budget = clocks.budget()
    assert budget.wait() == 0  # the first update runs at once

    def update() -> None:
        clocks.busy += 0.010  # the update itself

    budget.run(update)
    clocks.wall, clocks.busy = 0.050, clocks.busy + 0.020  # repaints and other docks
    assert budget.wait() == pytest.approx(0.030 / 0.25 - 0.050)
    clocks.wall = 0.120
    assert budget.wait() == 0


def test_a_hidden_tables_dock_reads_no_snapshot_and_catches_up_when_shown(
        qtbot: QtBot, session: PlcSession) -> None:
    dock = PlcTablesDock(session)
    qtbot.addWidget(dock)
    calls = counted(dock)
    session.write(parse_address("X40"), 7)
    for _ in range(5):  # five snapshots published
        session.run_scans(1)
    assert calls == dict.fromkeys(dock.models, 0)
    dock.tabs.setCurrentWidget(dock.tables[TableKind.DATA])
    dock.show()
    qtbot.waitExposed(dock)
    assert calls[TableKind.DATA] == 1 and calls[TableKind.KEEP] == 0
    assert dock.cell_texts(TableKind.DATA)[0][:3] == ["D10", "1", "7"]
    session.run_scans(1)  # shown: only the table on top follows the PLC
    assert calls[TableKind.DATA] == 2 and calls[TableKind.TIMER] == 0
    assert dock.cell_texts(TableKind.KEEP) == [["K5", "00000000", "00h"]]  # caught up
    assert calls[TableKind.KEEP] == 1


def test_before_the_gate_every_dock_read_every_snapshot(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    """The old behaviour stays reachable for benchmarks/realtime_docks.py."""
    monkeypatch.setattr(snapshot_gate, "UPDATE_ALWAYS", True)
    dock = PlcTablesDock(session)
    qtbot.addWidget(dock)
    calls = counted(dock)
    for _ in range(3):
        session.run_scans(1)
    assert calls == dict.fromkeys(dock.models, 3)


def test_while_the_thread_scans_a_dock_over_its_share_waits_then_shows_the_newest_state(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    dock = BitDisplayDock(session)
    qtbot.addWidget(dock)
    dock.show()
    qtbot.waitExposed(dock)
    dock.set_address(0, "X40")
    dock.start()
    clocks = Clocks()
    dock.gate.budget = clocks.budget()
    monkeypatch.setattr(PlcRun, "threaded", property(lambda _self: True))
    shown: list[int] = []
    update = dock.gate.update

    def recorded(snapshot: PlcSnapshot) -> None:
        shown.append(snapshot.scan_count)
        update(snapshot)

    dock.gate.update = recorded
    session.write(parse_address("X40"), 1)
    session.run_scans(1)
    assert dock.rows[0].value == 1 and len(shown) == 1
    clocks.busy += 0.050  # the GUI thread was busy: 50 ms of CPU in 10 ms
    clocks.wall += 0.010
    session.write(parse_address("X40"), 2)
    session.run_scans(1)
    assert dock.rows[0].value == 1 and len(shown) == 1 and dock.gate.pending  # held back
    session.write(parse_address("X40"), 3)  # the memory moves on
    clocks.wall += 0.5
    dock.gate.flush()  # what its timer does
    assert dock.rows[0].value == 3  # the newest state, not the snapshot held back
    assert not dock.gate.pending and len(shown) == 2


def test_docks_update_without_the_engine_lock(qtbot: QtBot, session: PlcSession) -> None:
    """A dock's update never keeps the scan thread from its lock: the snapshot is a copy."""
    dock = BitDisplayDock(session)
    qtbot.addWidget(dock)
    dock.show()
    dock.set_address(0, "X40")
    dock.start()
    engine = session.run.engine
    assert engine is not None
    free: list[bool] = []
    update = dock.gate.update

    def probed(snapshot: PlcSnapshot) -> None:
        def take() -> None:
            got = engine.lock.acquire(timeout=1)
            free.append(got)
            if got:
                engine.lock.release()

        other = threading.Thread(target=take)  # as the scan thread would
        other.start()
        other.join()
        update(snapshot)

    dock.gate.update = probed
    session.run_scans(1)
    session.run_scans(1)
    assert free == [True, True]


def test_the_chart_lets_a_due_scan_in_between_its_lanes_only_while_the_thread_scans(
        qtbot: QtBot, session: PlcSession, monkeypatch: pytest.MonkeyPatch) -> None:
    from ladderworks.gui.docks.time_chart import TimeChartDock

    chart = TimeChartDock(session)
    qtbot.addWidget(chart)
    chart.show()
    chart.signals_edit.setText("X2.1 R1.0 R9091.1")
    assert chart.start()
    session.run_scans(2)
    sleeps: list[float] = []
    monkeypatch.setattr(snapshot_gate.time, "sleep", sleeps.append)
    chart.gate.flush()
    session.run_scans(1)
    assert sleeps == []  # the virtual clock: nothing to let in
    monkeypatch.setattr(PlcRun, "threaded", property(lambda _self: True))
    chart.gate.update(session.run.snapshot())
    assert len(sleeps) == 3 and all(0 < s < 0.001 for s in sleeps)  # one per bit lane
    chart.stop()
