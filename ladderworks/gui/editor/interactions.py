"""One interaction class per tool: icon, key, name, help, cursor and its mouse handling."""

# The view forwards the grid's mouse events to the current interaction, as orange-canvas-core's
# scene forwards its events to the current `UserInteraction`.

from __future__ import annotations

from typing import ClassVar

from PySide6.QtCore import QCoreApplication, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QIcon, QMouseEvent, QPen
from PySide6.QtWidgets import QGraphicsRectItem

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.core.instructions import Write
from ladderworks.core.ladder import Coil, Contact, FunctionBox
from ladderworks.gui.editor.geometry import Hit, node_point
from ladderworks.gui.editor.grid_view import GridView
from ladderworks.gui.editor.inline_edit import InlineEdit
from ladderworks.gui.editor.ladder_edits import LadderEdits
from ladderworks.gui.tools import Tool, icon

translate = QCoreApplication.translate


class Interaction:
    """A tool of the palette; by default a left click (or SPACE at the cursor) applies it.

    It works on the grid (`editor`) through the editing operations (`edits`) and the in-place
    editor (`inline`)."""

    tool: ClassVar[Tool]
    icon_name: ClassVar[str]
    key: ClassVar[str]  # the letter that picks the tool in the grid
    cursor: ClassVar[Qt.CursorShape] = Qt.CursorShape.CrossCursor

    def __init__(self, editor: GridView, edits: LadderEdits, inline: InlineEdit) -> None:
        self.editor = editor
        self.edits = edits
        self.inline = inline

    title: ClassVar[str]  # marked for translation in the "Tool" context
    hint: ClassVar[str]

    @classmethod
    def name(cls) -> str:
        """The tool's name in the current UI language (the manual's words in Turkish)."""
        return QCoreApplication.translate("Tool", cls.title)

    @classmethod
    def help(cls) -> str:
        """One sentence on how the tool is used (status tip and tooltip)."""
        return QCoreApplication.translate("Tool", cls.hint)

    @classmethod
    def icon(cls) -> QIcon:
        """The palette icon."""
        return icon(cls.icon_name)

    def apply(self, hit: Hit) -> None:
        """Do what the tool does at a cell (a click, or SPACE at the cursor)."""
        raise NotImplementedError

    def cancel(self) -> None:
        """Forget a half-done use (ESC, or another tool chosen)."""

    def end(self) -> None:
        """Another tool takes over: take away what this one put on the scene."""
        self.cancel()

    def edit_at_cursor(self) -> None:
        """ENTER (Edit › Edit element): edit the element at the cursor, its address or its
        function table."""
        index, row, col = self.editor.cursor_cell
        found = self.editor.networks[index].element_at(row, col)
        if found is None:
            return
        (r, c), element = found
        if isinstance(element, Contact) and element.function:  # an edge/comparison contact
            self.edits.open_contact_dialog(index, r, c, element.function, element)
        elif isinstance(element, Contact | Coil):
            self.inline.open_address(index, r, c)
        elif isinstance(element, FunctionBox):
            self.edits.open_function_dialog(index, r, c, element.name, element)

    def mouse_press(self, event: QMouseEvent, hit: Hit) -> bool:
        """A left click on the grid (the cursor is already there); True when handled."""
        self.apply(hit)
        return True

    def mouse_move(self, event: QMouseEvent, hit: Hit) -> bool:
        """The mouse moved over the grid; True when handled."""
        return False

    def mouse_release(self, event: QMouseEvent, hit: Hit) -> bool:
        """The button was released; True when handled."""
        return False

    def mouse_double_click(self, event: QMouseEvent, hit: Hit) -> bool:
        """A double click; False lets the view take it as another click."""
        return False


class SelectInteraction(Interaction):
    """Select an element, drag over cells for a rectangle, double-click to edit."""

    tool = Tool.SELECT
    icon_name = "select"
    key = "S"
    cursor = Qt.CursorShape.ArrowCursor

    def __init__(self, editor: GridView, edits: LadderEdits, inline: InlineEdit) -> None:
        super().__init__(editor, edits, inline)
        self._drag_origin: tuple[int, int, int] | None = None  # where a drag began
    title = QT_TRANSLATE_NOOP("Tool", "Select")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Click an element or drag over cells to select; right-click: cut, copy, paste")

    def apply(self, hit: Hit) -> None:
        """Select the element at the cell (or edit the comment line clicked)."""
        if hit.comment_line is not None:
            self.inline.open_comment(hit.network, hit.comment_line)
        else:
            self.editor.select_element(hit.network, hit.row, hit.col)

    def mouse_press(self, event: QMouseEvent, hit: Hit) -> bool:
        """Select; a drag may start here."""
        self.apply(hit)
        if hit.comment_line is None:
            self._drag_origin = (hit.network, hit.row, hit.col)
        return True

    def mouse_move(self, event: QMouseEvent, hit: Hit) -> bool:
        """A drag selects the rectangle from where it began."""
        origin = self._drag_origin
        if (origin is not None and hit.network == origin[0] and hit.comment_line is None
                and (hit.row, hit.col) != origin[1:]):
            self.editor.select_rectangle(origin[0], origin[1:], (hit.row, hit.col))
        return False

    def mouse_release(self, event: QMouseEvent, hit: Hit) -> bool:
        """The drag ends."""
        self._drag_origin = None
        return False

    def mouse_double_click(self, event: QMouseEvent, hit: Hit) -> bool:
        """Edit the element (address, function table or comment)."""
        self.editor.cursor_cell = (hit.network, hit.row, hit.col)
        self.edit_at_cursor()
        return True


    def cancel(self) -> None:
        """No drag goes on."""
        self._drag_origin = None


class _PlaceBit(Interaction):
    """Place a contact or coil and open its address; on one of the same kind, change it."""

    def element(self) -> Contact | Coil:
        """The element placed."""
        raise NotImplementedError

    def apply(self, hit: Hit) -> None:
        """Place (or change) the element and type its address."""
        self.edits.place_bit(hit.network, hit.row, hit.col, self.element())


class InputInteraction(_PlaceBit):
    """A contact (RD / AND)."""

    tool = Tool.INPUT
    icon_name = "contact"
    key = "I"
    title = QT_TRANSLATE_NOOP("Tool", "Input")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Click a cell to place a contact (RD / AND), type its address, ENTER")

    def element(self) -> Contact | Coil:
        """A contact."""
        return Contact()


class InputNotInteraction(_PlaceBit):
    """A NOT contact (RD.NOT / AND.NOT)."""

    tool = Tool.INPUT_NOT
    icon_name = "contact_not"
    key = "N"
    title = QT_TRANSLATE_NOOP("Tool", "NOT input")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a cell to place a NOT contact (RD.NOT / AND.NOT)")

    def element(self) -> Contact | Coil:
        """A NOT contact."""
        return Contact(negated=True)


class OutputInteraction(_PlaceBit):
    """A coil (WRT)."""

    tool = Tool.OUTPUT
    icon_name = "coil"
    key = "O"
    title = QT_TRANSLATE_NOOP("Tool", "Output")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a cell to place a coil (WRT), type its address, ENTER")

    def element(self) -> Contact | Coil:
        """A coil."""
        return Coil()


class OutputNotInteraction(_PlaceBit):
    """A NOT coil (WRT.NOT)."""

    tool = Tool.OUTPUT_NOT
    icon_name = "coil_not"
    key = "W"
    title = QT_TRANSLATE_NOOP("Tool", "NOT output")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a cell to place a NOT coil (WRT.NOT)")

    def element(self) -> Contact | Coil:
        """A NOT coil."""
        return Coil(negated=True)


class SetCoilInteraction(_PlaceBit):
    """A SET coil."""

    tool = Tool.SET_COIL
    icon_name = "coil_set"
    key = "E"  # sEt: S is the select tool
    title = QT_TRANSLATE_NOOP("Tool", "SET coil")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Click a cell to place a SET coil (bit := 1 while the logic is 1)")

    def element(self) -> Contact | Coil:
        """A SET coil."""
        return Coil(write=Write.SET)


class ResetCoilInteraction(_PlaceBit):
    """An RST coil."""

    tool = Tool.RESET_COIL
    icon_name = "coil_reset"
    key = "U"  # Unset: R is the OR tool
    title = QT_TRANSLATE_NOOP("Tool", "RST coil")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Click a cell to place an RST coil (bit := 0 while the logic is 1)")

    def element(self) -> Contact | Coil:
        """An RST coil."""
        return Coil(write=Write.RESET)


class InvertInteraction(Interaction):
    """NOT: a contact or coil becomes its inverse."""

    tool = Tool.INVERT
    icon_name = "invert"
    key = "T"
    title = QT_TRANSLATE_NOOP("Tool", "NOT")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a contact or coil to turn it into its inverse")

    def apply(self, hit: Hit) -> None:
        """Invert the element at the cell."""
        self.edits.invert(hit.network, hit.row, hit.col)


class OrInteraction(Interaction):
    """OR: a parallel contact or coil below."""

    tool = Tool.OR
    icon_name = "or"
    key = "R"
    title = QT_TRANSLATE_NOOP("Tool", "OR")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a contact or coil to add a parallel one below it")

    def apply(self, hit: Hit) -> None:
        """Add a parallel element below the one at the cell."""
        self.edits.add_parallel(hit.network, hit.row, hit.col)


class LineInteraction(Interaction):
    """A wire between two grid nodes: the first click marks a node, the second draws."""

    tool = Tool.LINE
    icon_name = "line"
    key = "L"
    title = QT_TRANSLATE_NOOP("Tool", "Line")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Click a first point, then a second point: a horizontal or vertical wire")

    def __init__(self, editor: GridView, edits: LadderEdits, inline: InlineEdit) -> None:
        super().__init__(editor, edits, inline)
        self.start: tuple[int, int, int] | None = None  # network, row, node
        self.marker = QGraphicsRectItem()
        self.marker.setPen(QPen(QColor("#2e7d32"), 2))
        self.marker.setBrush(QBrush(QColor("#2e7d32")))
        self.marker.setZValue(11)
        self.marker.hide()
        editor.scene().addItem(self.marker)

    def apply(self, hit: Hit) -> None:
        """First point: mark it; second point (same network): draw the wire."""
        index, row, node = hit.network, hit.row, hit.node
        if self.start is None or self.start[0] != index:
            self.start = (index, row, node)
            x, y = node_point(self.editor.networks[index], row, node,
                              self.editor.layout_.rows[index])
            top = self.editor.layout_.tops[index]
            self.marker.setRect(QRectF(x - 4, top + y - 4, 8, 8))
            self.marker.show()
            self.editor.message.emit(translate("LadderEditor", "Line: click the second point"))
            return
        _, row1, node1 = self.start
        self.cancel()
        if (row1, node1) == (row, node):
            return
        self.edits.draw_line(index, (row1, node1), (row, node))

    def cancel(self) -> None:
        """Forget the first point."""
        self.start = None
        self.marker.hide()

    def end(self) -> None:
        """The marker leaves the scene."""
        self.cancel()
        self.editor.scene().removeItem(self.marker)


class CommentInteraction(Interaction):
    """A network comment line, typed in place."""

    tool = Tool.COMMENT
    icon_name = "comment"
    key = "C"
    title = QT_TRANSLATE_NOOP("Tool", "Comment")
    hint = QT_TRANSLATE_NOOP("Tool", "Click the start of an empty row, type the comment, ENTER")

    def apply(self, hit: Hit) -> None:
        """Edit the comment line clicked, or add one (from an empty row)."""
        editor = self.editor
        if hit.comment_line is not None:
            self.inline.open_comment(hit.network, hit.comment_line)
            return
        net = editor.networks[hit.network]
        if net.row_is_empty(hit.row) or hit.row >= net.rows:
            self.inline.open_comment(hit.network, len(net.comments))
        else:
            editor.message.emit(
                translate("LadderEditor", "The comment tool works on an empty row only"))

    def edit_at_cursor(self) -> None:
        """ENTER on an empty cell adds a comment line; on an element, edits it."""
        index, row, col = self.editor.cursor_cell
        net = self.editor.networks[index]
        if net.element_at(row, col) is None:
            self.inline.open_comment(index, len(net.comments))
        else:
            super().edit_at_cursor()


class DeleteInteraction(Interaction):
    """Delete the element clicked."""

    tool = Tool.DELETE
    icon_name = "delete"
    key = "D"
    cursor = Qt.CursorShape.PointingHandCursor
    title = QT_TRANSLATE_NOOP("Tool", "Delete")
    hint = QT_TRANSLATE_NOOP("Tool", "Click an element to delete it")

    def apply(self, hit: Hit) -> None:
        """Delete the element at the cell."""
        self.edits.delete(hit.network, hit.row, hit.col)


class FunctionInteraction(Interaction):
    """Place the functional instruction chosen in the palette's list."""

    tool = Tool.FUNCTION
    icon_name = "function"
    key = "F"
    title = QT_TRANSLATE_NOOP("Tool", "Function")
    hint = QT_TRANSLATE_NOOP(
        "Tool", "Choose a function in the list, click the diagram, fill its table")

    def apply(self, hit: Hit) -> None:
        """Open the function table; OK places the box."""
        self.edits.open_function_dialog(hit.network, hit.row, hit.col, self.edits.function_name)


class RowBeforeInteraction(Interaction):
    """Insert an empty row before the one clicked."""

    tool = Tool.ROW_BEFORE
    icon_name = "row_before"
    key = "B"
    cursor = Qt.CursorShape.PointingHandCursor
    after = False
    title = QT_TRANSLATE_NOOP("Tool", "Insert row before")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a cell to insert an empty row before it")

    def apply(self, hit: Hit) -> None:
        """Insert the row."""
        self.edits.insert_row(hit.network, hit.row, after=self.after)


class RowAfterInteraction(RowBeforeInteraction):
    """Insert an empty row after the one clicked."""

    tool = Tool.ROW_AFTER
    icon_name = "row_after"
    key = "A"
    after = True
    title = QT_TRANSLATE_NOOP("Tool", "Insert row after")
    hint = QT_TRANSLATE_NOOP("Tool", "Click a cell to insert an empty row after it")


# the palette's and the Tools menu's order
INTERACTIONS: tuple[type[Interaction], ...] = (
    SelectInteraction, InputInteraction, InputNotInteraction, OutputInteraction,
    OutputNotInteraction, SetCoilInteraction, ResetCoilInteraction, InvertInteraction,
    OrInteraction, LineInteraction, CommentInteraction, DeleteInteraction, FunctionInteraction,
    RowBeforeInteraction, RowAfterInteraction,
)
BY_TOOL: dict[Tool, type[Interaction]] = {cls.tool: cls for cls in INTERACTIONS}
BY_KEY: dict[str, type[Interaction]] = {cls.key: cls for cls in INTERACTIONS}
