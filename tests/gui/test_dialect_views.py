"""Delta and Fatek programs in the views a PMC program has: on-line mode, Find, the PDF."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects import parse_target
from ladderworks.gui import print_actions
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.print_pages import LadderPages
from ladderworks.paths import EXAMPLES

# (program, dialect, the input that starts it, the output it drives)
PROGRAMS = [
    (EXAMPLES / "delta" / "timer_t0.txt", "delta", "X0", "Y0"),  # T0 1.0 s, then Y0
    (EXAMPLES / "fatek" / "conveyor.lst", "fatek", "X0", "Y0"),
]
IDS = ["delta", "fatek"]


def _running(window: MainWindow, qtbot: QtBot, path: Path, dialect: str):
    """The program opened, compiled with F9 and started on the virtual clock."""
    assert window.load(path)
    assert window.model.dialect == dialect
    docks = window.plc_docks
    docks.session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert docks.session.run.engine is not None
    assert docks.session.start()
    return docks


@pytest.mark.parametrize(("path", "dialect", "start", "output"), PROGRAMS, ids=IDS)
def test_online_mode_shows_power_on_a_dialect_drawing(
        qtbot: QtBot, window: MainWindow, path: Path, dialect: str, start: str,
        output: str) -> None:
    docks = _running(window, qtbot, path, dialect)
    docks.online.actions["action_plc_online"].trigger()
    assert docks.online.online
    session = docks.session
    session.set_bit(parse_target(start, dialect)[0], 1)
    session.step(1200)
    assert session.run.bit(parse_target(output, dialect)[0]) == 1
    overlays = docks.online.live.overlays
    powered = [overlays[index].power.coils for index in range(len(overlays))]
    assert any(powered), "no coil shown powered"


@pytest.mark.parametrize(("path", "dialect", "start", "output"), PROGRAMS, ids=IDS)
def test_find_takes_the_dialects_spelling(
        qtbot: QtBot, window: MainWindow, path: Path, dialect: str, start: str,
        output: str) -> None:
    assert window.load(path)
    window.editor.move_cursor(0, 0, 0)
    window.activateWindow()
    window.editor.setFocus()
    qtbot.waitUntil(window.editor.hasFocus)
    qtbot.keyClick(window.editor, "f", Qt.KeyboardModifier.ControlModifier)
    dialog = window.find_dialog
    assert dialog is not None
    dialog.find_text.setText(output)
    assert dialog.find_next() is not None
    index, row, col = window.editor.cursor_cell
    found = window.editor.networks[index].element_at(row, col)
    assert found is not None
    assert getattr(found[1], "address", None) == parse_target(output, dialect)[0]
    assert dialog.message.text().endswith(output)  # "1 of 2: network 1, Y0", not Y0.0


@pytest.mark.parametrize(("path", "dialect", "start", "output"), PROGRAMS, ids=IDS)
def test_the_pdf_and_its_cross_reference_use_the_dialects_spelling(
        window: MainWindow, tmp_path: Path, path: Path, dialect: str, start: str,
        output: str) -> None:
    assert window.load(path)
    pdf = tmp_path / "program.pdf"
    count = print_actions.export_pdf(window, pdf)
    assert count >= 1 and pdf.read_bytes().startswith(b"%PDF")
    printer = print_actions.new_printer()
    rect = printer.pageLayout().paintRectPixels(print_actions.PRINT_DPI)
    plan = LadderPages(print_actions.print_job(window), rect.width(), rect.height())
    assert plan.job.dialect == dialect
    rows = {row.address: row for row in plan.rows}
    address = parse_target(output, dialect)[0]
    assert address in rows and rows[address].written  # the coil's network is listed
    assert all(row.symbol == "" for row in plan.rows)  # no FANUC signal names on its devices
