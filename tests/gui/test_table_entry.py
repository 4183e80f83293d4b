"""The PLC tables (issue 38, item 9): a value refused is said where it was typed (the editor
opens again with it, the reason under the cell); any device is added, K/H typed."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractItemView, QApplication, QLabel, QLineEdit
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.gui.docks.table_entries import TableKind
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import type_text

REGISTERS, TIMERS = TableKind.REGISTERS, TableKind.DEVICE_TIMERS


def _editor(qtbot: QtBot) -> QLineEdit:
    qtbot.waitUntil(lambda: isinstance(QApplication.focusWidget(), QLineEdit))
    editor = QApplication.focusWidget()
    assert isinstance(editor, QLineEdit)
    return editor


def _type(qtbot: QtBot, editor: QLineEdit, text: str) -> None:
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)


def test_a_refused_value_is_said_at_its_cell_and_any_device_is_added(
        qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "cmp_d10.txt")
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.start()
    tables = window.plc_docks.tables
    window.actions_by_name["action_dock_plc_tables"].trigger()
    table = tables.tables[REGISTERS]
    tables.device_tabs.setCurrentWidget(table)
    qtbot.waitUntil(table.isVisible)
    rect = table.visualRect(table.model().index(0, 1))  # D10's value
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    _type(qtbot, _editor(qtbot), "99999")
    error = table.viewport().findChild(QLabel, "plcTablesCellError")
    assert error is not None
    qtbot.waitUntil(error.isVisible)  # under the cell, not dropped
    assert error.text() == "99999 is out of range (-32768 to 65535)"
    assert error.geometry().top() >= rect.bottom() - 1
    editor = _editor(qtbot)
    assert editor.text() == "99999"  # the typed text again, to correct
    _type(qtbot, editor, "abc")
    qtbot.waitUntil(lambda: error.text() == "'abc' is not a number")
    _type(qtbot, _editor(qtbot), "K100")  # WPLSoft's K (decimal) …
    qtbot.waitUntil(lambda: table.state() != QAbstractItemView.State.EditingState)
    assert not error.isVisible()
    assert session.run.read(parse_target("D10", "delta")[0], 2) == 100
    qtbot.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    _type(qtbot, _editor(qtbot), "H1F")  # … and H (hex)
    qtbot.waitUntil(lambda: table.state() != QAbstractItemView.State.EditingState)
    assert session.run.read(parse_target("D10", "delta")[0], 2) == 0x1F
    adder = tables.adder.field
    assert adder.isVisible()  # any device, as WPLSoft's device monitor
    adder.setFocus()
    type_text(qtbot, adder, "D500")
    qtbot.keyClick(adder, Qt.Key.Key_Return)
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D10", "D500"]
    type_text(qtbot, adder, "T5")  # a timer the program does not use: into Timers
    qtbot.keyClick(adder, Qt.Key.Key_Return)
    assert tables.device_tabs.currentWidget() is tables.tables[TIMERS]
    assert [row[0] for row in tables.cell_texts(TIMERS)] == ["T5"]
    type_text(qtbot, adder, "X0")
    qtbot.keyClick(adder, Qt.Key.Key_Return)
    assert tables.adder.error.isVisible() and "'X0'" in tables.adder.error.text()
