"""The console's ladder editor: the grid (`GridView`) with the tools, the keys and in-place
editing; the mouse goes to the current tool's interaction, edits to `LadderEdits`."""

from __future__ import annotations

from PySide6.QtCore import QPoint, Qt, Signal
from PySide6.QtGui import QAction, QContextMenuEvent, QKeyEvent, QMouseEvent
from PySide6.QtWidgets import QMenu, QWidget

from ladderworks.gui.editor.geometry import SPARE_ROWS, Hit, NameDisplay, name_display
from ladderworks.gui.editor.grid_view import GridView
from ladderworks.gui.editor.inline_edit import InlineEdit
from ladderworks.gui.editor.interactions import BY_KEY, BY_TOOL, Interaction, SelectInteraction
from ladderworks.gui.editor.keyboard import GridKeys
from ladderworks.gui.editor.ladder_edits import LadderEdits
from ladderworks.gui.editor.ladder_model import LadderModel
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.tools import Tool


class LadderEditor(Retranslating, GridView):
    """The ladder console's drawing area over a `LadderModel`: every edit is an undo command
    made by its `edits` (`LadderEdits`), and the grid redraws what the model announces."""

    tool_requested = Signal(object)  # Tool picked with a letter key

    def __init__(self, model: LadderModel, parent: QWidget | None = None) -> None:
        super().__init__(model, parent)
        self.context_actions: list[QAction | None] = []
        self.edits = LadderEdits(self, self.open_address_editor)
        self.inline = InlineEdit(self, self.edits)
        self.inline_editor = self.inline.line_edit
        self.inline_message = self.inline.message
        self.interaction: Interaction = SelectInteraction(self, self.edits, self.inline)
        self.keys = GridKeys(self)  # Home/End, PageUp/PageDown, the menu key
        model.document_reset.connect(self._end_in_place)
        self.zoom_changed.connect(self.inline.close)

    def _end_in_place(self) -> None:
        """Another program: no address typed, no half-done tool use."""
        self.inline.close()
        self.interaction.cancel()

    @property
    def tool(self) -> Tool:
        """The current tool."""
        return self.interaction.tool

    def set_tool(self, tool: Tool) -> None:
        """Make `tool` current: its interaction gets the mouse from now on."""
        self.interaction.end()
        self.interaction = BY_TOOL[tool](self, self.edits, self.inline)
        self.viewport().setCursor(self.interaction.cursor)

    def set_function(self, name: str) -> None:
        """The functional instruction the function tool places."""
        self.edits.function_name = name

    def open_address_editor(self, index: int, row: int, col: int, placed: bool = False) -> None:
        """Edit the address (and `// comment`) of the contact or coil at a cell; `placed`: the
        element was just placed (ESC takes it away again)."""
        self.inline.open_address(index, row, col, placed)

    def edit_at_cursor(self) -> None:
        """ENTER: edit the element at the cursor (address, function table; a comment line with
        the comment tool)."""
        self.interaction.edit_at_cursor()

    # -- events -------------------------------------------------------------------------------

    def mousePressEvent(self, event: QMouseEvent) -> None:
        """Click: move the cursor there and hand the click to the current tool."""
        if self.inline.target is not None:
            self.inline.close()
        hit = self._hit(event.position().toPoint())
        if event.button() == Qt.MouseButton.LeftButton:
            self.setFocus()
            self.cursor_cell = (hit.network, hit.row, hit.col)
            self.keys.anchor = None  # a click ends a Shift+arrows selection
            self.interaction.mouse_press(event, hit)
            index = min(self.cursor_cell[0], len(self.networks) - 1)
            net = self.networks[index]
            self.cursor_cell = (
                index,
                min(self.cursor_cell[1], net.rows - 1 + SPARE_ROWS),
                min(self.cursor_cell[2], net.columns),
            )
            self.place_overlays()
            event.accept()
            return
        if event.button() == Qt.MouseButton.RightButton:
            net = self.networks[hit.network]
            self.cursor_cell = (hit.network, min(hit.row, max(net.rows - 1, 0)), hit.col)
            self.select_element(*self.cursor_cell)
            event.accept()
            return
        super().mousePressEvent(event)

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        """Report the cell under the mouse; the tool may follow it (a drag selects)."""
        hit = self._hit(event.position().toPoint())
        self.interaction.mouse_move(event, hit)
        if hit.comment_line is None:
            net = self.networks[hit.network]
            if hit.row < net.rows:
                self.hover_changed.emit(self.describe_cell(hit.network, hit.row, hit.col))
                self.viewport().setToolTip(self.tooltip_at(hit.network, hit.row, hit.col))
        super().mouseMoveEvent(event)

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        """The tool's release (a drag selection ends)."""
        self.interaction.mouse_release(event, self._hit(event.position().toPoint()))
        super().mouseReleaseEvent(event)

    def mouseDoubleClickEvent(self, event: QMouseEvent) -> None:
        """The tool's double click (select: edit the element); else a second click."""
        if self.interaction.mouse_double_click(event, self._hit(event.position().toPoint())):
            event.accept()
            return
        self.mousePressEvent(event)

    def contextMenuEvent(self, event: QContextMenuEvent) -> None:
        """Right-click menu: cut, copy, paste, delete, NOT, OR, insert row."""
        menu = QMenu(self)
        menu.setObjectName("ladder_context_menu")
        for action in self.context_actions:
            if action is None:
                menu.addSeparator()
            else:
                menu.addAction(action)
        where = event.globalPos()
        if event.reason() == QContextMenuEvent.Reason.Keyboard:  # Shift+F10, the menu key
            where = self.viewport().mapToGlobal(self.cell_point(*self.cursor_cell))
        self.show_menu(menu, where)

    def show_menu(self, menu: QMenu, where: QPoint) -> None:
        """Show a menu at `where` (global) until it closes."""
        menu.exec(where)

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Arrows move, letters pick tools, ENTER edits, SPACE uses the tool, DEL deletes."""
        key = event.key()
        index, row, col = self.cursor_cell
        if self.keys.handle(event):  # arrows, Shift+arrows, Home/End, pages, the menu key
            return
        if key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.edit_at_cursor()
            return
        if key == Qt.Key.Key_Space:
            node = col
            self.interaction.apply(Hit(index, row, col, node))
            return
        if key in (Qt.Key.Key_Delete, Qt.Key.Key_Backspace):
            self.edits.delete_at_cursor()
            return
        if key == Qt.Key.Key_Escape:
            self.interaction.cancel()
            self.selection = None
            self.place_overlays()
            self.tool_requested.emit(Tool.SELECT)
            return
        text = event.text().upper()
        if text in BY_KEY and not event.modifiers() & (
            Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.AltModifier
        ):
            self.tool_requested.emit(BY_KEY[text].tool)
            return
        super().keyPressEvent(event)

    def retranslate(self) -> None:
        """Repaint the signal descriptions in the new language (which networks have a comment
        to show may change with it: lay out again when comments are shown)."""
        if name_display() is NameDisplay.COMMENT:
            self.relayout()
        self.viewport().update()



__all__ = ["LadderEditor"]
