"""The family's own words (issue 38, item 8): a Delta or Fatek program's docks and dialogs
show its devices, ranges and name, never FANUC examples."""

from __future__ import annotations

from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.ladder.model import FunctionBox
from ladderworks.gui.main_window import MainWindow


def _box_cell(window: MainWindow, name: str) -> tuple[int, int, int, FunctionBox]:
    return next((index, *cell, element) for index, network in enumerate(window.model.networks)
                for cell, element in network.cells.items()
                if isinstance(element, FunctionBox) and element.name == name)


def test_a_delta_program_shows_its_own_examples_ranges_and_name(
        qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    docks = window.plc_docks
    window.actions_by_name["action_dock_time_chart"].trigger()
    chart = docks.time_chart.signals_edit.placeholderText()
    assert "R1.4" not in chart and "T0" in chart
    assert "Delta DVP" in docks.modbus.map_file.placeholderText()
    assert "seed" not in docks.modbus.served_map_text()
    assert "AlarmMsg.dat" not in docks.alarms.file_label.text()
    assert "Delta DVP" in docks.alarms.file_label.text()
    index, row, col, _box = _box_cell(window, "DVP.TMR")
    window.editor.edits.open_function_dialog(index, row, col, "DVP.TMR", _box)
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    assert dialog.table.item(0, 2).text() == "T0–T255"  # was "a device of this PLC"
    dialog.reject()
    english = docks.alarms.file_label.text()
    window.set_language("tr")
    assert docks.alarms.file_label.text() == (
        "Delta DVP programının alarm mesajları yoktur (alarm dosyası PMC programları içindir)")
    assert english != docks.alarms.file_label.text()
    window.set_language("en")
    assert window.load(paths.EXAMPLES / "spindle_override.LAD")  # a PMC program: FANUC's
    assert "R1.4" in docks.time_chart.signals_edit.placeholderText()


def test_a_fatek_timer_out_of_range_says_the_range(qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "fatek" / "conveyor.lst")
    index, row, col, box = _box_cell(window, "FBS.TMR")
    window.editor.edits.open_function_dialog(index, row, col, "FBS.TMR", box)
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    assert dialog.table.item(0, 2).text() == "T0–T255"
    dialog.set_value("timer", "T300")
    dialog.accept()
    assert dialog.warning.isVisibleTo(dialog)
    assert "T0-T255" in dialog.warning.text() and "use T" not in dialog.warning.text()
    dialog.reject()
