"""Issues 25/26: the PLC tables dock of a Delta or Fatek program shows its timers, counters and
registers (as WPLSoft's / WinProladder's device monitor) live, and writes a typed value into
the PLC."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractItemView, QApplication, QLineEdit
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.gui.docks.table_entries import TableKind
from ladderworks.gui.docks.tables import PlcTablesDock
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_session import PlcSession

TIMERS, COUNTERS, REGISTERS = TableKind.DEVICE_TIMERS, TableKind.DEVICE_COUNTERS, \
    TableKind.REGISTERS


def _run(qtbot: QtBot, window: MainWindow, path: str) -> tuple[PlcSession, PlcTablesDock]:
    """Open an example, compile it (F9) into the PLC, start it; the tables dock shown."""
    assert window.load(paths.EXAMPLES / path)
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    assert session.start()
    tables = window.plc_docks.tables
    tables.show()
    return session, tables


def _row(tables: PlcTablesDock, kind: TableKind, device: str) -> list[str]:
    return next(row for row in tables.cell_texts(kind) if row[0] == device)


def test_delta_timer_counter_and_register(qtbot: QtBot, window: MainWindow) -> None:
    session, tables = _run(qtbot, window, "delta/timer_t0.txt")
    assert tables.device_tabs.isVisibleTo(tables) and not tables.tabs.isVisibleTo(tables)
    assert not tables.dialect_note.isVisibleTo(tables)
    assert tables.device_tabs.tabText(0) == "Timers (T)"
    assert tables.device_tabs.tabText(2) == "Registers (D, CR)"  # CR: modules' registers
    assert tables.cell_texts(TIMERS) == [["T0", "100 ms", "K10", "0", "OFF"]]
    session.set_bit(parse_target("X0", "delta")[0], 1)
    session.step(500)
    row = _row(tables, TIMERS, "T0")
    assert 4 <= int(row[3]) <= 5 and row[4] == "OFF"
    # a current value typed in the table goes into the PLC, and the timer counts on from it
    assert tables.edit_cell(TIMERS, 0, 3, "9") is None
    assert session.run.read(parse_target("T0", "delta")[0], 2) == 9
    session.step(200)
    assert _row(tables, TIMERS, "T0")[3:] == ["10", "ON"]
    assert session.run.bit(parse_target("Y0", "delta")[0]) == 1
    model = tables.models[TIMERS]  # only the current value is typed into
    assert [bool(model.flags(model.index(0, column)) & Qt.ItemFlag.ItemIsEditable)
            for column in range(5)] == [False, False, False, True, False]
    # a register the program does not use is added by INSERT, as a range
    assert tables.insert_texts(REGISTERS, ["D100-D102"]) is None
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D100", "D101", "D102"]
    assert tables.edit_cell(REGISTERS, 1, 1, "-2") is None
    assert session.run.read(parse_target("D101", "delta")[0], 2) == 0xFFFE
    assert _row(tables, REGISTERS, "D101") == ["D101", "-2", "FFFE"]
    assert tables.edit_cell(REGISTERS, 2, 2, "7FFF") is None
    assert session.run.read(parse_target("D102", "delta")[0], 2) == 32767
    assert tables.edit_cell(REGISTERS, 2, 1, "70000") is not None  # out of 16 bits
    assert tables.insert_texts(REGISTERS, ["T5"]) is not None  # not a register
    assert tables.insert_texts(REGISTERS, ["D9-D2"]) is not None


def test_delta_counter_counts_in_the_table(qtbot: QtBot, window: MainWindow) -> None:
    session, tables = _run(qtbot, window, "delta/counter_reset.txt")
    assert tables.cell_texts(COUNTERS) == [["C0", "16-bit up", "K10", "0", "OFF"]]
    x0 = parse_target("X0", "delta")[0]
    for _ in range(3):
        session.set_bit(x0, 1)
        session.run_scans(1)
        session.set_bit(x0, 0)
        session.run_scans(1)
    tables.device_tabs.setCurrentIndex(1)
    assert _row(tables, COUNTERS, "C0")[3:] == ["3", "OFF"]
    assert tables.edit_cell(COUNTERS, 0, 3, "9") is None
    session.set_bit(x0, 1)
    session.run_scans(1)
    assert _row(tables, COUNTERS, "C0")[3:] == ["10", "ON"]
    model = tables.models[COUNTERS]  # an ON contact is drawn green, an OFF one not
    assert model.data(model.index(0, 4), Qt.ItemDataRole.BackgroundRole) is not None
    assert model.data(model.index(0, 3), Qt.ItemDataRole.BackgroundRole) is None
    session.set_bit(parse_target("X1", "delta")[0], 1)  # RST C0
    session.run_scans(1)
    assert _row(tables, COUNTERS, "C0")[3:] == ["0", "OFF"]
    assert model.data(model.index(0, 4), Qt.ItemDataRole.BackgroundRole) \
        == model.data(model.index(0, 1), Qt.ItemDataRole.BackgroundRole)  # read-only grey


def test_delta_register_preset_and_32bit_counter(qtbot: QtBot, window: MainWindow,
                                                 tmp_path: Path) -> None:
    program = tmp_path / "presets.txt"
    program.write_text("LD X0\nTMR T64 D5\nLD X1\nDCNT C200 K3\nLD M1000\nMOV K7 D5\nEND\n",
                       encoding="utf-8")
    session, tables = _run(qtbot, window, str(program))
    session.run_scans(1)
    assert tables.cell_texts(TIMERS) == [["T64", "100 ms", "D5 = 7", "0", "OFF"]]
    assert tables.cell_texts(COUNTERS) == [["C200", "32-bit up/down", "K3", "0", "OFF"]]
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D5"]
    session.set_bit(parse_target("M1028", "delta")[0], 1)
    session.run_scans(1)
    assert _row(tables, TIMERS, "T64")[1] == "10 ms"
    model = tables.models[TIMERS]
    assert model.data(model.index(0, 1), Qt.ItemDataRole.ToolTipRole) == "M1028 on: 10 ms a count"
    assert tables.edit_cell(COUNTERS, 0, 3, "-100000") is None
    assert session.run.read(parse_target("C200", "delta")[0], 4) == (-100000) & 0xFFFFFFFF


def test_fatek_tables(qtbot: QtBot, window: MainWindow) -> None:
    session, tables = _run(qtbot, window, "fatek/conveyor.lst")
    assert tables.device_tabs.tabText(2) == "Registers (R, D)"
    assert tables.cell_texts(TIMERS) == [["T50", "100 ms", "30", "0", "OFF"]]
    assert tables.cell_texts(COUNTERS) == [["C0", "16-bit up", "5", "0", "OFF"]]
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["R0", "R1", "R2"]
    session.run_scans(1)
    assert _row(tables, REGISTERS, "R2")[1] == "100"  # MOV 100 R2 at the first scan
    session.set_bit(parse_target("X0", "fatek")[0], 1)  # Y0 on: T50 runs
    session.step(500)
    assert 4 <= int(_row(tables, TIMERS, "T50")[3]) <= 5
    assert tables.edit_cell(TIMERS, 0, 3, "29") is None  # counts on from 29
    session.step(200)
    row = _row(tables, TIMERS, "T50")  # a Fatek timer runs on past its preset (001:392)
    assert row[3] in ("30", "31") and row[4] == "ON"
    x2 = parse_target("X2", "fatek")[0]
    for _ in range(2):
        session.set_bit(x2, 1)
        session.run_scans(1)
        session.set_bit(x2, 0)
        session.run_scans(1)
    assert _row(tables, COUNTERS, "C0")[3] == "2"
    assert tables.edit_cell(REGISTERS, 0, 1, "1234") is None
    assert session.run.read(parse_target("R0", "fatek")[0], 2) == 1234
    assert tables.insert_texts(REGISTERS, ["D0-D1"]) is None
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["R0", "R1", "R2", "D0", "D1"]
    assert tables.edit_cell(REGISTERS, 3, 2, "H00FF") is None
    assert session.run.read(parse_target("D0", "fatek")[0], 2) == 255


def test_device_tables_in_turkish_and_back_to_pmc(qtbot: QtBot, window: MainWindow) -> None:
    session, tables = _run(qtbot, window, "delta/timer_t0.txt")
    window.set_language("tr")
    assert tables.device_tabs.tabText(0) == "Zamanlayıcı (T)"
    assert tables.cell_texts(TIMERS)[0][4] == "KAPALI"
    window.set_language("en")
    session.stop()
    assert window.load(paths.EXAMPLES / "mcode_decoder.LAD")
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert tables.tabs.isVisibleTo(tables) and not tables.device_tabs.isVisibleTo(tables)


def test_the_last_column_fills_the_table(qtbot: QtBot, window: MainWindow) -> None:
    window.resize(1000, 600)
    window.show()
    _session, tables = _run(qtbot, window, "fatek/conveyor.lst")
    tables.raise_()
    tables.device_tabs.setCurrentIndex(2)
    qtbot.wait(50)
    view = tables.tables[REGISTERS]
    header = view.horizontalHeader()
    assert sum(header.sectionSize(i) for i in range(header.count())) >= \
        view.viewport().width() - 2


def test_insert_form_and_delete_on_a_device_table(qtbot: QtBot, window: MainWindow) -> None:
    session, tables = _run(qtbot, window, "delta/cmp_d10.txt")
    tables.device_tabs.setCurrentIndex(2)
    tables.context_menu(REGISTERS, -1)
    assert tables.insert_action is not None
    tables.insert_action.trigger()
    dialog = tables.insert_dialog
    assert dialog is not None and dialog.isVisible() and len(dialog.fields) == 1
    dialog.set_texts(["D20-D10"])
    dialog.try_accept()
    assert dialog.isVisible() and "D20-D10" in dialog.error.text()
    dialog.set_texts(["D20-D21"])
    dialog.try_accept()
    qtbot.waitUntil(lambda: not dialog.isVisible())
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D10", "D20", "D21"]
    session.run.write(parse_target("D21", "delta")[0], 77, 2)
    session.run_scans(1)
    assert _row(tables, REGISTERS, "D21")[1:] == ["77", "004D"]
    tables.context_menu(REGISTERS, 2)
    assert tables.delete_action is not None and tables.delete_action.isEnabled()
    tables.delete_action.trigger()  # an added device leaves the list; its value stays
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D10", "D20"]
    assert session.run.read(parse_target("D21", "delta")[0], 2) == 77
    assert tables.delete_row(REGISTERS, 0) is None  # the program's D10 stays listed
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D10", "D20"]


def test_a_value_typed_into_the_cell(qtbot: QtBot, window: MainWindow) -> None:
    """Double-click a register's value, type, ENTER: as the user does."""
    window.show()
    session, tables = _run(qtbot, window, "fatek/conveyor.lst")
    tables.raise_()
    table = tables.tables[REGISTERS]
    tables.device_tabs.setCurrentWidget(table)
    qtbot.waitUntil(table.isVisible)
    rect = table.visualRect(table.model().index(1, 2))  # R1's hex
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.waitUntil(lambda: isinstance(QApplication.focusWidget(), QLineEdit))
    editor = QApplication.focusWidget()
    assert isinstance(editor, QLineEdit)
    editor.selectAll()
    qtbot.keyClicks(editor, "FF00")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.state() != QAbstractItemView.State.EditingState)
    assert session.run.read(parse_target("R1", "fatek")[0], 2) == 0xFF00
    assert _row(tables, REGISTERS, "R1")[1:] == ["-256", "FF00"]


def test_delta_from_lists_its_module_register_to_type_into(qtbot: QtBot, window: MainWindow,
                                                           tmp_path: Path) -> None:
    """Issue 36: FROM's CR is shown without INSERT; a value typed there is what FROM reads."""
    program = tmp_path / "analog.txt"
    program.write_text("LD M1000\nFROM K0 K12 D200 K1\nEND\n", encoding="utf-8")
    session, tables = _run(qtbot, window, str(program))
    session.run_scans(1)
    assert [row[0] for row in tables.cell_texts(REGISTERS)] == ["D200", "CR12"]  # module 0, CR#12
    row = [row[0] for row in tables.cell_texts(REGISTERS)].index("CR12")
    assert tables.edit_cell(REGISTERS, row, 1, "1234") is None
    assert session.run.read(parse_target("CR12", "delta")[0], 2) == 1234
    session.run_scans(1)
    assert session.run.read(parse_target("D200", "delta")[0], 2) == 1234
    assert _row(tables, REGISTERS, "D200")[1] == "1234"
