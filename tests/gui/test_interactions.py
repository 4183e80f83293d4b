"""One interaction per tool: the palette and menus come from them; the view forwards the mouse."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QMouseEvent
from pytestqt.qtbot import QtBot

from ladderworks.gui.editor.geometry import Hit
from ladderworks.gui.editor.interactions import (
    BY_KEY,
    INTERACTIONS,
    Interaction,
    LineInteraction,
)
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.tools import Tool
from ladderworks.paths import icons_dir
from tests.gui.conftest import Drawer


def test_every_tool_has_one_interaction_with_its_own_key_and_icon() -> None:
    assert [cls.tool for cls in INTERACTIONS] == list(Tool)
    assert len(BY_KEY) == len(INTERACTIONS)
    assert all(len(cls.key) == 1 and cls.key.isupper() for cls in INTERACTIONS)
    assert all((icons_dir() / f"{cls.icon_name}.svg").is_file() for cls in INTERACTIONS)


def test_palette_and_tools_menu_are_built_from_the_interactions(window: MainWindow) -> None:
    names = [f"tool_{cls.tool.value}" for cls in INTERACTIONS]
    assert [button.defaultAction().objectName() for button in window.tool_palette.buttons] == names
    menu = window.menus.menus["menu_tools"]  # the tools, then the cross reference
    assert [a.objectName() for a in menu.actions() if not a.isSeparator()] == [
        *names, "action_cross_reference"]
    for cls in INTERACTIONS:
        action = window.tool_actions[cls.tool]
        assert action.text() == f"{cls.name()}\t{cls.key}" and action.statusTip() == cls.help()
        assert action.iconText() == cls.name()
    window.set_language("tr")
    assert window.tool_actions[Tool.SELECT].iconText() == "SEÇİM"


def test_each_tool_sets_its_cursor(window: MainWindow) -> None:
    shapes = {}
    for tool in (Tool.SELECT, Tool.INPUT, Tool.DELETE, Tool.ROW_AFTER):
        window.set_tool(tool)
        shapes[tool] = window.editor.viewport().cursor().shape()
    assert shapes == {Tool.SELECT: Qt.CursorShape.ArrowCursor,
                      Tool.INPUT: Qt.CursorShape.CrossCursor,
                      Tool.DELETE: Qt.CursorShape.PointingHandCursor,
                      Tool.ROW_AFTER: Qt.CursorShape.PointingHandCursor}


def test_escape_forgets_the_lines_first_point_and_picks_select(drawer: Drawer,
                                                               window: MainWindow) -> None:
    drawer.key("L")
    drawer.click_node(0, 0, 0)
    line = window.editor.interaction
    assert isinstance(line, LineInteraction) and line.start == (0, 0, 0)
    marker = line.marker
    assert marker.isVisible() and marker.scene() is window.editor.scene()
    drawer.key(Qt.Key.Key_Escape)
    assert line.start is None and window.current_tool() is Tool.SELECT
    assert marker.scene() is None  # the line tool's marker left with it
    drawer.line(0, (0, 0), (0, 3))  # a fresh first point, then the second: a wire
    assert window.model.networks[0].cells


class Recording(Interaction):
    """A tool that records what the view hands it."""

    tool = Tool.SELECT
    icon_name = "select"
    key = "S"

    def __init__(self, editor: LadderEditor, seen: list[tuple[str, int, int]]) -> None:
        super().__init__(editor, editor.edits, editor.inline)
        self.seen = seen

    def apply(self, hit: Hit) -> None:
        self.seen.append(("apply", hit.row, hit.col))

    def mouse_move(self, event: QMouseEvent, hit: Hit) -> bool:
        if event.buttons() & Qt.MouseButton.LeftButton:
            self.seen.append(("move", hit.row, hit.col))
        return True

    def mouse_release(self, event: QMouseEvent, hit: Hit) -> bool:
        self.seen.append(("release", hit.row, hit.col))
        return True

    def mouse_double_click(self, event: QMouseEvent, hit: Hit) -> bool:
        self.seen.append(("double", hit.row, hit.col))
        return True


def test_the_view_forwards_the_mouse_to_the_current_interaction(window: MainWindow,
                                                                qtbot: QtBot) -> None:
    view = window.editor
    seen: list[tuple[str, int, int]] = []
    view.interaction = Recording(view, seen)
    start, end = view.cell_point(0, 0, 1), view.cell_point(0, 0, 3)
    qtbot.mousePress(view.viewport(), Qt.MouseButton.LeftButton, pos=start)
    qtbot.mouseMove(view.viewport(), end)
    qtbot.mouseRelease(view.viewport(), Qt.MouseButton.LeftButton, pos=end)
    qtbot.mouseDClick(view.viewport(), Qt.MouseButton.LeftButton, pos=end)
    assert seen == [("apply", 0, 1), ("move", 0, 3), ("release", 0, 3), ("double", 0, 3)]
    assert view.cursor_cell == (0, 0, 1)  # the press put the cursor there
    qtbot.keyClick(view, Qt.Key.Key_Space)  # SPACE uses the tool at the cursor
    assert seen[-1] == ("apply", 0, 1)
