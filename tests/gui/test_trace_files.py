"""The time chart exports and imports LADDER-III signal-trace results beside its CSV."""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.gui.docks import trace_files
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_session


def test_export_ladder3_then_import_it_back(qtbot: QtBot, tmp_path: Path) -> None:
    UiLanguage().apply("en")
    session = running_session("timer_relay.LAD")
    session.set_timer_preset(1, 96)
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    dock.signals_edit.setText("R1.4 R1.7")
    dock.period_spin.setValue(8)
    assert dock.start()
    session.run_scans(2)
    session.set_bit(parse_address("R1.4"), 1)
    session.run_scans(20)
    qtbot.waitUntil(lambda: len(dock.record) == 22)
    dock.stop()
    path = tmp_path / "trace.csv"
    assert trace_files.export_ladder3(dock, path)
    lines = path.read_text().splitlines()
    assert lines[0] == "Data, R1.4, R1.7"
    assert lines[1] == "-21, 0, 0" and lines[-1] == "0, 1, 1"
    edges = dock.record.rising_edges(1)
    dock.clear()
    assert len(dock.record) == 0
    assert trace_files.import_trace(dock, path)
    assert len(dock.record) == 22
    assert dock.record.rising_edges(1) == edges
    assert dock.signals_edit.text() == "R1.4 R1.7"
    assert dock.chart_actions[trace_files.IMPORT].text() == "Import..."
    session.stop()


def test_import_refuses_a_file_that_is_no_trace(qtbot: QtBot, tmp_path: Path) -> None:
    UiLanguage().apply("en")
    session = running_session("timer_relay.LAD")
    dock = TimeChartDock(session)
    qtbot.addWidget(dock)
    path = tmp_path / "x.csv"
    path.write_text("Data, X0.0\n0, zz\n")
    assert not trace_files.import_trace(dock, path)
    assert "line 2" in dock.message.text()
    session.stop()
