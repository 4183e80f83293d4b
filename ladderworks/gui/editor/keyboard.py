"""Grid keys that move: arrows (Shift: select), Home/End, Ctrl+Home/End, PageUp/PageDown, the
menu key."""

from __future__ import annotations

from PySide6.QtCore import QPoint, Qt
from PySide6.QtGui import QContextMenuEvent, QKeyEvent

from ladderworks.gui.editor.geometry import SPARE_ROWS, cell_h, grid_top
from ladderworks.gui.editor.grid_view import GridView

Cursor = tuple[int, int, int]  # network, row, column
ARROWS: dict[int, tuple[int, int]] = {
    Qt.Key.Key_Left: (0, -1), Qt.Key.Key_Right: (0, 1), Qt.Key.Key_Up: (-1, 0),
    Qt.Key.Key_Down: (1, 0)}
MODIFIER_KEYS = (Qt.Key.Key_Shift, Qt.Key.Key_Control, Qt.Key.Key_Alt, Qt.Key.Key_Meta)


class GridKeys:
    """Maps a key press in the ladder grid to a cursor move or a command; True if handled."""

    def __init__(self, editor: GridView) -> None:
        self._editor = editor
        self.anchor: Cursor | None = None  # where a Shift+arrows selection started

    def _arrow(self, key: int, shift: bool) -> bool:
        """An arrow moves the cursor (into the next or previous network at an end); with Shift
        it stretches a selection from where the first Shift+arrow started."""
        if key not in ARROWS:
            return False
        editor = self._editor
        index, row, col = editor.cursor_cell
        drow, dcol = ARROWS[key]
        if shift:
            if self.anchor is None or self.anchor[0] != index:
                self.anchor = (index, row, col)
            editor.move_cursor(index, max(row + drow, 0), max(col + dcol, 0))
            editor.select_rectangle(index, self.anchor[1:], editor.cursor_cell[1:])
            return True
        row += drow
        col += dcol
        if row < 0 and index > 0:
            index -= 1
            row = editor.networks[index].rows - 1
        elif row >= editor.networks[index].rows + SPARE_ROWS and index < len(editor.networks) - 1:
            index += 1
            row = 0
        editor.move_cursor(index, row, col)
        return True

    def handle(self, event: QKeyEvent) -> bool:
        """Do what the key means in the grid (cursor moves, the context menu)."""
        key = event.key()
        modifiers = event.modifiers()
        ctrl = bool(modifiers & Qt.KeyboardModifier.ControlModifier)
        shift = bool(modifiers & Qt.KeyboardModifier.ShiftModifier)
        if not (shift and key in ARROWS) and key not in MODIFIER_KEYS:
            self.anchor = None  # any other key ends a Shift+arrows selection
        if self._arrow(key, shift):
            return True
        if key == Qt.Key.Key_Menu or (key == Qt.Key.Key_F10 and shift):
            self.open_context_menu()
            return True
        target = self.target(key, ctrl)
        if target is None:
            return False
        self._editor.move_cursor(*target)
        return True

    def target(self, key: int, ctrl: bool = False) -> Cursor | None:
        """Where Home, End, Ctrl+Home, Ctrl+End, PageUp, PageDown put the cursor (None: not
        one of those keys)."""
        editor = self._editor
        index, row, col = editor.cursor_cell
        networks = editor.networks
        if key == Qt.Key.Key_Home:
            return (0, 0, 0) if ctrl else (index, row, 0)
        if key == Qt.Key.Key_End:
            if ctrl:
                editor.finish_loading()  # a large program: the end is after every network
                return editor.model.blank_index(), 0, 0  # the empty network: draw the next
            return index, row, networks[index].columns  # the coil column
        if key in (Qt.Key.Key_PageUp, Qt.Key.Key_PageDown):
            return self._page(index, row, col, key == Qt.Key.Key_PageDown)
        return None

    def _page(self, index: int, row: int, col: int, down: bool) -> Cursor:
        """The cell a viewport's height above or below the cursor, same column."""
        editor = self._editor
        tops = editor.layout_.tops
        networks = editor.networks
        if down and index >= len(networks) - 2:
            editor.finish_loading()  # a large program: page on into the networks still pending
        page = max(editor.viewport().height() / max(editor.zoom(), 0.01) - cell_h(), cell_h())
        rows = editor.layout_.rows
        y = tops[index] + grid_top(networks[index]) + row * rows[index].height + rows[index].wire
        y += page if down else -page
        target = editor.layout_.network_at(y)
        net = networks[target]
        local = int((y - tops[target] - grid_top(net)) // rows[target].height)
        last_row = net.rows - 1 + SPARE_ROWS
        if target == index and local == row:  # at the first or last page: to its first/last row
            local = last_row if down else 0
        return target, min(max(local, 0), last_row), col

    def open_context_menu(self) -> None:
        """The right-click menu, at the cursor cell (Shift+F10, the menu key)."""
        editor = self._editor
        index, row, col = editor.cursor_cell
        point: QPoint = editor.cell_point(index, row, col)
        viewport = editor.viewport()
        editor.contextMenuEvent(QContextMenuEvent(
            QContextMenuEvent.Reason.Keyboard, point, viewport.mapToGlobal(point)))
