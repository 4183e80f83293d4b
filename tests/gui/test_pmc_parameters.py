"""PMC parameters through the window: set in the PLC tables, saved beside the program, reopened."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtWidgets import QMessageBox
from pytestqt.qtbot import QtBot

from ladderworks.gui import file_dialogs
from ladderworks.gui.docks.table_entries import TableKind
from ladderworks.gui.docks.tables import PlcTablesDock
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import CHECKOUT
from tests.gui.test_new_program import file_new
from tests.gui.test_plc_tables import type_into_cell

PROGRAM = "%@3\nRD R1.4\nTMR 1\nWRT R1.7\n%\n"


def open_with_dialog(window: MainWindow, monkeypatch: pytest.MonkeyPatch, path: Path) -> None:
    """File > Open, choosing `path` in the file dialog."""
    monkeypatch.setattr(file_dialogs, "open_file_name",
                        lambda *_args, **_kwargs: str(path))
    window.actions_by_name["action_open"].trigger()


def compile_into_plc(qtbot: QtBot, window: MainWindow) -> None:
    """PLC control: take the console's program, compile; wait until the PLC has it."""
    control = window.plc_docks.control
    control.control_actions["action_plc_take_console"].trigger()
    with qtbot.waitSignal(window.plc_docks.session.program_loaded, timeout=10_000):
        control.control_actions["action_plc_control_compile"].trigger()


def tables_of(window: MainWindow) -> PlcTablesDock:
    """View > PLC tables."""
    window.actions_by_name["action_dock_plc_tables"].trigger()
    dock = window.plc_docks.others["tables"]
    assert isinstance(dock, PlcTablesDock) and dock.isVisible()
    return dock


def run_cli(*argv: str) -> str:
    """`ladderworks-cli ARGS` in a fresh process."""
    done = subprocess.run([sys.executable, "-m", "ladderworks.cli", *argv], cwd=CHECKOUT,
                          capture_output=True, text=True, timeout=120, check=True)
    return done.stdout


def test_timer_preset_is_saved_reopened_and_used_by_the_cli(
        qtbot: QtBot, window: MainWindow, monkeypatch: pytest.MonkeyPatch,
        tmp_path: Path) -> None:
    program = tmp_path / "TIMER.LAD"
    program.write_text(PROGRAM, encoding="utf-8")
    open_with_dialog(window, monkeypatch, program)
    assert not window.is_modified()
    compile_into_plc(qtbot, window)
    dock = tables_of(window)
    assert dock.cell_texts(TableKind.TIMER) == [["1", "TMR", "0", "48", "0"]]
    type_into_cell(qtbot, dock, TableKind.TIMER, 0, 2, "500")
    qtbot.waitUntil(window.is_modified)
    assert window.windowTitle().startswith("TIMER.LAD*")
    window.actions_by_name["action_save"].trigger()
    assert not window.is_modified()
    assert program.read_text(encoding="utf-8") == PROGRAM  # the ladder file is untouched
    saved = (tmp_path / "TIMER.LAD.prm").read_text(encoding="utf-8")
    assert "T0:4 = 500" in saved and "TMR 1 preset (ms)" in saved
    # a change not saved: opening asks first; Discard drops it
    type_into_cell(qtbot, dock, TableKind.TIMER, 0, 2, "700")
    qtbot.waitUntil(window.is_modified)
    asked: list[str] = []

    def discard(*args: object, **_kwargs: object) -> QMessageBox.StandardButton:
        asked.append(str(args[2]))
        return QMessageBox.StandardButton.Discard

    monkeypatch.setattr(QMessageBox, "question", discard)
    open_with_dialog(window, monkeypatch, program)
    assert asked == ["The program has unsaved changes. Save them?"]
    assert not window.is_modified()
    qtbot.waitUntil(lambda: dock.cell_texts(TableKind.TIMER)[0][2] == "500")
    assert window.plc_docks.session.run.timer_preset(1) == 500
    # the command line reads TIMER.LAD.prm beside the program: 500 ms -> 480 ms (48 ms ticks)
    out = run_cli("run", str(program), "--ms", "600", "--set", "R1.4=1",
                  "--trace", "R1.7", "--period", "48")
    rows = [line.split(",") for line in out.splitlines()[1:]]
    assert next(int(time) for time, value in rows if value == "1") == 480


def test_new_program_has_default_parameters(
        qtbot: QtBot, window: MainWindow, monkeypatch: pytest.MonkeyPatch,
        tmp_path: Path) -> None:
    program = tmp_path / "K.LAD"
    program.write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "K.LAD.prm").write_text("K5 = 0b00000011\nnonsense\n", encoding="utf-8")
    open_with_dialog(window, monkeypatch, program)
    session = window.plc_docks.session
    assert session.run.parameters.get(session.run.parameters.values()[0].address) == 3
    assert "1 lines not understood" in window.last_warning and "line 2" in window.last_warning
    assert not window.is_modified()
    dock = tables_of(window)
    assert ["K5", "00000011", "03h"] in dock.cell_texts(TableKind.KEEP)
    file_new(qtbot, window, None)
    assert not session.run.parameters and not window.is_modified()
    assert dock.cell_texts(TableKind.KEEP) == []
