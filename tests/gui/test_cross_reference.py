"""The cross reference dock: readers and writers of an address, jump by double-click."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QItemSelectionModel, Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder.model import Coil
from ladderworks.core.xref import Access, UseKind
from ladderworks.gui.docks.cross_reference import CrossReferenceDock
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import type_text

PROGRAM = """%@2-C
R10.2   MYRELAY
X0.1    START_PB
%
%@3
N00001:
RD         X0.1
AND.NOT    R10.2
WRT        Y0.0
N00002:
RD         X0.2
SET        R10.2
N00003:
RD         X0.3
RST        R10.2
N00004:
RD         R10.2
SUB 44
R20
D100
%
"""


def _open(window: MainWindow, tmp_path: Path) -> CrossReferenceDock:
    path = tmp_path / "xref.LAD"
    path.write_text(PROGRAM, "utf-8")
    assert window.load(path)
    dock = window.cross_reference
    assert isinstance(dock, CrossReferenceDock)
    return dock


def _ask(qtbot: QtBot, dock: CrossReferenceDock, text: str) -> None:
    dock.show()
    dock.raise_()  # its tab, beside the error list
    qtbot.waitUntil(dock.table.isVisible)
    dock.query.clear()
    type_text(qtbot, dock.query, text)
    qtbot.keyClick(dock.query, Qt.Key.Key_Return)


def _rows(dock: CrossReferenceDock) -> list[list[str]]:
    model = dock.model
    return [[model.index(r, c).data() for c in range(model.columnCount())]
            for r in range(model.rowCount())]


def test_a_symbol_typed_lists_readers_and_writers(qtbot: QtBot, window: MainWindow,
                                                  tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    window.actions_by_name["action_dock_cross_reference"].trigger()
    assert dock.isVisible()
    _ask(qtbot, dock, "MYRELAY")
    rows = _rows(dock)
    assert [(r[0], r[1], r[2], r[3], r[5], r[6]) for r in rows] == [
        ("R10.2", "MYRELAY", "1", "N00001", "NOT contact", "Read"),
        ("R10.2", "MYRELAY", "2", "N00002", "SET coil", "Write"),
        ("R10.2", "MYRELAY", "3", "N00003", "RST coil", "Write"),
        ("R10.2", "MYRELAY", "4", "N00004", "Contact", "Read"),
    ]
    assert dock.summary.text() == "R10.2 — uses: 4 (read: 2, written: 2)"
    _ask(qtbot, dock, "R21.0")  # a bit of MOVW's 2-byte input R20
    assert [(r[0], r[5], r[6]) for r in _rows(dock)] == [("R20:2", "MOVW input", "Read")]
    _ask(qtbot, dock, "NOSUCH")
    assert dock.model.rowCount() == 0
    assert "neither an address nor a symbol" in dock.summary.text()


def test_double_click_jumps_the_editor_to_the_network_and_cell(qtbot: QtBot, window: MainWindow,
                                                               tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    _ask(qtbot, dock, "R10.2")
    uses = dock.model.uses
    target = next(k for k, u in enumerate(uses) if u.kind is UseKind.RESET)
    use = uses[target]
    assert use.access is Access.WRITE and use.cell is not None

    def row_in_view() -> bool:
        dock.table.scrollTo(dock.model.index(target, 2))
        return dock.table.viewport().rect().contains(
            dock.table.visualRect(dock.model.index(target, 2)).center())

    qtbot.waitUntil(row_in_view)
    rect = dock.table.visualRect(dock.model.index(target, 2))
    # a double-click as a mouse makes it: press and release, then press again as a double-click
    qtbot.mouseClick(dock.table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    qtbot.mouseDClick(dock.table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    editor = window.editor
    assert editor.cursor_cell == (use.network, *use.cell)
    element = editor.networks[use.network].element_at(*use.cell)
    assert element is not None and isinstance(element[1], Coil)
    assert element[1].address == parse_address("R10.2")
    assert editor.hasFocus()
    # the keyboard does it too: select a row, press Enter
    dock.table.setFocus()
    dock.table.selectionModel().setCurrentIndex(
        dock.model.index(0, 0), QItemSelectionModel.SelectionFlag.ClearAndSelect)
    qtbot.keyClick(dock.table, Qt.Key.Key_Return)
    assert editor.cursor_cell[0] == uses[0].network


def test_context_menu_entry_shows_the_cells_address(qtbot: QtBot, window: MainWindow,
                                                    tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    editor = window.editor
    action = window.actions_by_name["action_cross_reference"]
    assert action in editor.context_actions
    cell = next(c for c, e in editor.networks[1].cells.items() if isinstance(e, Coil))
    editor.move_cursor(1, *cell)
    editor.setFocus()
    qtbot.keyClick(editor, Qt.Key.Key_X,
                   Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier)
    qtbot.waitUntil(dock.isVisible)
    assert dock.query.text() == "R10.2" and dock.query.hasFocus()
    assert dock.model.rowCount() == 4
    editor.move_cursor(3, 0, 5)  # an empty cell: the dock opens with its field to type in
    action.trigger()
    assert dock.query.hasFocus() and dock.query.selectedText() == "R10.2"


def test_the_index_is_built_once_per_program_revision(qtbot: QtBot, window: MainWindow,
                                                      tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    _ask(qtbot, dock, "R10.2")
    _ask(qtbot, dock, "Y0.0")
    _ask(qtbot, dock, "")
    assert dock.builds == 1
    assert dock.model.rowCount() == len(dock.cross_reference())
    editor = window.editor
    editor.move_cursor(0, 0, 0)  # the first contact, X0.1: an edit to X0.4
    editor.edits.delete_at_cursor()
    assert dock._xref is None  # the edit made the index stale
    _ask(qtbot, dock, "X0.1")
    assert dock.builds == 2 and dock.model.rowCount() == 0
    editor.undo_stack.undo()
    _ask(qtbot, dock, "X0.1")
    assert dock.builds == 3 and dock.model.rowCount() == 1


def test_the_dock_speaks_turkish_after_a_live_switch(qtbot: QtBot, window: MainWindow,
                                                     tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    _ask(qtbot, dock, "R10.2")
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_tr"].trigger()
    assert dock.windowTitle() == "Çapraz referans"
    assert dock.model.headerData(0, Qt.Orientation.Horizontal) == "Adres"
    rows = _rows(dock)
    assert (rows[0][4], rows[0][5], rows[0][6]) == ("2. seviye", "DEĞİL kontak", "Okuma")
    assert dock.summary.text() == "R10.2 — kullanım: 4 (okuma: 2, yazma: 2)"
    assert window.actions_by_name["action_cross_reference"].text().startswith("Bu adresin")
    assert window.actions_by_name["action_export_pdf"].text() == "P&DF olarak dışa aktar..."


def test_a_long_list_still_fits_its_columns(qtbot: QtBot, window: MainWindow,
                                            tmp_path: Path) -> None:
    """Every use of a large program: each title readable, the address column not 100 px of
    mostly blank (the real S41 program lists 37,733 uses)."""
    networks = "".join(f"N{n:05d}:\nRD         X0.1\nWRT        Y0.0\n" for n in range(1200))
    path = tmp_path / "long.LAD"
    path.write_text(f"%@3\n{networks}%\n", "utf-8")
    assert window.load(path)
    dock = window.cross_reference
    assert isinstance(dock, CrossReferenceDock)
    _ask(qtbot, dock, "")
    assert dock.model.rowCount() == 2400
    header = dock.table.horizontalHeader()
    for column in range(dock.model.columnCount() - 1):  # the last one stretches
        assert header.sectionSize(column) >= header.sectionSizeHint(column), column
    address = dock.table.fontMetrics().horizontalAdvance("X0.1")
    assert header.sectionSize(0) <= max(header.sectionSizeHint(0), address + 24)
