"""Keyboard-first (issue 18 item 3): a network from an empty file by keys alone, the grid's
Home/End/Page keys, Ctrl+Y, the menu key's context menu at the cursor, Tab without a trap."""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QApplication, QMenu
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Coil, Contact
from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.tools import Tool
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import type_text

CTRL = Qt.KeyboardModifier.ControlModifier


def _focused_grid(window: MainWindow, qtbot: QtBot) -> None:
    window.activateWindow()
    window.editor.setFocus()
    qtbot.waitUntil(window.editor.hasFocus)


def test_a_network_is_built_from_an_empty_file_with_the_keyboard_alone(
        window: MainWindow, qtbot: QtBot, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "keys.LAD"
    monkeypatch.setattr(file_dialogs, "save_file_name", lambda *_a, **_k: str(target))
    view = window.editor
    _focused_grid(window, qtbot)
    assert view.cursor_cell == (0, 0, 0)

    def key(k: Qt.Key | str, modifier: Qt.KeyboardModifier = Qt.KeyboardModifier.NoModifier
            ) -> None:
        widget = QApplication.focusWidget()
        assert widget is not None
        qtbot.keyClick(widget, k, modifier)

    def address(text: str) -> None:
        qtbot.waitUntil(view.inline_editor.hasFocus)
        type_text(qtbot, view.inline_editor, text)
        key(Qt.Key.Key_Return)
        assert view.hasFocus()  # back in the grid, not in the palette

    key("i")                   # the input tool
    key(Qt.Key.Key_Space)      # a contact at the cursor
    address("X1.0")
    key(Qt.Key.Key_Right)
    key("l")                   # a wire from node 1 ...
    key(Qt.Key.Key_Space)
    key(Qt.Key.Key_End)        # ... to the coil column's node
    key(Qt.Key.Key_Space)
    key("o")                   # the output tool at the coil column
    key(Qt.Key.Key_Space)
    address("Y1.0")
    key("s", CTRL)             # Save: the dialog answers with the file name
    qtbot.waitUntil(target.exists)
    text = target.read_text()
    lines = [line.split("//")[0].split() for line in text.splitlines()]
    assert ["RD", "X1.0"] in lines and ["WRT", "Y1.0"] in lines
    net = view.networks[0]
    assert net.cells[(0, 0)] == Contact(parse_address("X1.0"))
    assert net.cells[(0, net.columns)] == Coil(parse_address("Y1.0"))
    assert not window.is_modified()
    assert not [d for d in window.check() if d.is_error]  # wired: it checks without errors


def test_focus_stays_in_the_grid_after_an_address(window: MainWindow, qtbot: QtBot) -> None:
    view = window.editor
    _focused_grid(window, qtbot)
    qtbot.keyClick(view, "i")
    qtbot.keyClick(view, Qt.Key.Key_Space)
    qtbot.waitUntil(view.inline_editor.hasFocus)
    type_text(qtbot, view.inline_editor, "X2.1")
    qtbot.keyClick(view.inline_editor, Qt.Key.Key_Return)
    assert QApplication.focusWidget() is view
    qtbot.keyClick(view, Qt.Key.Key_Space)  # SPACE in the grid: the tool again, not SELECT
    assert window.current_tool() is Tool.INPUT


def test_ctrl_y_and_ctrl_shift_z_redo(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    view = window.editor
    _focused_grid(window, qtbot)
    view.move_cursor(0, 0, 0)
    before = view.networks[0].cells[(0, 0)]
    qtbot.keyClick(view, Qt.Key.Key_Delete)
    assert (0, 0) not in view.networks[0].cells
    qtbot.keyClick(view, "z", CTRL)
    assert view.networks[0].cells[(0, 0)] == before
    qtbot.keyClick(view, "y", CTRL)
    assert (0, 0) not in view.networks[0].cells
    qtbot.keyClick(view, "z", CTRL)
    qtbot.keyClick(view, "z", CTRL | Qt.KeyboardModifier.ShiftModifier)
    assert (0, 0) not in view.networks[0].cells
    shortcuts = [k.toString() for k in window.actions_by_name["action_redo"].shortcuts()]
    assert shortcuts[:2] == ["Ctrl+Y", "Ctrl+Shift+Z"]


def test_home_end_and_page_keys_move_the_cursor(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "rising_edge.LAD")
    view = window.editor
    _focused_grid(window, qtbot)
    view.move_cursor(1, 0, 3)
    qtbot.keyClick(view, Qt.Key.Key_End)
    assert view.cursor_cell == (1, 0, view.networks[1].columns)
    qtbot.keyClick(view, Qt.Key.Key_Home)
    assert view.cursor_cell == (1, 0, 0)
    qtbot.keyClick(view, Qt.Key.Key_End, CTRL)
    assert view.cursor_cell == (len(view.networks) - 1, 0, 0)
    qtbot.keyClick(view, Qt.Key.Key_Home, CTRL)
    assert view.cursor_cell == (0, 0, 0)
    qtbot.keyClick(view, Qt.Key.Key_PageDown)
    assert view.cursor_cell[0] > 0  # a page further down: a later network
    qtbot.keyClick(view, Qt.Key.Key_PageUp)
    assert view.cursor_cell == (0, 0, 0)


def test_page_down_walks_a_long_program_a_page_at_a_time(window: MainWindow,
                                                         qtbot: QtBot) -> None:
    window.resize(1024, 600)
    for _ in range(40):
        window.model.networks.insert(0, window.model.networks[-1].copy())
    window.model.set_document(window.model.ladder_document())  # 40 empty networks + the end
    view = window.editor
    _focused_grid(window, qtbot)
    view.move_cursor(0, 0, 2)
    seen = [view.cursor_cell[0]]
    for _ in range(3):
        qtbot.keyClick(view, Qt.Key.Key_PageDown)
        seen.append(view.cursor_cell[0])
    steps = [b - a for a, b in pairwise(seen)]
    assert all(step > 1 for step in steps), seen  # more than one network per page
    assert view.cursor_cell[2] == 2  # the column is kept
    scene = view.cell_rect(*view.cursor_cell)
    assert view.viewport().rect().intersects(view.mapFromScene(scene).boundingRect())


def _menu_position(window: MainWindow, qtbot: QtBot, press: object,
                   monkeypatch: pytest.MonkeyPatch) -> tuple[QPoint, list[str]]:
    """Run `press`; where the menu it opens was asked to show, and its actions (the menu is
    not shown: Qt may move a shown menu to fit the screen, which depends on the window's
    place)."""
    seen: list[tuple[QPoint, list[str]]] = []

    def record(menu: QMenu, where: QPoint) -> None:
        seen.append((QPoint(where), [a.objectName() for a in menu.actions()]))

    monkeypatch.setattr(window.editor, "show_menu", record)
    press()  # type: ignore[operator]
    assert seen, "no context menu opened"
    return seen[-1]


@pytest.mark.parametrize("key", ["menu", "shift_f10"])
def test_menu_key_opens_the_context_menu_at_the_cursor_cell(
        window: MainWindow, qtbot: QtBot, key: str, monkeypatch: pytest.MonkeyPatch) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    view = window.editor
    _focused_grid(window, qtbot)
    view.move_cursor(0, 1, 1)
    if key == "menu":
        def press() -> None:
            qtbot.keyClick(view, Qt.Key.Key_Menu)
    else:
        def press() -> None:
            qtbot.keyClick(view, Qt.Key.Key_F10, Qt.KeyboardModifier.ShiftModifier)
    where, names = _menu_position(window, qtbot, press, monkeypatch)
    cell = view.viewport().mapToGlobal(view.mapFromScene(view.cell_rect(0, 1, 1).center()))
    assert (where - cell).manhattanLength() <= 2, (where, cell)
    assert "action_cut" in names and "action_invert" in names
    corner = view.viewport().mapToGlobal(QPoint(0, 0))
    assert (where - corner).manhattanLength() > 50  # not the view's corner


def test_tab_leaves_the_signal_table(window: MainWindow, qtbot: QtBot) -> None:
    window.signals_dock.show()
    window.signals_dock.raise_()
    table = window.signals_dock.table
    qtbot.waitUntil(lambda: table.isVisible() and table.rowCount() > 0)
    table.setFocus()
    qtbot.waitUntil(table.hasFocus)
    qtbot.keyClick(table, Qt.Key.Key_Tab)
    assert not table.hasFocus()
    visited = set()
    for _ in range(40):  # Tab goes round the window and comes back to the grid
        widget = QApplication.focusWidget()
        assert widget is not None
        if widget is window.editor:
            break
        visited.add(widget.objectName())
        qtbot.keyClick(widget, Qt.Key.Key_Tab)
    assert QApplication.focusWidget() is window.editor, visited
    window.tool_palette.raise_()
    qtbot.waitUntil(window.tool_palette.functions.isVisible)
    qtbot.keyClick(window.editor, Qt.Key.Key_Tab)  # no fifteen tool-button stops first
    assert QApplication.focusWidget() is window.tool_palette.functions


def test_tool_keys_are_shown_in_the_menu_and_tooltips(window: MainWindow) -> None:
    action = window.tool_actions[Tool.OUTPUT]
    assert action.text() == "Output\tO"
    assert action.toolTip().startswith("Output (O): ")
    assert window.tool_palette.buttons[list(Tool).index(Tool.OUTPUT)].text() == "Output"


def test_ctrl_end_reaches_the_end_of_a_program_still_loading(window: MainWindow, qtbot: QtBot,
                                                             tmp_path: Path) -> None:
    from benchmarks.large_program import large_program_text

    source = tmp_path / "large.LAD"
    source.write_text(large_program_text(1200))
    window.load(source)
    view = window.editor
    assert view.loading  # the rest is laid out in the background
    _focused_grid(window, qtbot)
    qtbot.keyClick(view, Qt.Key.Key_End, CTRL)
    assert not view.loading
    assert view.cursor_cell == (1200, 0, 0)  # the empty network after the 1,200
    assert view.networks[1200].is_empty()
    qtbot.keyClick(view, Qt.Key.Key_PageUp)
    assert view.cursor_cell[0] < 1200
