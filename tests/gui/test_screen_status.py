"""Issue 31 item 7: the status bar describes the cursor's cell as it is now."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Drawer, type_text


def test_a_changed_address_is_described_at_once(drawer: Drawer, window: MainWindow,
                                                qtbot: QtBot) -> None:
    drawer.element(0, 0, 0, "I", "X21.7")
    window.editor.move_cursor(0, 0, 0)
    assert "X21.7" in window.cell_label.text()
    window.editor.edit_at_cursor()  # ENTER on the contact: its address editor
    editor = window.editor.inline_editor
    qtbot.waitUntil(editor.isVisible)
    editor.clear()
    type_text(qtbot, editor, "X21.6")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    assert "X21.6" in window.cell_label.text()
    assert "X21.7" not in window.cell_label.text()
    window.editor.undo_stack.undo()  # undo too: the cell as it is again
    assert "X21.7" in window.cell_label.text()


def test_a_coil_placed_is_described_where_it_landed(drawer: Drawer, window: MainWindow,
                                                    qtbot: QtBot) -> None:
    drawer.element(0, 0, 0, "I", "X2.1")
    qtbot.mouseMove(window.editor.viewport(), window.editor.cell_point(0, 0, 3))
    drawer.key("O")
    drawer.click(0, 0, 3)  # the coil goes to the coil column, not to column 3
    index, row, col = window.editor.cursor_cell
    coil_column = window.editor.networks[0].coil_column
    assert col == coil_column and col != 3
    assert window.cell_label.text() == window.editor.describe_cell(index, row, col)
    drawer.type_inline("Y0.0")
    assert "Y0.0" in window.cell_label.text()
    assert window.cell_label.text() == window.editor.describe_cell(0, 0, coil_column)
