"""Issue 31 item 2: ESC cancels a placement, and a second ESC goes back to the Select tool."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Contact
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.tools import Tool
from tests.gui.conftest import Drawer


def test_escape_takes_away_the_element_just_placed_and_its_step(drawer: Drawer,
                                                                window: MainWindow,
                                                                qtbot: QtBot) -> None:
    stack = window.editor.undo_stack
    drawer.key("I")
    drawer.click(0, 0, 0)
    editor = window.editor.inline_editor
    qtbot.waitUntil(editor.isVisible)
    assert window.editor.networks[0].cells.get((0, 0)) == Contact()  # the "?" element
    qtbot.keyClick(editor, Qt.Key.Key_Escape)
    assert not editor.isVisible()
    assert (0, 0) not in window.editor.networks[0].cells
    assert stack.count() == 0 and not stack.canUndo() and not stack.canRedo()
    assert not window.is_modified()
    assert window.current_tool() is Tool.INPUT  # the tool stays until a second ESC
    qtbot.keyClick(window.editor, Qt.Key.Key_Escape)
    assert window.current_tool() is Tool.SELECT
    drawer.click(0, 0, 3)  # a click now only moves the cursor
    assert window.editor.networks[0].cells == {}
    assert window.editor.cursor_cell == (0, 0, 3)


def test_escape_on_an_element_with_an_address_keeps_it(drawer: Drawer, window: MainWindow,
                                                         qtbot: QtBot) -> None:
    drawer.element(0, 0, 0, "I", "X2.1")
    steps = window.editor.undo_stack.count()
    drawer.key("I")
    drawer.click(0, 0, 0)  # the same kind: its address opens again
    editor = window.editor.inline_editor
    qtbot.waitUntil(editor.isVisible)
    qtbot.keyClick(editor, Qt.Key.Key_Escape)
    assert window.editor.networks[0].cells[(0, 0)] == Contact(parse_address("X2.1"))
    assert window.editor.undo_stack.count() == steps


def test_escape_after_a_refused_address_still_removes_the_placed_coil(
        drawer: Drawer, window: MainWindow, qtbot: QtBot) -> None:
    drawer.element(0, 0, 0, "I", "X2.1")
    steps = window.editor.undo_stack.count()
    drawer.key("O")
    drawer.click(0, 0, 4)
    editor = window.editor.inline_editor
    qtbot.waitUntil(editor.isVisible)
    qtbot.keyClicks(editor, "Q1.0")
    qtbot.keyClick(editor, Qt.Key.Key_Return)  # refused: the edit stays open
    assert editor.isVisible()
    qtbot.keyClick(editor, Qt.Key.Key_Escape)
    assert len(window.editor.networks[0].cells) == 1  # the contact alone, no wire, no coil
    assert window.editor.undo_stack.count() == steps
    assert not window.editor.undo_stack.canRedo()
