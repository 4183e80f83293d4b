"""Issues 25/26: the PLC tables (PMC parameters) are hidden for a Delta or Fatek program, with a
translated note saying where its presets and devices are; a PMC program gets them back."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.gui.main_window import MainWindow


def _compile(qtbot: QtBot, window: MainWindow) -> None:
    window.plc_docks.session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert window.plc_docks.session.run.engine is not None


def test_tables_hidden_with_a_note_for_dialects(qtbot: QtBot, window: MainWindow) -> None:
    tables = window.plc_docks.tables
    tables.show()
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    _compile(qtbot, window)
    assert not tables.tabs.isVisibleTo(tables) and tables.dialect_note.isVisibleTo(tables)
    assert tables.dialect_note.text().startswith("A Delta DVP program has no PMC parameter")
    window.set_language("tr")
    assert tables.dialect_note.text().startswith("Delta DVP programının PMC parametre")
    window.set_language("en")
    assert window.load(paths.EXAMPLES / "fatek" / "conveyor.lst")
    _compile(qtbot, window)
    assert tables.dialect_note.text().startswith("A Fatek FBs program")
    assert window.load(paths.EXAMPLES / "mcode_decoder.LAD")
    _compile(qtbot, window)
    assert tables.tabs.isVisibleTo(tables) and not tables.dialect_note.isVisibleTo(tables)
    assert tables.tabs.count() == 4
