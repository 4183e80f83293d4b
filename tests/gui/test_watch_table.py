"""Issue 39's real-window test: an exported S7 folder (SD and XML) opened with File › Open
folder, run with START, "Start" modified to TRUE in the watch table and the coil "Motor" seen
TRUE in the table and in the memory; the rows kept per program; other families watched too."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QAbstractItemView, QComboBox, QLineEdit, QToolBar
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.watch.values import Format
from ladderworks.gui import file_dialogs
from ladderworks.gui.docks.watch_table import ADDRESS, FORMAT, MODIFY, MONITOR, NAME
from ladderworks.gui.main_window import MainWindow

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples"


def _text(window: MainWindow, row: int, column: int) -> str:
    item = window.plc_docks.watch.table.item(row, column)
    assert item is not None
    return item.text()


def _type_into(qtbot: QtBot, window: MainWindow, row: int, column: int, text: str) -> None:
    """Type `text` into a cell's editor and press Enter, as a user does."""
    table = window.plc_docks.watch.table
    item = table.item(row, column)
    assert item is not None
    table.setCurrentCell(row, column)
    table.editItem(item)
    editors = [e for e in table.viewport().findChildren(QLineEdit) if e.isVisible()]
    assert len(editors) == 1
    editor = editors[0]
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)  # Qt commits it on its next turn
    qtbot.waitUntil(lambda: table.state() != QAbstractItemView.State.EditingState)


def _type_name(qtbot: QtBot, window: MainWindow, name: str) -> int:
    """Type a name into the table's last (empty) row, as a user adds one."""
    table = window.plc_docks.watch.table
    last = table.rowCount() - 1
    _type_into(qtbot, window, last, NAME, name)
    qtbot.waitUntil(lambda: table.rowCount() == last + 2)
    return last


@pytest.mark.parametrize("form", ["s7", "s7-xml"])
def test_an_exported_folder_runs_and_a_watch_table_modify_drives_the_coil(
        qtbot: QtBot, window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        form: str) -> None:
    folder = tmp_path / "jumps"
    shutil.copytree(EXAMPLES / form / "jumps", folder)
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    monkeypatch.setattr(file_dialogs, "open_folder_name", lambda *_args: str(folder))
    window.actions_by_name["action_open_folder"].trigger()
    assert window.path == folder
    assert window.windowTitle().startswith("jumps")
    assert window.settings.recent_files()[0] == str(folder)
    assert window.editor.networks
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)  # compile and load, as a user does
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()
    assert session.run.running

    toggle = window.actions_by_name["action_dock_watch_table"]
    toolbar = window.findChild(QToolBar, "toolbar_main")
    assert toolbar is not None and toggle in toolbar.actions()
    assert toggle in window.menus.menus["menu_plc"].actions()
    toggle.trigger()
    watch = window.plc_docks.watch
    qtbot.waitUntil(watch.isVisible)
    start_row = _type_name(qtbot, window, '"Start"')
    motor_row = _type_name(qtbot, window, "Motor")
    assert _text(window, start_row, ADDRESS) == "%I0.2"
    assert _text(window, motor_row, ADDRESS) == "%Q0.2"
    session.run_scans(2)
    assert _text(window, motor_row, MONITOR) == "FALSE"

    _type_into(qtbot, window, start_row, MODIFY, "TRUE")
    assert watch.rows[start_row].modify == "TRUE"
    table = watch.table
    table.selectRow(start_row)
    qtbot.mouseClick(window.findChild(type(watch.modify_button), "watchModifyNow"),
                     Qt.MouseButton.LeftButton)
    session.run_scans(2)
    motor, _ = parse_absolute("%Q0.2")
    assert session.run.bit(motor) == 1
    assert _text(window, motor_row, MONITOR) == "TRUE"
    assert _text(window, start_row, MONITOR) == "TRUE"

    # a bad value is refused at its cell, translated; nothing else is written
    watch.set_modify(start_row, "maybe", checked=True)
    assert watch.modify_now() == 0
    qtbot.waitUntil(watch.cell_error.isVisible)
    assert "TRUE or FALSE" in watch.cell_error.text()
    assert list(watch.modify_errors) == [start_row]
    assert watch.modify_errors[start_row].code == "watch-bool"

    # the display format follows the user's choice and is kept with the rows
    box = table.cellWidget(motor_row, FORMAT)
    assert isinstance(box, QComboBox) and box.currentData() == Format.BOOL.value
    watch.set_format(motor_row, Format.DEC)
    assert _text(window, motor_row, MONITOR) == "1"

    # Save of the unchanged folder writes nothing; reopened from the recent list, the rows
    assert window.save()
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before
    window.new_file()
    assert watch.rows == []
    window.actions_by_name["action_recent_0"].trigger()
    assert window.path == folder
    assert [(r.name, r.fmt, r.modify, r.checked) for r in watch.rows] == [
        ('"Start"', "", "maybe", True), ("Motor", Format.DEC.value, "", False)]
    assert _text(window, motor_row, NAME) == "Motor"
    assert _text(window, start_row, MODIFY) == "maybe"


def test_a_delta_program_is_watched_by_its_devices(qtbot: QtBot, window: MainWindow,
                                                    tmp_path: Path) -> None:
    path = tmp_path / "seal.txt"
    path.write_text("LD X0\nOR Y0\nANI X1\nOUT Y0\nLD M1000\nMOV K-5 D0\nEND\n", "utf-8")
    assert window.load(path)
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    window.findChild(QAction, "action_plc_start").trigger()
    window.actions_by_name["action_dock_watch_table"].trigger()
    watch = window.plc_docks.watch
    qtbot.waitUntil(watch.isVisible)
    x0 = watch.add_row("X0")
    y0 = watch.add_row("Y0")
    d0 = watch.add_row("D0")
    bad = watch.add_row("Q9")
    session.run_scans(2)
    assert _text(window, d0, MONITOR) == "-5"
    assert _text(window, y0, MONITOR) == "FALSE"
    assert "neither a name" in _text(window, bad, ADDRESS)
    watch.set_modify(x0, "1", checked=True)
    assert watch.modify_now() == 1
    session.run_scans(2)
    assert _text(window, y0, MONITOR) == "TRUE"
    watch.table.selectRow(bad)
    watch.table.setFocus()
    qtbot.keyClick(watch.table, Qt.Key.Key_Delete)  # the bad row goes
    assert [row.name for row in watch.rows] == ["X0", "Y0", "D0"]
    assert not window.is_modified()  # not the ladder's Delete


def test_live_values_while_the_plc_scans_in_real_time_and_turkish_texts(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    """The PLC scanning on its own (thread, then its process): the Monitor values follow,
    a modify reaches the scans; a language switch retitles the columns and formats."""
    folder = tmp_path / "timers"
    shutil.copytree(EXAMPLES / "s7" / "timers", folder)
    assert window.load(folder)
    session = window.plc_docks.session
    assert session.run.realtime
    assert window.compile() is not None
    window.findChild(QAction, "action_plc_start").trigger()
    window.actions_by_name["action_dock_watch_table"].trigger()
    watch = window.plc_docks.watch
    qtbot.waitUntil(watch.isVisible)
    start = watch.add_row("Start")
    elapsed = watch.add_row('"IEC_Timer_0_DB".ET')
    lamp = watch.add_row('"Lamba 2"')
    assert _text(window, elapsed, MONITOR) == "T#0MS"
    watch.set_modify(start, "TRUE", checked=True)
    assert watch.modify_now() == 1
    qtbot.waitUntil(lambda: _text(window, elapsed, MONITOR) not in ("", "T#0MS"),
                    timeout=10000)
    assert _text(window, lamp, MONITOR) == "FALSE"  # [%MD0 >= T#5s]: not before 5 s
    window.set_language("tr")
    try:
        header = watch.table.horizontalHeaderItem
        assert [header(c).text() for c in range(5)] == [
            "Ad", "Adres", "Görüntüleme biçimi", "İzleme değeri", "Değiştirme değeri"]
        assert watch.windowTitle() == "İzleme tablosu"
        assert watch.modify_button.text() == "Şimdi değiştir"
        assert watch.message.text() == "Yazılan değer: 1"  # said again in Turkish
        box = watch.table.cellWidget(elapsed, FORMAT)
        assert isinstance(box, QComboBox) and box.currentText() == "Zaman"
        for column in range(5):  # no cut title
            assert watch.table.columnWidth(column) >= \
                watch.table.horizontalHeader().sectionSizeHint(column) or column == MODIFY
    finally:
        window.set_language("en")
    session.stop()


def test_a_changed_folder_program_writes_its_entry_block_file_only(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    folder = tmp_path / "timers"
    shutil.copytree(EXAMPLES / "s7" / "timers", folder)
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    assert window.load(folder)
    window.editor.move_cursor(1, 0, 0)
    window.actions_by_name["action_delete_network"].trigger()
    asked: list[str] = []
    monkeypatch.setattr(file_dialogs, "save_file_name",
                        lambda *args: asked.append(str(args[2])) or "")
    assert window.save()
    assert not asked and window.path == folder  # no file name asked: the folder's own file
    after = {p.name: p.read_bytes() for p in folder.iterdir()}
    assert [name for name in after if after[name] != before[name]] == ["Main.s7dcl"]


def test_a_folder_without_exports_is_refused_with_its_reason(window: MainWindow,
                                                             tmp_path: Path) -> None:
    folder = tmp_path / "empty"
    folder.mkdir()
    (folder / "notes.txt").write_text("not a block\n", "utf-8")
    window.load(folder)
    assert window.model.showing_text
    tree = window.errors.tree
    shown = [tree.topLevelItem(i).text(c) for i in range(tree.topLevelItemCount())
             for c in range(tree.columnCount())]
    assert any(".s7dcl" in text for text in shown), shown
    window.save()
    assert sorted(p.name for p in folder.iterdir()) == ["notes.txt"]
