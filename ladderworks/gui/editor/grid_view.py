"""The ladder grid as drawn: the model's networks on a QGraphicsScene, the cursor and the
selection, positions and zoom. The console's editor (`view.LadderEditor`) adds the tools, the
keys and in-place editing on top of it."""

from __future__ import annotations

from PySide6.QtCore import QPoint, QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QBrush, QColor, QPainter, QPaintEvent, QPen, QUndoStack
from PySide6.QtWidgets import QGraphicsRectItem, QGraphicsScene, QGraphicsView, QWidget

from ladderworks.core.address import Address, AddressError
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.dialects.typed_bits import read_bit
from ladderworks.core.il import Program
from ladderworks.core.instructions import lookup
from ladderworks.core.ladder import Coil, Contact, LadderNetwork, Selection, Wire
from ladderworks.core.ladder.logic import coil_spec
from ladderworks.core.symbols import resolve
from ladderworks.gui.editor.centre import centre_on
from ladderworks.gui.editor.geometry import (
    CELL_W,
    COMMENT_H,
    LEFT,
    SPARE_ROWS,
    Hit,
    Layout,
    cell_centre,
    cell_h,
    cell_origin,
    node_point,
)
from ladderworks.gui.editor.label_text import CommentedAddresses, shows_comment
from ladderworks.gui.editor.labelled_item import LabelledNetworkItem
from ladderworks.gui.editor.ladder_model import LadderModel
from ladderworks.gui.editor.lazy_items import LazyItems
from ladderworks.gui.editor.network_item import NetworkItem
from ladderworks.gui.symbol_text import cell_status, element_tooltip, name_and_text

ZOOM_STEP = 1.2
ZOOM_MIN = 0.3
ZOOM_MAX = 3.0


class GridView(QGraphicsView):
    """The drawing of a `LadderModel`: it redraws what the model announces, and keeps the
    cursor, the selection and the zoom."""

    hover_changed = Signal(str)
    cursor_placed = Signal()  # the cursor's frame was put on its cell (moved, or a relayout)
    message = Signal(str)
    zoom_changed = Signal(float)  # the new zoom factor (the status bar shows it)
    drawing_changed = Signal()
    relaid_out = Signal()  # every network's rows were worked out again (View › Element names)

    def __init__(self, model: LadderModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("ladder_view")
        self.model = model
        self._scene = QGraphicsScene(self)
        self._scene.setBackgroundBrush(QBrush(QColor("#ffffff")))
        self.setScene(self._scene)
        self.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        self.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.MinimalViewportUpdate)
        self.setMouseTracking(True)
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.network_items = LazyItems(self._make_item)  # made when shown (a real program: 10,000+)
        self.comments = CommentedAddresses(self.describe_address)  # asked once per address
        self.layout_ = Layout(self.commented)
        self.cursor_cell: tuple[int, int, int] = (0, 0, 0)  # network, row, col
        self.selection: tuple[int, Selection] | None = None
        self._zoom = 1.0
        self._cursor_item = QGraphicsRectItem()
        self._cursor_item.setPen(QPen(QColor("#1565c0"), 2))
        self._cursor_item.setZValue(10)
        self._selection_item = QGraphicsRectItem()
        self._selection_item.setPen(QPen(QColor("#f57c00"), 2, Qt.PenStyle.DashLine))
        self._selection_item.setBrush(QBrush(QColor(255, 152, 0, 40)))
        self._selection_item.setZValue(9)
        for item in (self._cursor_item, self._selection_item):
            self._scene.addItem(item)
        self._selection_item.hide()
        model.document_reset.connect(self._on_reset)
        model.networks_inserted.connect(self._on_inserted)
        model.network_removed.connect(self._on_removed)
        model.network_changed.connect(self._on_changed)
        model.networks_changed.connect(self._on_many_changed)
        model.diagnostics_found.connect(self.mark_diagnostics)
        self._on_reset()

    # -- the model, as the window and the tests ask for it ------------------------------------

    @property
    def networks(self) -> list[LadderNetwork]:
        """The model's networks (the last is the blank one to draw in)."""
        return self.model.networks

    @property
    def undo_stack(self) -> QUndoStack:
        """The model's undo stack."""
        return self.model.undo_stack

    @property
    def loading(self) -> bool:
        """True while a large program's networks are still being laid out."""
        return self.model.loading

    def finish_loading(self) -> None:
        """Lay out every network still pending now."""
        self.model.finish_loading()

    def program(self) -> tuple[Program | None, list[Diagnostic]]:
        """The program drawn (None when a network cannot be coded) and the diagnostics."""
        return self.model.program()

    def is_empty(self) -> bool:
        """True when nothing is drawn."""
        return self.model.is_empty()

    # -- following the model ------------------------------------------------------------------

    def _on_reset(self) -> None:
        for _index, item in self.network_items.made():
            self._scene.removeItem(item)
        self.network_items.reset(len(self.networks))
        self.comments.forget()  # another program: other symbols
        self.layout_ = Layout(self.commented)
        self.layout_.rebuild(self.networks)
        self.selection = None
        self.cursor_cell = (0, 0, 0)
        self._update_scene_rect()
        self.verticalScrollBar().setValue(0)  # another program starts at its top left
        self.horizontalScrollBar().setValue(0)
        self.place_overlays()

    def _on_inserted(self, first: int, count: int) -> None:
        for _network in range(count):
            self.network_items.insert(first)
        self._relayout(first)
        self._renumber(max(first - 1, 0))

    def _on_removed(self, index: int) -> None:
        item = self.network_items.pop(index)
        if item is not None:
            self._scene.removeItem(item)
        if self.cursor_cell[0] >= len(self.networks):
            self.cursor_cell = (len(self.networks) - 1, 0, 0)
        self._relayout(min(index, len(self.networks) - 1))
        self._renumber(max(index - 1, 0))

    def _on_changed(self, index: int) -> None:
        self._on_many_changed([index])

    def _on_many_changed(self, indices: list[int]) -> None:
        if not indices:
            return
        changed = set(indices)
        for index in changed:
            self.layout_.forget(self.networks[index])  # its rows may change (a comment typed)
        for index, item in self.network_items.made(min(changed)):
            if index in changed:
                item.error_cells = set()
                item.refresh()
        self._relayout(min(changed))
        self._renumber(min(changed))
        self.drawing_changed.emit()

    def _make_item(self, index: int) -> NetworkItem:
        item = LabelledNetworkItem(self.networks[index], self.network_number(index),
                                   self.describe_address)
        item.spelling = spelling(self.model.dialect)  # a Delta program: Delta's spelling
        item.is_new = index == self.model.blank_index() and self.networks[index].is_empty()
        item.setPos(0, self.layout_.tops[index])
        self._scene.addItem(item)
        return item

    def make_visible_items(self) -> None:
        """Make the items of the networks in (and just around) the viewport."""
        if not self.networks or not self.layout_.tops:
            return
        shown = self.mapToScene(self.viewport().rect()).boundingRect()
        for index in self.layout_.shown(shown.top() - cell_h(), shown.bottom() + cell_h()):
            if index < len(self.networks):
                self.network_items[index]

    def paintEvent(self, event: QPaintEvent) -> None:
        """Make the visible networks' items, then paint."""
        self.make_visible_items()
        super().paintEvent(event)

    def describe_address(self, address: object) -> tuple[str, str] | None:
        """(symbol, comment) of the program, else (signal name, description) of the manual
        (a Delta program's addresses are no FANUC signals: none)."""
        if spelling(self.model.dialect).dialect:
            return None
        return name_and_text(address, self.model.symbols)

    def commented(self, network: LadderNetwork) -> bool:
        """True when an element of `network` has a comment to show (its rows are taller)."""
        return shows_comment(network, self.comments)

    def typed_bit(self, text: str, element: Contact | Coil) -> str | Address | Diagnostic:
        """The device typed on a contact or coil. A dialect program's reader reads it as the
        element's line (`LD T0`: T0's contact; `OUT X0`: its refusal, a Diagnostic); a PMC
        program's text is itself or the address of a program symbol (the edit checks it)."""
        dialect = self.model.dialect
        if not spelling(dialect).dialect:
            try:
                return str(resolve(text, self.model.symbols))
            except AddressError:
                return text
        spec = coil_spec(element) if isinstance(element, Coil) else lookup(
            "RD.NOT" if element.negated else "RD")
        assert spec is not None
        return read_bit(spec, text, str(dialect))

    def spell_address(self, address: Address) -> str:
        """An address as the program writes it (`X17` in a Delta program)."""
        return spelling(self.model.dialect).address(address)

    def network_number(self, index: int) -> int:
        """The number network `index` is shown with: the program's END after the blank
        network is numbered as the program counts it (the blank's own tag is `+`)."""
        blank = self.model.blank_index()
        return index if index > blank else index + 1

    def _renumber(self, start: int) -> None:
        blank = self.model.blank_index()
        for index, item in self.network_items.made(start):
            item.number = self.network_number(index)
            item.is_new = index == blank and self.networks[index].is_empty()
            item.update()

    def _relayout(self, start: int) -> None:
        self.layout_.rebuild(self.networks, start)
        for index, item in self.network_items.made(start):
            item.setPos(0, self.layout_.tops[index])
        self._update_scene_rect()
        self.place_overlays()

    def _update_scene_rect(self) -> None:
        widest = max(800, *(LEFT + (n.columns + 1) * CELL_W + 8 for n in self.networks))
        self._scene.setSceneRect(QRectF(-4, -4, widest + 8, self.layout_.total_height() + 40))

    def relayout(self) -> None:
        """The rows changed height (View › Element names, the language): lay every network
        out again."""
        self.comments.forget()
        self.layout_.forget()
        for _index, item in self.network_items.made():
            item.refresh()
        self._relayout(0)
        self.viewport().update()
        self.relaid_out.emit()

    def mark_diagnostics(self, diagnostics: list[Diagnostic]) -> None:
        """Outline the cells the diagnostics point at."""
        for _index, item in self.network_items.made():
            if item.error_cells:
                item.error_cells = set()
                item.update()
        for diagnostic in diagnostics:
            if diagnostic.network is None or diagnostic.cell is None:
                continue
            index = self.model.editor_network(diagnostic.network)
            if 0 <= index < len(self.network_items):
                item = self.network_items[index]
                item.error_cells.add(diagnostic.cell)
                item.update()

    # -- cursor, overlays, positions ----------------------------------------------------------

    def cell_rect(self, index: int, row: int, col: int) -> QRectF:
        """A cell's rectangle in scene coordinates."""
        rows = self.layout_.rows[index]
        x, y = cell_origin(self.networks[index], row, col, rows)
        return QRectF(x, self.layout_.tops[index] + y, CELL_W, rows.height)

    def cell_point(self, index: int, row: int, col: int) -> QPoint:
        """Viewport point at a cell's centre (scrolled into view first)."""
        x, y = cell_centre(self.networks[index], row, col, self.layout_.rows[index])
        scene = QPointF(x, self.layout_.tops[index] + y)
        self.ensureVisible(QRectF(scene.x() - 60, scene.y() - 60, 120, 120), 10, 10)
        return self.mapFromScene(scene)

    def node_point(self, index: int, row: int, node: int) -> QPoint:
        """Viewport point at a grid node (left edge of column `node`, middle of `row`)."""
        x, y = node_point(self.networks[index], row, node, self.layout_.rows[index])
        scene = QPointF(x, self.layout_.tops[index] + y)
        self.ensureVisible(QRectF(scene.x() - 60, scene.y() - 60, 120, 120), 10, 10)
        return self.mapFromScene(scene)

    def comment_point(self, index: int, line: int) -> QPoint:
        """Viewport point on network comment line `line`."""
        scene = QPointF(LEFT + 40, self.layout_.tops[index] + line * COMMENT_H + COMMENT_H / 2)
        self.ensureVisible(QRectF(scene.x() - 40, scene.y() - 40, 80, 80), 10, 10)
        return self.mapFromScene(scene)

    def move_cursor(self, index: int, row: int, col: int) -> None:
        """Put the cursor on a cell."""
        net = self.networks[index]
        row = min(max(row, 0), net.rows - 1 + SPARE_ROWS)
        col = min(max(col, 0), net.columns)
        self.cursor_cell = (index, row, col)
        self.place_overlays()
        self.ensureVisible(self.cell_rect(index, row, col), 20, 20)
        self.hover_changed.emit(self.describe_cell(index, row, col))

    def place_overlays(self) -> None:
        """Draw the cursor and the selection where they are."""
        if not self.networks:
            return
        index, row, col = self.cursor_cell
        index = min(index, len(self.networks) - 1)
        self._cursor_item.setRect(self.cell_rect(index, row, col).adjusted(1, 1, -1, -1))
        if self.selection is not None and self.selection[0] < len(self.networks):
            sel_index, sel = self.selection
            rect = self.cell_rect(sel_index, sel.top, sel.left).united(
                self.cell_rect(sel_index, sel.bottom, sel.right)
            )
            self._selection_item.setRect(rect)
            self._selection_item.show()
        else:
            self._selection_item.hide()
        self.cursor_placed.emit()

    def jump_to(self, index: int, row: int, col: int) -> None:
        """The cursor on a cell found elsewhere (Find, cross reference, error list), that cell
        brought to the middle of the view (not to its bottom edge)."""
        self.move_cursor(index, row, col)
        centre_on(self, self.cell_rect(*self.cursor_cell))

    def go_to(self, diagnostic: Diagnostic) -> None:
        """Jump to a diagnostic's network and cell."""
        if diagnostic.network is not None and diagnostic.network >= len(self.networks) - 1:
            self.finish_loading()
        if diagnostic.network is None:
            return
        index = self.model.editor_network(diagnostic.network)
        if not 0 <= index < len(self.networks):
            return
        row, col = diagnostic.cell if diagnostic.cell is not None else (0, 0)
        self.jump_to(index, row, col)
        self.setFocus()

    def tooltip_at(self, index: int, row: int, col: int) -> str:
        """Tooltip of a cell's contact or coil: address, symbol, its comments; else ""."""
        return element_tooltip(self.networks[index], row, col, self.model.symbols)

    def describe_cell(self, index: int, row: int, col: int) -> str:
        """Status-bar text: the cell, and the address with its signal name and comment."""
        return cell_status(self.networks[index], index, row, col, self.model.symbols,
                           self.model.dialect)

    def select_element(self, index: int, row: int, col: int) -> None:
        """Select the element covering a cell (nothing on a wire or an empty cell)."""
        found = self.networks[index].element_at(row, col)
        if found is None or isinstance(found[1], Wire):
            self.selection = None
        else:
            (r, c), element = found
            cells = self.networks[index].footprint((r, c), element)
            self.selection = (index, Selection.spanning(cells[0], cells[-1]))
        self.place_overlays()

    def select_rectangle(self, index: int, corner: tuple[int, int],
                         other: tuple[int, int]) -> None:
        """Select the cells between two corners of one network (rows and columns clamped)."""
        net = self.networks[index]
        last_row = max(net.rows - 1, 0)

        def clamp(cell: tuple[int, int]) -> tuple[int, int]:
            return min(max(cell[0], 0), last_row), min(max(cell[1], 0), net.columns)

        self.selection = (index, Selection.spanning(clamp(corner), clamp(other)))
        self.place_overlays()

    def cursor_to(self, index: int, row: int, col: int) -> None:
        """Put the cursor on the cell where an edit put an element (no scrolling)."""
        self.cursor_cell = (index, row, col)
        self.place_overlays()

    # -- zoom ---------------------------------------------------------------------------------

    def zoom_in(self) -> None:
        """Zoom in one step."""
        self._set_zoom(self._zoom * ZOOM_STEP)

    def zoom_out(self) -> None:
        """Zoom out one step."""
        self._set_zoom(self._zoom / ZOOM_STEP)

    def zoom_reset(self) -> None:
        """Back to 100 %."""
        self._set_zoom(1.0)

    def zoom(self) -> float:
        """The current zoom factor."""
        return self._zoom

    def set_zoom(self, factor: float) -> None:
        """Zoom to `factor` (clamped to the zoom range)."""
        self._set_zoom(factor)

    def _set_zoom(self, factor: float) -> None:
        self._zoom = min(max(factor, ZOOM_MIN), ZOOM_MAX)
        self.resetTransform()
        self.scale(self._zoom, self._zoom)
        self.zoom_changed.emit(self._zoom)

    # -- events -------------------------------------------------------------------------------

    def _hit(self, pos: QPoint) -> Hit:
        scene = self.mapToScene(pos)
        return self.layout_.hit(self.networks, scene.x(), scene.y())

