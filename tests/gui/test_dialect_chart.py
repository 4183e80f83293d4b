"""Issues 25/26: the time chart and the bit display name a Delta or Fatek program's addresses
in its own spelling (`X0`, `D0`), not the PMC's (`X0.0`), and give them no FANUC signal names."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.gui.main_window import MainWindow


def _running(qtbot: QtBot, window: MainWindow, example: Path) -> None:
    assert window.load(example)
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()


def test_delta_lanes_readout_and_csv_in_delta_spelling(qtbot: QtBot, window: MainWindow,
                                                      tmp_path: Path) -> None:
    _running(qtbot, window, paths.EXAMPLES / "delta" / "timer_t0.txt")
    session = window.plc_docks.session
    chart = window.plc_docks.time_chart
    chart.signals_edit.setText("X0 Y0 T0")
    assert chart.start()
    session.set_bit(parse_target("X0", "delta")[0], 1)
    session.run_scans(5)
    chart.stop()
    assert [chart.lane_name(s) for s in chart.record.signals] == ["X0", "Y0", "T0"]  # no HW_ESTP
    assert list(chart.cursor_values()) == ["X0", "Y0", "T0"]
    chart.set_cursor(chart.record.times[-1])
    readout = chart.cursor_label.text()
    assert readout.count("X0 = 1") == 1 and "X0.0" not in readout
    csv = tmp_path / "trace.csv"
    assert chart.export_csv(csv)
    assert csv.read_text(encoding="utf-8").splitlines()[0] == "time_ms,X0,Y0,T0"


def test_a_saved_delta_trace_imports_back(qtbot: QtBot, window: MainWindow,
                                          tmp_path: Path) -> None:
    from ladderworks.gui.docks.trace_files import import_trace

    _running(qtbot, window, paths.EXAMPLES / "delta" / "timer_t0.txt")
    chart = window.plc_docks.time_chart
    csv = tmp_path / "trace.csv"
    csv.write_text("time_ms,X0,D0\n0,0,5\n8,1,6\n", encoding="utf-8")
    assert import_trace(chart, csv)
    assert [s.label for s in chart.record.signals] == ["X0", "D0"]
    assert chart.record.signals[1].width == 2  # Delta's D0 is a word


def test_fatek_lanes_and_bit_tooltips_in_fatek_spelling(qtbot: QtBot, window: MainWindow) -> None:
    _running(qtbot, window, paths.EXAMPLES / "fatek" / "conveyor.lst")
    chart = window.plc_docks.time_chart
    chart.signals_edit.setText("X0 Y10 M1000 D0")
    assert chart.start()
    window.plc_docks.session.run_scans(3)
    chart.stop()
    assert [chart.lane_name(s) for s in chart.record.signals] == ["X0", "Y10", "M1000", "D0"]
    bits = window.plc_docks.bit_display
    bits.set_address(0, "X0")
    tip = next(button for button in bits.rows[0].bits if button.bit == 0).toolTip()
    assert tip.splitlines()[0] == "X0" and "HW_ESTP" not in tip


def test_pmc_lanes_keep_pmc_spelling_and_signal_names(qtbot: QtBot,
                                                    window: MainWindow) -> None:
    _running(qtbot, window, paths.EXAMPLES / "mcode_decoder.LAD")
    chart = window.plc_docks.time_chart
    chart.signals_edit.setText("X0.0 D10:2")
    assert chart.start()
    assert [s.label for s in chart.record.signals] == ["X0.0", "D10:2"]
    assert chart.lane_name(chart.record.signals[0]) == "X0.0 HW_ESTP"


def test_status_bar_names_the_cell_in_delta_spelling(window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    contact = window.editor.describe_cell(0, 0, 0)
    assert contact.split("  |  ")[1:] == ["X0"]  # not X0.0 HW_ESTP
    box = next(cell for cell, element in window.model.networks[0].cells.items()
               if type(element).__name__ == "FunctionBox")
    assert window.editor.describe_cell(0, *box).endswith("TMR T0 K10")
