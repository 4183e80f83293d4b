"""The grid editor: in-place address editing, the function table, tools, keys, menu, zoom."""

from __future__ import annotations

from PySide6.QtCore import QPoint, Qt, QTimer
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QApplication, QMenu
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Coil, Contact, FunctionBox, Wire
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.tools import Tool
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import Drawer, type_text


def test_invalid_address_is_refused_with_a_message(drawer: Drawer, window: MainWindow,
                                                   qtbot: QtBot) -> None:
    drawer.key("I")
    drawer.click(0, 0, 0)
    editor = window.editor.inline_editor
    qtbot.waitUntil(editor.isVisible)
    type_text(qtbot, editor, "X2.9")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    message = window.editor.inline_message
    assert message.isVisible()
    assert message.text() == "'X2.9': bit number must be 0 to 7"
    assert editor.isVisible()
    assert window.editor.networks[0].cells[(0, 0)] == Contact()
    editor.clear()
    type_text(qtbot, editor, "X2.1")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    assert not editor.isVisible()
    assert window.editor.networks[0].cells[(0, 0)] == Contact(parse_address("X2.1"))


def test_address_refusal_is_in_turkish_when_the_ui_is(drawer: Drawer, window: MainWindow,
                                                      qtbot: QtBot) -> None:
    window.set_language("tr")
    drawer.key("O")
    drawer.click(0, 0, 10)
    type_text(qtbot, window.editor.inline_editor, "Q1.0")
    qtbot.keyClick(window.editor.inline_editor, Qt.Key.Key_Return)
    assert "bilinmeyen alan 'Q'" in window.editor.inline_message.text()


def test_function_table_refuses_a_wrong_parameter(drawer: Drawer, window: MainWindow,
                                                  qtbot: QtBot) -> None:
    window.tool_palette.set_function("TMRB")
    assert window.current_tool() is Tool.FUNCTION
    drawer.click(0, 0, 2)
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    qtbot.waitUntil(dialog.isVisible)
    assert [dialog.table.item(r, 0).text() for r in range(2)] == ["Timer number", "Preset"]
    assert dialog.table.item(0, 2).text() == "1 to 100"
    dialog.set_value("timer", "101")
    dialog.set_value("preset", "500")
    dialog.buttons.button(dialog.buttons.StandardButton.Ok).click()
    assert dialog.isVisible()
    assert dialog.warning.text() == "TMRB: parameter 1 (Timer number) must be 1 to 100, found 101"
    assert dialog.table.currentRow() == 0
    assert window.editor.networks[0].cells == {}
    dialog.set_value("timer", "7")
    with qtbot.waitSignal(dialog.accepted):
        dialog.buttons.button(dialog.buttons.StandardButton.Ok).click()
    box = window.editor.networks[0].cells[(0, 8)]  # right-aligned: W1 at the coil column
    assert isinstance(box, FunctionBox) and box.name == "TMRB" and box.params == (7, 500)


def test_not_or_and_delete_tools(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    net = window.editor.networks[0]
    drawer.key("T")
    drawer.click(0, 0, 0)
    assert net.cells[(0, 0)] == Contact(parse_address("X1.0"), negated=True)
    drawer.key("R")
    drawer.click(0, 0, 0)
    drawer.type_inline("X1.1")
    assert net.cells[(1, 0)] == Contact(parse_address("X1.1"))
    assert {(0, 0), (0, 1)} <= net.links
    drawer.key("D")
    drawer.click(0, 1, 0)
    assert (1, 0) not in net.cells
    window.editor.undo_stack.undo()
    assert (1, 0) in net.cells


def test_keyboard_moves_edits_and_deletes(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    view = window.editor
    view.setFocus()
    view.move_cursor(0, 0, 0)
    qtbot.keyClick(view, Qt.Key.Key_Right)
    qtbot.keyClick(view, Qt.Key.Key_Down)
    assert view.cursor_cell == (0, 1, 1)
    assert "R1.6" in window.cell_label.text()
    qtbot.keyClick(view, Qt.Key.Key_Return)
    qtbot.waitUntil(view.inline_editor.isVisible)
    assert view.inline_editor.text() == "R1.6"
    view.inline_editor.clear()
    type_text(qtbot, view.inline_editor, "R1.5 // yeni")
    qtbot.keyClick(view.inline_editor, Qt.Key.Key_Return)
    element = view.networks[0].cells[(1, 1)]
    assert isinstance(element, Contact)
    assert (str(element.address), element.comment, element.negated) == ("R1.5", "yeni", True)
    qtbot.keyClick(view, Qt.Key.Key_Delete)
    assert (1, 1) not in view.networks[0].cells
    qtbot.keyClick(view, "l")
    assert window.current_tool() is Tool.LINE
    qtbot.keyClick(view, Qt.Key.Key_Escape)
    assert window.current_tool() is Tool.SELECT


def test_status_bar_shows_signal_names(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_single.LAD")
    view = window.editor
    qtbot.mouseMove(view.viewport(), view.cell_point(0, 0, 1))
    qtbot.waitUntil(lambda: "F2.5" in window.cell_label.text())
    assert "OPSTP" in window.cell_label.text()
    assert "İSTEĞE BAĞLI DURMA" in window.cell_label.text()


def test_right_click_menu_offers_the_edit_actions(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    view = window.editor
    point = view.cell_point(0, 0, 0)
    menus: list[list[str]] = []

    def close_popups() -> None:
        # The right-click may open the menu itself (platform-dependent), and the explicit
        # event opens it again: close every popup that appears, whichever way it came.
        menu = QApplication.activePopupWidget()
        if isinstance(menu, QMenu):
            menus.append([a.objectName() for a in menu.actions() if a.objectName()])
            menu.close()

    closer = QTimer()
    closer.timeout.connect(close_popups)
    closer.start(10)
    try:
        qtbot.mouseClick(view.viewport(), Qt.MouseButton.RightButton, pos=point)
        view.contextMenuEvent(_context_event(view, point))
    finally:
        closer.stop()
    assert QApplication.activePopupWidget() is None
    assert menus
    seen = menus[-1]
    assert seen[:4] == ["action_cut", "action_copy", "action_paste", "action_delete"]
    assert {"action_invert", "action_or", "action_insert_row_before",
            "action_insert_row_after"} <= set(seen)
    assert view.selection is not None and view.selection[0] == 0


def _context_event(view: object, point: QPoint) -> object:
    from PySide6.QtGui import QContextMenuEvent

    viewport = view.viewport()  # type: ignore[attr-defined]
    return QContextMenuEvent(QContextMenuEvent.Reason.Mouse, point, viewport.mapToGlobal(point))


def test_copy_paste_and_insert_rows(window: MainWindow) -> None:
    window.load(EXAMPLES / "rising_edge.LAD")
    view = window.editor
    view.move_cursor(0, 0, 0)
    window.actions_by_name["action_copy"].trigger()
    view.move_cursor(1, 0, 2)
    window.actions_by_name["action_insert_row_after"].trigger()
    assert view.networks[1].rows == 2
    view.move_cursor(1, 1, 2)
    window.actions_by_name["action_paste"].trigger()
    assert view.networks[1].cells[(1, 2)] == view.networks[0].cells[(0, 0)]
    window.actions_by_name["action_delete_network"].trigger()
    assert len(view.networks) == 2
    window.actions_by_name["action_undo"].trigger()
    assert len(view.networks) == 3


def test_zoom(window: MainWindow) -> None:
    view = window.editor
    window.actions_by_name["action_zoom_in"].trigger()
    assert view.zoom() > 1.0
    assert view.transform().m11() == view.zoom()
    window.actions_by_name["action_zoom_reset"].trigger()
    window.actions_by_name["action_zoom_out"].trigger()
    assert view.zoom() < 1.0


def test_a_coil_clicked_in_a_contact_column_goes_to_the_output_column_wired(
        drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    item = window.editor.network_items[0]
    assert [mark.cell for mark in item.open_ends] == [(0, 1)]  # marked while drawing
    drawer.element(0, 0, 3, "O", "Y1.0")  # the address editor opens on the coil's new cell
    net = window.editor.networks[0]
    assert net.cells[(0, net.coil_column)] == Coil(parse_address("Y1.0"))
    assert all(isinstance(net.cells[(0, c)], Wire) for c in range(1, net.coil_column))
    assert item.open_ends == []
    assert window.check() == []
    program, diagnostics = window.editor.program()
    assert diagnostics == [] and program is not None
    assert [str(i.operand) for i in program.instructions()] == ["X1.0", "Y1.0"]


def test_an_open_circuit_is_marked_at_the_cell_as_the_user_draws(
        drawer: Drawer, window: MainWindow, qtbot: QtBot) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    drawer.element(0, 0, 1, "I", "X1.1")
    drawer.element(0, 0, 9, "O", "Y1.0")
    view = window.editor
    assert view.network_items[0].open_ends == []
    drawer.key("D")
    drawer.click(0, 0, 1)  # deleting the middle contact breaks the rung there
    item = view.network_items[0]
    assert [(m.cell, m.gap) for m in item.open_ends] == [((0, 1), True)]
    image = view.viewport().grab().toImage()
    centre = view.mapFromScene(view.cell_rect(0, 0, 1).center())
    reds = sum(1 for dx in range(-30, 31) for dy in range(-40, 41)
               if _is_red(image.pixelColor(centre.x() + dx, centre.y() + dy)))
    assert reds > 20  # the red gap is painted on that cell
    view.move_cursor(0, 0, 1)
    assert "open circuit here" in window.cell_label.text()
    view.move_cursor(0, 0, 0)
    assert "open circuit" not in window.cell_label.text()
    view.undo_stack.undo()
    assert view.network_items[0].open_ends == []


def _is_red(colour: QColor) -> bool:
    return colour.red() > 180 and colour.green() < 90 and colour.blue() < 90


def test_the_or_tool_then_a_contact_lengthens_the_branch(drawer: Drawer,
                                                         window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    drawer.element(0, 0, 5, "O", "Y1.0")
    drawer.key("R")
    drawer.click(0, 0, 0)
    drawer.type_inline("X1.1")
    drawer.element(0, 1, 1, "I", "X1.2")
    net = window.editor.networks[0]
    assert (0, 0) in net.links and (0, 2) in net.links and (0, 1) not in net.links
    assert window.check() == []
    assert window.editor.network_items[0].open_ends == []


def test_drag_selects_a_rectangle_that_copies_and_pastes_whole(window: MainWindow,
                                                               qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")  # rows 0 and 1: two contacts each, then OR
    view = window.editor
    source = view.networks[0]
    start = view.cell_point(0, 0, 0)
    end = view.cell_point(0, 1, 1)
    qtbot.mousePress(view.viewport(), Qt.MouseButton.LeftButton, pos=start)
    qtbot.mouseMove(view.viewport(), view.cell_point(0, 1, 0))
    qtbot.mouseMove(view.viewport(), end)
    qtbot.mouseRelease(view.viewport(), Qt.MouseButton.LeftButton, pos=end)
    assert view.selection is not None
    index, sel = view.selection
    assert (index, sel.top, sel.left, sel.bottom, sel.right) == (0, 0, 0, 1, 1)
    window.actions_by_name["action_copy"].trigger()
    # paste into the empty network at the end: the four contacts arrive together
    last = len(view.networks) - 1
    view.selection = None
    view.move_cursor(last, 0, 0)
    window.actions_by_name["action_paste"].trigger()
    pasted = view.networks[last].cells
    for cell in ((0, 0), (0, 1), (1, 0), (1, 1)):
        assert pasted[cell] == source.cells[cell]


def test_shift_arrows_extend_the_selection(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    view = window.editor
    view.setFocus()
    view.move_cursor(0, 0, 0)
    for key in (Qt.Key.Key_Right, Qt.Key.Key_Down):
        qtbot.keyClick(view, key, Qt.KeyboardModifier.ShiftModifier)
    assert view.selection is not None
    _, sel = view.selection
    assert (sel.top, sel.left, sel.bottom, sel.right) == (0, 0, 1, 1)
    window.actions_by_name["action_delete"].trigger()
    assert not any(cell in view.networks[0].cells for cell in ((0, 0), (0, 1), (1, 0), (1, 1)))
    window.actions_by_name["action_undo"].trigger()
    assert (1, 1) in view.networks[0].cells
