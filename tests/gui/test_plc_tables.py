"""The PLC tables dock: timer presets (TMRB read-only), counters, data table, keep relays."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractItemView, QApplication, QLineEdit
from pytestqt.qtbot import QtBot

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.il import parse_file
from ladderworks.gui.docks.table_entries import TableKind
from ladderworks.gui.docks.tables import PlcTablesDock
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES
from tests.gui.plc_examples import running_text

PROGRAM = """%@3
RD R1.4
TMR 1
WRT R1.7
RD R2.0
TMRB 2 200
WRT R2.1
RD R9091.1
RD.STK R9091.0
RD.STK X3.0
RD.STK X3.1
CTR 3
WRT R3.0
RD K5.0
WRT R4.0
%
"""
R1_4, R1_7 = parse_address("R1.4"), parse_address("R1.7")


@pytest.fixture
def tables(qtbot: QtBot) -> Iterator[tuple[PlcSession, PlcTablesDock]]:
    """A program with a timer, a fixed timer, a counter and a keep relay, and the tables."""
    UiLanguage().apply("en")
    session = running_text(PROGRAM)
    session.set_timer_preset(1, 1000)
    dock = PlcTablesDock(session)
    qtbot.addWidget(dock)
    dock.show()
    yield session, dock
    session.stop()


def delay_of_r1_7(session: PlcSession) -> int:
    """Turn R1.4 on and measure (in ms of the virtual clock) until R1.7 follows."""
    session.set_bit(R1_4, 0)
    session.run_scans(2)
    assert session.run.engine is not None
    start = session.run.engine.now_ms
    session.set_bit(R1_4, 1)
    while not session.run.bit(R1_7):
        session.run_scans(1)
        assert session.run.engine.now_ms - start < 100_000
    return session.run.engine.now_ms - session.run.engine.period_ms - start


def type_into_cell(qtbot: QtBot, dock: PlcTablesDock, kind: TableKind, row: int, column: int,
                   text: str) -> None:
    """Double-click a cell, type, ENTER: as the user does."""
    table = dock.tables[kind]
    dock.tabs.setCurrentWidget(table)
    rect = table.visualRect(table.model().index(row, column))
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.waitUntil(lambda: isinstance(QApplication.focusWidget(), QLineEdit))
    editor = QApplication.focusWidget()
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)  # the delegate commits from the event loop
    qtbot.waitUntil(lambda: table.state() != QAbstractItemView.State.EditingState)


def test_rows_of_the_program(tables: tuple[PlcSession, PlcTablesDock]) -> None:
    _session, dock = tables
    assert dock.cell_texts(TableKind.TIMER) == [
        ["1", "TMR", "1000", "48", "960"],
        ["2", "TMRB", "200", "8", "200"],
    ]
    assert dock.cell_texts(TableKind.COUNTER) == [["3", "0", "0"]]
    assert dock.cell_texts(TableKind.KEEP) == [["K5", "00000000", "00h"]]
    model = dock.models[TableKind.TIMER]
    assert not model.flags(model.index(1, 2)) & Qt.ItemFlag.ItemIsEditable  # TMRB
    assert model.flags(model.index(0, 2)) & Qt.ItemFlag.ItemIsEditable


def test_changing_a_timer_preset_changes_the_delay(
        qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    assert delay_of_r1_7(session) == 960
    type_into_cell(qtbot, dock, TableKind.TIMER, 0, 2, "500")  # while running
    qtbot.waitUntil(lambda: session.run.timer_preset(1) == 500)
    assert dock.cell_texts(TableKind.TIMER)[0] == ["1", "TMR", "500", "48", "480"]
    assert delay_of_r1_7(session) == 480


def test_refused_values_keep_the_old_one(
        qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    assert dock.edit_cell(TableKind.TIMER, 0, 2, "abc") == "'abc' is not a number"
    assert dock.message.text() == "'abc' is not a number"
    assert dock.edit_cell(TableKind.TIMER, 0, 2, "100000000") == \
        "100000000 is out of range (0 to 99999999)"
    assert session.run.timer_preset(1) == 1000
    assert dock.cell_texts(TableKind.TIMER)[0][2] == "1000"
    problem = dock.edit_cell(TableKind.TIMER, 1, 2, "50")
    assert problem is not None and "TMRB 2" in problem and "fixed in the program" in problem
    assert dock.edit_cell(TableKind.KEEP, 0, 1, "102") is not None
    assert dock.edit_cell(TableKind.COUNTER, 0, 1, "40000") == \
        "40000 is out of range (0 to 32767)"


def test_counter_and_keep_relays(qtbot: QtBot,
                                 tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    type_into_cell(qtbot, dock, TableKind.COUNTER, 0, 1, "3")
    assert session.run.counter(3) == (3, 0)
    for _ in range(3):  # three pulses on ACT X3.1: counts 1, 2, 3 = preset
        session.set_bit(parse_address("X3.1"), 1)
        session.run_scans(1)
        session.set_bit(parse_address("X3.1"), 0)
        session.run_scans(1)
    qtbot.waitUntil(lambda: dock.cell_texts(TableKind.COUNTER) == [["3", "3", "3"]])
    assert session.run.bit(parse_address("R3.0")) == 1
    dock.edit_cell(TableKind.COUNTER, 0, 2, "1")  # the current value can be set too
    session.run_scans(1)
    assert session.run.counter(3) == (3, 1) and session.run.bit(parse_address("R3.0")) == 0
    type_into_cell(qtbot, dock, TableKind.KEEP, 0, 1, "00000001")
    session.run_scans(1)
    assert session.run.bit(parse_address("R4.0")) == 1
    assert dock.cell_texts(TableKind.KEEP) == [["K5", "00000001", "01h"]]


def test_insert_and_delete(qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    menu = dock.context_menu(TableKind.DATA, -1)
    assert [a.objectName() for a in menu.actions()] == ["action_table_insert",
                                                        "action_table_delete"]
    assert not dock.delete_action.isEnabled()
    dock.insert_action.trigger()
    dialog = dock.insert_dialog
    assert dialog is not None and dialog.isVisible()
    dialog.set_texts(["D20", "2", "70000"])
    dialog.try_accept()
    assert dialog.isVisible() and "out of range (-32768 to 65535)" in dialog.error.text()
    dialog.set_texts(["D20", "2", "-2"])
    dialog.try_accept()
    qtbot.waitUntil(lambda: not dialog.isVisible())
    assert dock.cell_texts(TableKind.DATA) == [["D20", "2", "-2", "FFFEh"]]
    assert session.run.read(Address(Area.D, 20), 2) == 0xFFFE
    type_into_cell(qtbot, dock, TableKind.DATA, 0, 2, "1234")
    assert session.run.read(Address(Area.D, 20), 2) == 1234
    assert dock.insert_texts(TableKind.TIMER, ["12", "38"]) is None
    assert dock.cell_texts(TableKind.TIMER)[2] == ["12", "TMR", "38", "8", "32"]  # manual: 32
    assert dock.insert_texts(TableKind.TIMER, ["101", "5"]) == "101 is out of range (1 to 100)"
    assert dock.insert_texts(TableKind.COUNTER, ["7", "12", "4"]) is None
    assert session.run.counter(7) == (12, 4)
    assert dock.insert_texts(TableKind.KEEP, ["K9", "1010"]) is None
    assert session.run.read(Address(Area.K, 9)) == 0b1010
    # DELETE clears the row under the mouse; a row the program uses stays, at 0
    dock.context_menu(TableKind.DATA, 0)
    assert dock.delete_action.isEnabled()
    dock.delete_action.trigger()
    assert dock.cell_texts(TableKind.DATA) == []
    assert session.run.read(Address(Area.D, 20), 2) == 0
    assert dock.delete_row(TableKind.TIMER, 2) is None  # timer 12, listed by the user
    assert [row[0] for row in dock.cell_texts(TableKind.TIMER)] == ["1", "2"]
    assert dock.delete_row(TableKind.TIMER, 0) is None  # timer 1: the program's, kept at 0
    assert dock.cell_texts(TableKind.TIMER)[0] == ["1", "TMR", "0", "48", "0"]
    assert "fixed in the program" in (dock.delete_row(TableKind.TIMER, 1) or "")
    assert dock.cell_texts(TableKind.TIMER)[1][2] == "200"


def test_values_follow_the_plc_and_a_new_program(
        qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    session.write(Address(Area.K, 50), 0x81)  # e.g. set by another tool
    session.run_scans(1)
    qtbot.waitUntil(lambda: ["K50", "10000001", "81h"] in dock.cell_texts(TableKind.KEEP))
    session.load_program(parse_file(EXAMPLES / "timer_relay.LAD").program)
    assert [row[1] for row in dock.cell_texts(TableKind.TIMER)] == ["TMR"]  # no TMRB now


def _widths(dock: PlcTablesDock, kind: TableKind) -> list[int]:
    """The column widths, but the last (it stretches to the view's width)."""
    table = dock.tables[kind]
    return [table.columnWidth(column) for column in range(table.model().columnCount() - 1)]


def _fitted(dock: PlcTablesDock, kind: TableKind) -> list[int]:
    """The widths resizeColumnsToContents gives the table now."""
    dock.tables[kind].resizeColumnsToContents()
    return _widths(dock, kind)


def test_hidden_tables_fit_their_columns_when_shown(
        qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    dock.hide()
    session.load_program(parse_file(EXAMPLES / "timer_relay.LAD").program)
    for kind in TableKind:
        dock.tables[kind].setColumnWidth(0, 333)  # what a fit made while hidden would change
    dock.show()
    dock.tabs.setCurrentWidget(dock.tables[TableKind.TIMER])
    shown = _widths(dock, TableKind.TIMER)
    assert shown[0] != 333 and shown == _fitted(dock, TableKind.TIMER)
    assert _widths(dock, TableKind.DATA)[0] == 333  # not shown yet: not fitted yet
    dock.tabs.setCurrentWidget(dock.tables[TableKind.DATA])
    shown = _widths(dock, TableKind.DATA)
    assert shown[0] != 333 and shown == _fitted(dock, TableKind.DATA)


def test_a_shown_table_fits_its_columns_at_once(
        qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    session, dock = tables
    dock.tabs.setCurrentWidget(dock.tables[TableKind.TIMER])
    dock.tables[TableKind.TIMER].setColumnWidth(0, 333)
    session.load_program(parse_file(EXAMPLES / "timer_relay.LAD").program)
    shown = _widths(dock, TableKind.TIMER)
    assert shown[0] != 333 and shown == _fitted(dock, TableKind.TIMER)


def test_turkish(qtbot: QtBot, tables: tuple[PlcSession, PlcTablesDock]) -> None:
    _session, dock = tables
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: dock.windowTitle() == "PLC TABLOLARI")
        dock.context_menu(TableKind.TIMER, 0)
        assert dock.insert_action is not None and dock.insert_action.text() == "EKLE (INSERT)"
        assert dock.edit_cell(TableKind.TIMER, 0, 2, "abc") == "'abc' bir sayı değil"
    finally:
        language.apply("en")


def test_every_plc_dock_has_its_view_toggle(qtbot: QtBot, window: MainWindow) -> None:
    from PySide6.QtWidgets import QDockWidget

    docks = window.plc_docks
    shown = [docks.bit_display, docks.time_chart, docks.alarms, docks.tables]
    assert [d.objectName() for d in shown] == ["bitDisplayDock", "timeChartDock", "alarmDock",
                                               "plcTablesDock"]
    found = window.findChildren(QDockWidget)
    assert all(dock in found for dock in shown)
    view = window.menus.menus["menu_view"]
    names = [action.objectName() for action in view.actions()]
    for name in ("action_dock_bit_display", "action_dock_time_chart", "action_dock_alarms",
                 "action_dock_plc_tables"):
        assert name in names
        if not window.actions_by_name[name].isChecked():
            window.actions_by_name[name].trigger()
        assert window.actions_by_name[name].isChecked()
    # tabbed for small screens: each toggle brought its dock to the front of its group
    assert docks.bit_display in window.tabifiedDockWidgets(docks.tables)
    assert docks.alarms in window.tabifiedDockWidgets(docks.time_chart)
    assert docks.tables.isVisible() and docks.time_chart.isVisible()
