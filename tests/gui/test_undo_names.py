"""Edit › Undo and Redo name their step ("Undo Delete", "Geri al: Sil"), and the names follow
a live language switch; the address typed with its comment is one step."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction

from ladderworks.core.ladder import Contact, FunctionBox
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Drawer


def _undo(window: MainWindow) -> QAction:
    return window.actions_by_name["action_undo"]


def _redo(window: MainWindow) -> QAction:
    return window.actions_by_name["action_redo"]


def test_undo_and_redo_name_the_step_in_the_language_shown(drawer: Drawer) -> None:
    d = drawer
    window = d.window
    assert _undo(window).text() == "&Undo"  # nothing to undo yet
    d.element(0, 0, 0, "I", "X0.0")
    assert _undo(window).text() == "&Undo Address X0.0"  # placing, then the address typed
    d.key("S")
    d.click(0, 0, 0)
    d.key(Qt.Key.Key_Delete)
    assert _undo(window).text() == "&Undo Delete"
    window.set_language("tr")
    assert _undo(window).text() == "&Geri al: Sil"  # wholly Turkish
    window.model.undo_stack.undo()
    assert _redo(window).text() == "&Yinele: Sil"
    assert _undo(window).text() == "&Geri al: Adres X0.0"
    window.set_language("en")
    assert _undo(window).text() == "&Undo Address X0.0"  # wholly English again
    assert _redo(window).text() == "&Redo Delete"
    assert _undo(window).toolTip() == "Undo Address X0.0"


def test_an_address_typed_with_its_comment_is_one_step(drawer: Drawer) -> None:
    d = drawer
    stack = d.window.model.undo_stack
    d.element(0, 0, 0, "I", "X0.0")
    steps = stack.count()
    d.click(0, 0, 0)  # the input tool on its own contact: edit its address and comment
    d.type_inline("X0.1 // KAPI")
    assert stack.count() == steps + 1
    contact = d.view.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact)
    assert (str(contact.address), contact.comment) == ("X0.1", "KAPI")
    stack.undo()
    contact = d.view.networks[0].cells[(0, 0)]
    assert (str(contact.address), contact.comment) == ("X0.0", "")  # both taken back


def test_a_boxs_parameters_and_comment_are_one_step(drawer: Drawer) -> None:
    d = drawer
    qtbot = d.qtbot
    stack = d.window.model.undo_stack

    def fill(number: str, comment: str) -> None:
        dialog = d.view.edits.function_dialog
        assert dialog is not None
        qtbot.waitUntil(dialog.isVisible)
        qtbot.keyClick(dialog.table, number)
        qtbot.keyClick(dialog.table.focusWidget() or dialog.table, Qt.Key.Key_Return)
        dialog.comment.clear()
        dialog.comment.insert(comment)
        with qtbot.waitSignal(dialog.accepted):
            qtbot.keyClick(dialog.comment, Qt.Key.Key_Return)

    d.key("F")  # the function tool; TMR is first in the drop-down
    d.click(0, 0, 0)
    fill("1", "ILK")
    (anchor, box), = [(c, e) for c, e in d.view.networks[0].cells.items()
                      if isinstance(e, FunctionBox)]
    steps = stack.count()
    d.key("S")
    d.click(0, *anchor)
    d.key(Qt.Key.Key_Return)  # ENTER on the box: its function table
    fill("2", "IKINCI")
    changed = d.view.networks[0].cells[anchor]
    assert isinstance(changed, FunctionBox) and changed.comment == "IKINCI"
    assert changed.params != box.params
    assert stack.count() == steps + 1
    assert _undo(d.window).text() == "&Undo Parameters of TMR"
    stack.undo()
    assert d.view.networks[0].cells[anchor] == box  # parameters and comment taken back
