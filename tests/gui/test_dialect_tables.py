"""Issues 25/26: a Delta or Fatek program's PLC tables are its device tables (timers, counters,
registers), not the PMC parameter tables; a dialect without device tables gets a translated
note instead; a PMC program gets its four tables back."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects.base import Dialect
from ladderworks.gui.main_window import MainWindow


def _compile(qtbot: QtBot, window: MainWindow) -> None:
    window.plc_docks.session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert window.plc_docks.session.run.engine is not None


def test_dialects_show_device_tables(qtbot: QtBot, window: MainWindow) -> None:
    tables = window.plc_docks.tables
    tables.show()
    for example in ("delta/timer_t0.txt", "fatek/conveyor.lst"):
        assert window.load(paths.EXAMPLES / example)
        _compile(qtbot, window)
        assert not tables.tabs.isVisibleTo(tables) and tables.device_tabs.isVisibleTo(tables)
        assert not tables.dialect_note.isVisibleTo(tables)
        assert tables.device_tabs.count() == 3
    assert window.load(paths.EXAMPLES / "mcode_decoder.LAD")
    _compile(qtbot, window)
    assert tables.tabs.isVisibleTo(tables) and not tables.device_tabs.isVisibleTo(tables)
    assert not tables.dialect_note.isVisibleTo(tables)
    assert tables.tabs.count() == 4


def test_a_dialect_without_device_tables_gets_a_note(qtbot: QtBot, window: MainWindow,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(Dialect, "device_tables", lambda _self: None)
    tables = window.plc_docks.tables
    tables.show()
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    _compile(qtbot, window)
    assert not tables.tabs.isVisibleTo(tables) and not tables.device_tabs.isVisibleTo(tables)
    assert tables.dialect_note.isVisibleTo(tables)
    assert tables.dialect_note.text().startswith("A Delta DVP program has no PMC parameter")
    window.set_language("tr")
    assert tables.dialect_note.text().startswith("Delta DVP programının PMC parametre")
