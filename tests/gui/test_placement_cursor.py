"""A coil or box placed by a click goes where it belongs (the coil column, right-aligned before
it); the cursor follows it there, so the keys go on from the element just placed."""

from __future__ import annotations

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.ladder import Coil, Contact, FunctionBox
from tests.gui.conftest import Drawer


def _cursor_shown_at(d: Drawer, index: int, row: int, col: int) -> bool:
    view = d.view
    return (view.cursor_cell == (index, row, col)
            and view._cursor_item.rect() == view.cell_rect(index, row, col).adjusted(1, 1, -1, -1))


def test_a_coil_clicked_mid_rung_lands_in_the_coil_column_and_so_does_the_cursor(
        drawer: Drawer) -> None:
    d = drawer
    net = d.view.networks[0]
    coil_column = net.coil_column
    d.key("O")
    d.click(0, 0, 2)  # in the middle of the empty rung
    assert _cursor_shown_at(d, 0, 0, coil_column)
    d.type_inline("Y0.0")
    net = d.view.networks[0]
    assert isinstance(net.cells[(0, coil_column)], Coil)
    assert _cursor_shown_at(d, 0, 0, coil_column)
    d.key("I")  # a contact stays where it is clicked, and the cursor with it
    d.click(0, 0, 1)
    d.type_inline("X0.0")
    assert isinstance(d.view.networks[0].cells[(0, 1)], Contact)
    assert _cursor_shown_at(d, 0, 0, 1)
    d.key("O")  # a coil clicked where one already is: the cursor on that coil
    d.click(0, 0, 3)
    assert _cursor_shown_at(d, 0, 0, coil_column)


def test_a_box_lands_right_aligned_before_the_coil_column_with_the_cursor(
        drawer: Drawer, qtbot: QtBot) -> None:
    d = drawer
    d.key("F")  # the function tool; TMR is first in the drop-down
    d.click(0, 0, 0)
    dialog = d.view.edits.function_dialog
    assert dialog is not None
    qtbot.waitUntil(dialog.isVisible)
    qtbot.keyClick(dialog.table, "1")
    qtbot.keyClick(dialog.table.focusWidget() or dialog.table, Qt.Key.Key_Return)
    with qtbot.waitSignal(dialog.accepted):
        qtbot.keyClick(dialog.comment, Qt.Key.Key_Return)
    net = d.view.networks[0]
    (anchor, box), = [(cell, e) for cell, e in net.cells.items() if isinstance(e, FunctionBox)]
    assert anchor == (0, net.columns - box.width) != (0, 0)  # moved right from the click
    assert _cursor_shown_at(d, 0, *anchor)
