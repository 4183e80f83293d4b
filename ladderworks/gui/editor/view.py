"""The grid editor view: networks on a QGraphicsScene, tools on mouse clicks and keys."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QPoint, QPointF, QRectF, Qt, Signal
from PySide6.QtGui import (
    QAction,
    QBrush,
    QColor,
    QContextMenuEvent,
    QKeyEvent,
    QMouseEvent,
    QPainter,
    QPaintEvent,
    QPen,
    QUndoStack,
)
from PySide6.QtWidgets import (
    QApplication,
    QGraphicsRectItem,
    QGraphicsScene,
    QGraphicsView,
    QLabel,
    QLineEdit,
    QMenu,
    QWidget,
)

from ladderworks.core import ladder as core
from ladderworks.core.address import Address, AddressError
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Instruction, Program, print_instruction
from ladderworks.core.instructions import Write, lookup
from ladderworks.core.ladder import (
    Coil,
    Contact,
    Edit,
    EditRefused,
    FunctionBox,
    LadderDocument,
    LadderNetwork,
    Selection,
    Wire,
    convert,
)
from ladderworks.core.ladder.convert import Kept
from ladderworks.core.signals import signal_at
from ladderworks.core.symbols import SymbolTable, resolve
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.commands import NetworkEditCommand, NetworkListCommand
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
    grid_top,
    node_point,
)
from ladderworks.gui.editor.labelled_item import LabelledNetworkItem
from ladderworks.gui.editor.lazy_items import LazyItems
from ladderworks.gui.editor.network_item import NetworkItem
from ladderworks.gui.editor.progressive import ProgressiveLoader
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.symbol_text import name_and_text, tooltip
from ladderworks.gui.tools import KEY_TOOLS, Tool

ZOOM_STEP = 1.2
ZOOM_MIN = 0.3
ZOOM_MAX = 3.0


translate = QCoreApplication.translate


def is_blank(network: LadderNetwork) -> bool:
    """True for a network with nothing drawn and no comment (the drawing area at the end)."""
    return network.is_empty() and not network.comments


def describe_signal(address: object) -> tuple[str, str] | None:
    """(short name, description in the UI language) of a named F/G/X/Y signal."""
    if not isinstance(address, Address):
        return None
    signal = signal_at(address)
    if signal is None:
        return None
    from PySide6.QtCore import QLocale

    turkish = QLocale().language() == QLocale.Language.Turkish
    return signal.name, (signal.turkish if turkish else signal.english) or signal.english


class LadderEditor(QGraphicsView):
    """The ladder console's drawing area; every edit goes through `undo_stack`."""

    tool_requested = Signal(object)  # Tool picked with a letter key
    hover_changed = Signal(str)
    message = Signal(str)
    drawing_changed = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("ladder_view")
        self._scene = QGraphicsScene(self)
        self._scene.setBackgroundBrush(QBrush(QColor("#ffffff")))
        self.setScene(self._scene)
        self.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        self.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.MinimalViewportUpdate)
        self.setMouseTracking(True)
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.undo_stack = QUndoStack(self)
        self.document = LadderDocument()
        self.symbols: SymbolTable | None = None  # the program's `%@2` symbols
        self.networks: list[LadderNetwork] = []
        self.network_items = LazyItems(self._make_item)  # made when shown (a real program: 10,000+)
        self.loader = ProgressiveLoader(self)
        self.layout_ = Layout()
        self.tool = Tool.SELECT
        self.function_name = "TMR"
        self.cursor_cell: tuple[int, int, int] = (0, 0, 0)  # network, row, col
        self.selection: tuple[int, Selection] | None = None
        self._drag_origin: tuple[int, int, int] | None = None  # select tool: where a drag began
        self._shift_anchor: tuple[int, int, int] | None = None  # Shift+arrows: the fixed corner
        self.line_start: tuple[int, int, int] | None = None  # network, row, node
        self.function_dialog: FunctionDialog | None = None
        self.context_actions: list[QAction | None] = []
        self._zoom = 1.0
        self._cursor_item = QGraphicsRectItem()
        self._cursor_item.setPen(QPen(QColor("#1565c0"), 2))
        self._cursor_item.setZValue(10)
        self._selection_item = QGraphicsRectItem()
        self._selection_item.setPen(QPen(QColor("#f57c00"), 2, Qt.PenStyle.DashLine))
        self._selection_item.setBrush(QBrush(QColor(255, 152, 0, 40)))
        self._selection_item.setZValue(9)
        self._line_item = QGraphicsRectItem()
        self._line_item.setPen(QPen(QColor("#2e7d32"), 2))
        self._line_item.setBrush(QBrush(QColor("#2e7d32")))
        self._line_item.setZValue(11)
        for item in (self._cursor_item, self._selection_item, self._line_item):
            self._scene.addItem(item)
        self._selection_item.hide()
        self._line_item.hide()
        self.inline_editor = QLineEdit(self.viewport())
        self.inline_editor.setObjectName("inline_editor")
        self.inline_editor.hide()
        self.inline_editor.installEventFilter(self)
        self.inline_message = QLabel(self.viewport())
        self.inline_message.setObjectName("inline_message")
        self.inline_message.setStyleSheet(
            "background: #fff3f3; color: #b00020; border: 1px solid #b00020; padding: 2px;"
        )
        self.inline_message.hide()
        self._inline_target: tuple[str, int, int, int] | None = None  # kind, network, row, col

    # -- the document ------------------------------------------------------------------------

    def set_program(self, program: Program, kept: Kept | None = None) -> None:
        """Show a program as ladder (clears undo); every program the parser accepts lays out.

        A large program shows its first networks at once; the rest are laid out in the
        background (`loading`; `finish_loading()` waits for them). `kept` receives each
        network as laid out with the one it came from (the document's faithful Save)."""
        document = self.loader.head(program, kept)
        self.set_document(document, keep_pending=True)
        self.loader.start()

    @property
    def loading(self) -> bool:
        """True while a large program's networks are still being laid out."""
        return self.loader.loading

    def finish_loading(self) -> None:
        """Lay out every network still pending now."""
        self.loader.finish()

    def append_networks(self, networks: list[LadderNetwork]) -> None:
        """Add laid-out networks before the empty network at the end (background loading)."""
        at = len(self.networks) - 1
        self.networks[at:at] = networks
        for _network in networks:
            self.network_items.insert(at)
        self._relayout(at)
        self._renumber(at)

    def set_document(self, document: LadderDocument, *, keep_pending: bool = False) -> None:
        """Show a ladder document (clears undo)."""
        if not keep_pending:
            self.loader.cancel()
        self._close_inline()
        self.undo_stack.clear()
        self.document = document
        self.symbols = document.origin.symbols if document.origin is not None else None
        self.networks = [net for net in document.networks]
        self.networks.append(LadderNetwork())
        for _index, item in self.network_items.made():
            self._scene.removeItem(item)
        self.network_items.reset(len(self.networks))
        self.layout_ = Layout()
        self.layout_.rebuild(self.networks)
        self.selection = None
        self.line_start = None
        self.cursor_cell = (0, 0, 0)
        self._update_scene_rect()
        self._place_overlays()

    def mark_modified(self) -> None:
        """Make the document count as changed (e.g. after text edits shown as ladder)."""
        self.undo_stack.resetClean()

    def ladder_document(self) -> LadderDocument:
        """The document with the drawn networks (the empty network at the end left out)."""
        self.finish_loading()
        doc = self.document
        nets = list(self.networks)
        if nets and is_blank(nets[-1]):
            nets.pop()
        return LadderDocument(nets, doc.header, doc.trailer, doc.footer, doc.before, doc.after,
                              doc.origin)

    def program(self) -> tuple[Program | None, list[Diagnostic]]:
        """The program drawn (None when a network cannot be coded) and the diagnostics."""
        program, diagnostics = self.saved_program()
        return (None if has_errors(diagnostics) else program), diagnostics

    def saved_program(self) -> tuple[Program, list[Diagnostic]]:
        """The program to save: a network that cannot be coded yet is kept as a draft."""
        program, diagnostics = convert.ladder_to_program(self.ladder_document())
        self.mark_diagnostics(diagnostics)
        return program, diagnostics

    def is_empty(self) -> bool:
        """True when nothing is drawn."""
        self.finish_loading()
        return all(net.is_empty() for net in self.networks)

    def _make_item(self, index: int) -> NetworkItem:
        item = LabelledNetworkItem(self.networks[index], index + 1, self.describe_address)
        item.is_new = index == len(self.networks) - 1 and self.networks[index].is_empty()
        item.setPos(0, self.layout_.tops[index])
        self._scene.addItem(item)
        return item

    def make_visible_items(self) -> None:
        """Make the items of the networks in (and just around) the viewport."""
        if not self.networks or not self.layout_.tops:
            return
        shown = self.mapToScene(self.viewport().rect()).boundingRect()
        first = self.layout_.network_at(shown.top() - cell_h())
        last = self.layout_.network_at(shown.bottom() + cell_h())
        for index in range(first, min(last, len(self.networks) - 1) + 1):
            self.network_items[index]

    def paintEvent(self, event: QPaintEvent) -> None:
        """Make the visible networks' items, then paint."""
        self.make_visible_items()
        super().paintEvent(event)

    def describe_address(self, address: object) -> tuple[str, str] | None:
        """(symbol, comment) of the program, else (signal name, description) of the manual."""
        return name_and_text(address, self.symbols)

    def resolve_address(self, text: str) -> str:
        """The address a typed text names: itself, or the address of a program symbol."""
        try:
            return str(resolve(text, self.symbols))
        except AddressError:
            return text

    def _renumber(self, start: int) -> None:
        last = len(self.network_items) - 1
        for index, item in self.network_items.made(start):
            item.number = index + 1
            item.is_new = index == last and self.networks[index].is_empty()
            item.update()

    def _relayout(self, start: int) -> None:
        self.layout_.rebuild(self.networks, start)
        for index, item in self.network_items.made(start):
            item.setPos(0, self.layout_.tops[index])
        self._update_scene_rect()
        self._place_overlays()

    def _update_scene_rect(self) -> None:
        widest = max(800, *(LEFT + (n.columns + 1) * CELL_W + 8 for n in self.networks))
        self._scene.setSceneRect(QRectF(-4, -4, widest + 8, self.layout_.total_height() + 40))

    def relayout(self) -> None:
        """The rows changed height (View › Element names): lay every network out again."""
        for _index, item in self.network_items.made():
            item.refresh()
        self._relayout(0)

    def network_changed(self, index: int) -> None:
        """A command changed network `index`: repaint and restack from it."""
        self.network_items[index].error_cells = set()
        self.network_items[index].refresh()
        self._relayout(index)
        self._renumber(index)
        self.drawing_changed.emit()

    def insert_network(self, index: int, network: LadderNetwork) -> None:
        """Insert a network (used by undo commands)."""
        self.networks.insert(index, network)
        self.network_items.insert(index)
        self._relayout(index)
        self._renumber(max(index - 1, 0))

    def remove_network(self, index: int) -> LadderNetwork:
        """Remove a network (used by undo commands); returns it."""
        network = self.networks.pop(index)
        item = self.network_items.pop(index)
        if item is not None:
            self._scene.removeItem(item)
        if self.cursor_cell[0] >= len(self.networks):
            self.cursor_cell = (len(self.networks) - 1, 0, 0)
        self._relayout(min(index, len(self.networks) - 1))
        self._renumber(max(index - 1, 0))
        return network

    def mark_diagnostics(self, diagnostics: list[Diagnostic]) -> None:
        """Outline the cells the diagnostics point at."""
        for _index, item in self.network_items.made():
            if item.error_cells:
                item.error_cells = set()
                item.update()
        for diagnostic in diagnostics:
            if (
                diagnostic.network is not None
                and diagnostic.cell is not None
                and 0 <= diagnostic.network < len(self.network_items)
            ):
                item = self.network_items[diagnostic.network]
                item.error_cells.add(diagnostic.cell)
                item.update()

    # -- editing through commands -------------------------------------------------------------

    def run_edit(self, index: int, operation: Callable[[LadderNetwork], Edit], text: str) -> bool:
        """Apply a core edit to network `index` as an undoable command; False if refused."""
        try:
            undo_edit = operation(self.networks[index])
        except EditRefused as refused:
            self.message.emit(diagnostic_text(refused.diagnostic))
            return False
        self.undo_stack.push(NetworkEditCommand(self, index, undo_edit, text))
        return True

    def assign_address_at_cursor(self, address: Address) -> bool:
        """Put `address` on the contact or coil at the cursor (one undo step); False if none."""
        index, row, col = self.cursor_cell
        if index >= len(self.networks) or address.bit is None:
            return False
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return False
        (r, c), _element = found
        text = str(address)
        return self.run_edit(index, lambda n: core.set_address(n, r, c, text),
                             translate("LadderEditor", "Address {0}").format(text))

    def set_tool(self, tool: Tool) -> None:
        """Make `tool` current."""
        self.tool = tool
        self.line_start = None
        self._line_item.hide()
        if tool in (Tool.ROW_BEFORE, Tool.ROW_AFTER, Tool.DELETE):
            self.viewport().setCursor(Qt.CursorShape.PointingHandCursor)
        elif tool is Tool.SELECT:
            self.viewport().setCursor(Qt.CursorShape.ArrowCursor)
        else:
            self.viewport().setCursor(Qt.CursorShape.CrossCursor)

    def set_function(self, name: str) -> None:
        """The functional instruction the function tool places."""
        self.function_name = name

    def apply_tool(self, hit: Hit) -> None:
        """Do what the current tool does at a cell (a click, or SPACE at the cursor)."""
        index, row, col = hit.network, hit.row, hit.col
        net = self.networks[index]
        tool = self.tool
        if hit.comment_line is not None and tool in (Tool.COMMENT, Tool.SELECT):
            self.open_comment_editor(index, hit.comment_line)
            return
        if tool is Tool.SELECT:
            self._select(index, row, col)
        elif tool in (Tool.INPUT, Tool.INPUT_NOT):
            self._place_bit(index, row, col, Contact(negated=tool is Tool.INPUT_NOT))
        elif tool in (Tool.OUTPUT, Tool.OUTPUT_NOT):
            self._place_bit(index, row, col, Coil(negated=tool is Tool.OUTPUT_NOT))
        elif tool in (Tool.SET_COIL, Tool.RESET_COIL):
            write = Write.SET if tool is Tool.SET_COIL else Write.RESET
            self._place_bit(index, row, col, Coil(write=write))
        elif tool is Tool.INVERT:
            self.run_edit(
                index, lambda n: core.invert(n, row, col), translate("LadderEditor", "NOT")
            )
        elif tool is Tool.OR:
            self._add_parallel(index, row, col)
        elif tool is Tool.LINE:
            self._line_click(index, row, hit.node)
        elif tool is Tool.COMMENT:
            if net.row_is_empty(row) or row >= net.rows:
                self.open_comment_editor(index, len(net.comments))
            else:
                self.message.emit(
                    translate("LadderEditor", "The comment tool works on an empty row only")
                )
        elif tool is Tool.DELETE:
            self.run_edit(
                index, lambda n: core.delete(n, row, col), translate("LadderEditor", "Delete")
            )
        elif tool is Tool.FUNCTION:
            self.open_function_dialog(index, row, col, self.function_name)
        elif tool in (Tool.ROW_BEFORE, Tool.ROW_AFTER):
            after = tool is Tool.ROW_AFTER
            self.run_edit(
                index,
                lambda n: core.insert_row(n, row, after=after),
                translate("LadderEditor", "Insert row"),
            )

    def _place_bit(self, index: int, row: int, col: int, element: Contact | Coil) -> None:
        row, col = core.target_cell(self.networks[index], row, col, element)  # coil: the rail
        found = self.networks[index].element_at(row, col)
        if found is not None and type(found[1]) is type(element):
            old = found[1]
            assert isinstance(old, Contact | Coil)
            if isinstance(old, Coil) and isinstance(element, Coil) and old.write != element.write:
                kind = replace(old, negated=element.negated, write=element.write)
                self.run_edit(
                    index, lambda n: core.replace_element(n, row, col, kind),
                    translate("LadderEditor", "Place coil"))
            elif old.negated != element.negated:
                self.run_edit(
                    index, lambda n: core.invert(n, row, col), translate("LadderEditor", "NOT")
                )
            self.open_address_editor(index, found[0][0], found[0][1])
            return
        text = (
            translate("LadderEditor", "Place contact")
            if isinstance(element, Contact)
            else translate("LadderEditor", "Place coil")
        )
        if self.run_edit(index, lambda n: core.place_wired(n, row, col, element), text):
            self.open_address_editor(index, row, col)

    def _add_parallel(self, index: int, row: int, col: int) -> None:
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            self.message.emit(
                translate("LadderEditor", "Select a contact or a coil for the OR tool")
            )
            return
        (row, col), _old = found
        if self.run_edit(
            index, lambda n: core.add_parallel(n, row, col), translate("LadderEditor", "OR")
        ):
            self.open_address_editor(index, row + 1, col)

    def _line_click(self, index: int, row: int, node: int) -> None:
        if self.line_start is None or self.line_start[0] != index:
            self.line_start = (index, row, node)
            x, y = node_point(self.networks[index], row, node)
            top = self.layout_.tops[index]
            self._line_item.setRect(QRectF(x - 4, top + y - 4, 8, 8))
            self._line_item.show()
            self.message.emit(translate("LadderEditor", "Line: click the second point"))
            return
        _, row1, node1 = self.line_start
        self.line_start = None
        self._line_item.hide()
        if (row1, node1) == (row, node):
            return
        self.run_edit(
            index,
            lambda n: core.draw_line(n, (row1, node1), (row, node)),
            translate("LadderEditor", "Line"),
        )

    def _select(self, index: int, row: int, col: int) -> None:
        found = self.networks[index].element_at(row, col)
        if found is None or isinstance(found[1], Wire):
            self.selection = None
        else:
            (r, c), element = found
            cells = self.networks[index].footprint((r, c), element)
            self.selection = (index, Selection.spanning(cells[0], cells[-1]))
        self._place_overlays()

    def open_function_dialog(
        self, index: int, row: int, col: int, name: str, box: FunctionBox | None = None
    ) -> None:
        """The function property table; on OK the box is placed (or its parameters set)."""
        spec = box.spec if box is not None else lookup(name)
        if spec is None:
            return
        current = Instruction(box.name, params=box.params) if box is not None else None
        dialect = self.document.origin.dialect if self.document.origin is not None else "seed"
        dialog = FunctionDialog(spec, current, self, box.comment if box is not None else "",
                                dialect)
        self.function_dialog = dialog

        def done() -> None:
            instruction = dialog.instruction
            if instruction is None:
                return
            if box is None:
                element = FunctionBox.new(spec.name, instruction.params, dialog.comment_text)
                self.run_edit(
                    index,
                    lambda n: core.place_wired(n, row, col, element),
                    translate("LadderEditor", "Place {0}").format(spec.name),
                )
            else:
                self.undo_stack.beginMacro(
                    translate("LadderEditor", "Parameters of {0}").format(spec.name))
                self.run_edit(
                    index,
                    lambda n: core.set_params(n, row, col, instruction.params),
                    translate("LadderEditor", "Parameters of {0}").format(spec.name),
                )
                if dialog.comment_text != box.comment:
                    self.run_edit(
                        index,
                        lambda n: core.set_comment(n, row, col, dialog.comment_text),
                        translate("LadderEditor", "Comment"),
                    )
                self.undo_stack.endMacro()
            self.setFocus()

        dialog.accepted.connect(done)
        dialog.open()

    # -- in-place editing ---------------------------------------------------------------------

    def open_address_editor(self, index: int, row: int, col: int) -> None:
        """Edit the address (and `// comment`) of the contact or coil at a cell."""
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return
        element = found[1]
        text = str(element.address) if element.address is not None else ""
        if element.comment:
            text += "  // " + element.comment
        x, y = cell_origin(self.networks[index], row, col)
        rect = QRectF(x - 10, self.layout_.tops[index] + y, CELL_W + 60, 24)
        self._open_inline(
            ("address", index, row, col),
            text,
            rect,
            translate("LadderEditor", "Address or symbol, e.g. X2.1 (// comment)"),
        )

    def open_comment_editor(self, index: int, line: int) -> None:
        """Edit (or add) network comment line `line` (the comment tool)."""
        net = self.networks[index]
        text = net.comments[line] if line < len(net.comments) else ""
        rect = QRectF(
            LEFT, self.layout_.tops[index] + line * COMMENT_H, (net.columns + 1) * CELL_W, 24
        )
        self._open_inline(
            ("comment", index, line, 0), text, rect, translate("LadderEditor", "Comment")
        )

    def _open_inline(
        self, target: tuple[str, int, int, int], text: str, rect: QRectF, placeholder: str
    ) -> None:
        self._inline_target = target
        self.ensureVisible(rect, 20, 20)
        top_left = self.mapFromScene(rect.topLeft())
        width = int(rect.width() * self._zoom)
        self.inline_editor.setGeometry(top_left.x(), top_left.y(), max(width, 140), 26)
        self.inline_editor.setPlaceholderText(placeholder)
        self.inline_editor.setText(text)
        self.inline_editor.selectAll()
        self.inline_message.hide()
        self.inline_editor.show()
        self.inline_editor.setFocus()

    def _close_inline(self) -> None:
        self._inline_target = None
        self.inline_editor.hide()
        self.inline_message.hide()
        if self.inline_editor.hasFocus():
            self.setFocus()

    def _refuse_inline(self, diagnostic: Diagnostic) -> None:
        text = diagnostic_text(diagnostic)
        self.inline_message.setText(text)
        self.inline_message.adjustSize()
        geometry = self.inline_editor.geometry()
        self.inline_message.move(geometry.left(), geometry.bottom() + 2)
        self.inline_message.show()
        self.inline_message.raise_()
        self.message.emit(text)

    def _commit_inline(self) -> None:
        target = self._inline_target
        if target is None:
            return
        kind, index, row, col = target
        text = self.inline_editor.text()
        if kind == "comment":
            self._commit_comment(index, row, text)
            return
        address_text, _, comment = text.partition("//")
        address_text = address_text.strip()
        comment = comment.strip()
        if not address_text:
            self._close_inline()
            return
        address_text = self.resolve_address(address_text)
        try:
            core.edits.to_address(address_text, (row, col))
        except EditRefused as refused:
            self._refuse_inline(refused.diagnostic)
            return
        found = self.networks[index].element_at(row, col)
        assert found is not None
        element = found[1]
        assert isinstance(element, Contact | Coil)
        self.undo_stack.beginMacro(translate("LadderEditor", "Address {0}").format(address_text))
        self.run_edit(
            index,
            lambda n: core.set_address(n, row, col, address_text),
            translate("LadderEditor", "Address"),
        )
        if comment != element.comment:
            self.run_edit(
                index,
                lambda n: core.set_comment(n, row, col, comment),
                translate("LadderEditor", "Comment"),
            )
        self.undo_stack.endMacro()
        self._close_inline()

    def _commit_comment(self, index: int, line: int, text: str) -> None:
        lines = list(self.networks[index].comments)
        if line < len(lines):
            if text.strip():
                lines[line] = text.rstrip()
            else:
                del lines[line]
        elif text.strip():
            lines.append(text.rstrip())
        else:
            self._close_inline()
            return
        self._close_inline()
        self.run_edit(
            index,
            lambda n: core.set_network_comments(n, lines),
            translate("LadderEditor", "Comment"),
        )

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """ENTER in the inline editor commits it, ESC cancels it."""
        if watched is self.inline_editor and event.type() == QEvent.Type.KeyPress:
            assert isinstance(event, QKeyEvent)
            if event.key() == Qt.Key.Key_Escape:
                self._close_inline()
                return True
            if event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
                # consumed here: an ignored ENTER would reach the grid and open the editor again
                self._commit_inline()
                return True
        return super().eventFilter(watched, event)

    # -- actions on the cursor (menus, keys) --------------------------------------------------

    def _cursor_target(self) -> tuple[int, int, int]:
        if self.selection is not None:
            index, sel = self.selection
            return index, sel.top, sel.left
        return self.cursor_cell

    def edit_at_cursor(self) -> None:
        """ENTER: edit the element at the cursor (address, function table or comment)."""
        index, row, col = self.cursor_cell
        net = self.networks[index]
        found = net.element_at(row, col)
        if found is None:
            if self.tool is Tool.COMMENT:
                self.open_comment_editor(index, len(net.comments))
            return
        (r, c), element = found
        if isinstance(element, Contact | Coil):
            self.open_address_editor(index, r, c)
        elif isinstance(element, FunctionBox):
            self.open_function_dialog(index, r, c, element.name, element)

    def delete_at_cursor(self) -> None:
        """DEL: delete the selection or the element at the cursor."""
        if self.selection is not None:
            index, sel = self.selection
            text = translate("LadderEditor", "Delete")
            try:
                _, undo_edit = core.cut(self.networks[index], sel)
            except EditRefused as refused:
                self.message.emit(diagnostic_text(refused.diagnostic))
                return
            self.undo_stack.push(NetworkEditCommand(self, index, undo_edit, text))
            self.selection = None
            self._place_overlays()
            return
        index, row, col = self.cursor_cell
        self.run_edit(
            index, lambda n: core.delete(n, row, col), translate("LadderEditor", "Delete")
        )

    def invert_at_cursor(self) -> None:
        """NOT on the element at the cursor."""
        index, row, col = self._cursor_target()
        self.run_edit(index, lambda n: core.invert(n, row, col), translate("LadderEditor", "NOT"))

    def or_at_cursor(self) -> None:
        """OR on the element at the cursor (a parallel contact or coil)."""
        index, row, col = self._cursor_target()
        self._add_parallel(index, row, col)

    def insert_row_before(self) -> None:
        """Insert an empty row before the cursor's row."""
        index, row, _ = self.cursor_cell
        self.run_edit(
            index, lambda n: core.insert_row(n, row), translate("LadderEditor", "Insert row")
        )

    def insert_row_after(self) -> None:
        """Insert an empty row after the cursor's row."""
        index, row, _ = self.cursor_cell
        self.run_edit(
            index,
            lambda n: core.insert_row(n, row, after=True),
            translate("LadderEditor", "Insert row"),
        )

    def copy(self) -> None:
        """Copy the selection (or the element at the cursor) to the clipboard as grid text."""
        index, sel = self._selection_or_cursor()
        QApplication.clipboard().setText(core.copy_text(self.networks[index], sel))

    def cut(self) -> None:
        """Cut the selection (or the element at the cursor)."""
        index, sel = self._selection_or_cursor()
        try:
            text, undo_edit = core.cut(self.networks[index], sel)
        except EditRefused as refused:
            self.message.emit(diagnostic_text(refused.diagnostic))
            return
        QApplication.clipboard().setText(text)
        self.undo_stack.push(
            NetworkEditCommand(self, index, undo_edit, translate("LadderEditor", "Cut"))
        )
        self.selection = None
        self._place_overlays()

    def paste(self) -> None:
        """Paste grid text with its top-left at the cursor."""
        text = QApplication.clipboard().text()
        if not text:
            return
        index, row, col = self.cursor_cell
        self.run_edit(
            index, lambda n: core.paste(n, row, col, text), translate("LadderEditor", "Paste")
        )

    def delete_network(self) -> None:
        """Delete the network at the cursor."""
        index = self.cursor_cell[0]
        if index >= len(self.networks) - 1:
            return
        self.undo_stack.push(
            NetworkListCommand(self, index, None, translate("LadderEditor", "Delete network"))
        )

    def _selection_or_cursor(self) -> tuple[int, Selection]:
        if self.selection is not None:
            return self.selection
        index, row, col = self.cursor_cell
        found = self.networks[index].element_at(row, col)
        if found is not None:
            cells = self.networks[index].footprint(*found)
            return index, Selection.spanning(cells[0], cells[-1])
        return index, Selection(row, col, row, col)

    # -- cursor, overlays, positions ----------------------------------------------------------

    def cell_rect(self, index: int, row: int, col: int) -> QRectF:
        """A cell's rectangle in scene coordinates."""
        x, y = cell_origin(self.networks[index], row, col)
        return QRectF(x, self.layout_.tops[index] + y, CELL_W, cell_h())

    def cell_point(self, index: int, row: int, col: int) -> QPoint:
        """Viewport point at a cell's centre (scrolled into view first)."""
        x, y = cell_centre(self.networks[index], row, col)
        scene = QPointF(x, self.layout_.tops[index] + y)
        self.ensureVisible(QRectF(scene.x() - 60, scene.y() - 60, 120, 120), 10, 10)
        return self.mapFromScene(scene)

    def node_point(self, index: int, row: int, node: int) -> QPoint:
        """Viewport point at a grid node (left edge of column `node`, middle of `row`)."""
        x, y = node_point(self.networks[index], row, node)
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
        self._place_overlays()
        self.ensureVisible(self.cell_rect(index, row, col), 20, 20)
        self.hover_changed.emit(self.describe_cell(index, row, col))

    def _place_overlays(self) -> None:
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

    def go_to(self, diagnostic: Diagnostic) -> None:
        """Jump to a diagnostic's network and cell."""
        if diagnostic.network is not None and diagnostic.network >= len(self.networks) - 1:
            self.finish_loading()
        if diagnostic.network is None or not 0 <= diagnostic.network < len(self.networks):
            return
        row, col = diagnostic.cell if diagnostic.cell is not None else (0, 0)
        self.move_cursor(diagnostic.network, row, col)
        self.setFocus()

    def tooltip_at(self, index: int, row: int, col: int) -> str:
        """Tooltip of a cell's contact or coil: address, symbol, its comments; else ""."""
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil) or found[1].address is None:
            return ""
        element = found[1]
        address = element.address
        if address is None:
            return ""
        text = tooltip(address, self.symbols)
        return text + (f"\n// {element.comment}" if element.comment else "")

    def describe_cell(self, index: int, row: int, col: int) -> str:
        """Status-bar text: the cell, and the address with its signal name and comment."""
        parts = [
            translate("LadderEditor", "N{0} row {1} col {2}").format(index + 1, row + 1, col + 1)
        ]
        if self.networks[index].label:
            parts.append(self.networks[index].label)
        found = self.networks[index].element_at(row, col)
        if found is not None:
            element = found[1]
            if isinstance(element, Contact | Coil) and element.address is not None:
                parts.append(str(element.address))
                described = self.describe_address(element.address)
                if described is not None:
                    parts.append(" — ".join(text for text in described if text))
                if element.comment:
                    parts.append(element.comment)
            elif isinstance(element, FunctionBox):
                parts.append(print_instruction(Instruction(element.name, params=element.params)))
        return "  |  ".join(parts)

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

    def _set_zoom(self, factor: float) -> None:
        self._zoom = min(max(factor, ZOOM_MIN), ZOOM_MAX)
        self.resetTransform()
        self.scale(self._zoom, self._zoom)
        self._close_inline()

    # -- events -------------------------------------------------------------------------------

    def _hit(self, pos: QPoint) -> Hit:
        scene = self.mapToScene(pos)
        return self.layout_.hit(self.networks, scene.x(), scene.y())

    def mousePressEvent(self, event: QMouseEvent) -> None:
        """Click: move the cursor there and use the current tool."""
        if self._inline_target is not None:
            self._close_inline()
        hit = self._hit(event.position().toPoint())
        if event.button() == Qt.MouseButton.LeftButton:
            self.setFocus()
            self.cursor_cell = (hit.network, hit.row, hit.col)
            self.apply_tool(hit)
            self._shift_anchor = None
            if self.tool is Tool.SELECT and hit.comment_line is None:
                self._drag_origin = (hit.network, hit.row, hit.col)
            index = min(self.cursor_cell[0], len(self.networks) - 1)
            net = self.networks[index]
            self.cursor_cell = (
                index,
                min(self.cursor_cell[1], net.rows - 1 + SPARE_ROWS),
                min(self.cursor_cell[2], net.columns),
            )
            self._place_overlays()
            event.accept()
            return
        if event.button() == Qt.MouseButton.RightButton:
            net = self.networks[hit.network]
            self.cursor_cell = (hit.network, min(hit.row, max(net.rows - 1, 0)), hit.col)
            self._select(*self.cursor_cell)
            event.accept()
            return
        super().mousePressEvent(event)

    def select_rectangle(self, index: int, corner: tuple[int, int],
                         other: tuple[int, int]) -> None:
        """Select the cells between two corners of one network (rows and columns clamped)."""
        net = self.networks[index]
        last_row = max(net.rows - 1, 0)

        def clamp(cell: tuple[int, int]) -> tuple[int, int]:
            return min(max(cell[0], 0), last_row), min(max(cell[1], 0), net.columns)

        self.selection = (index, Selection.spanning(clamp(corner), clamp(other)))
        self._place_overlays()

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        """Report the cell under the mouse; with the select tool, a drag selects a rectangle."""
        hit = self._hit(event.position().toPoint())
        origin = self._drag_origin
        if (origin is not None and hit.network == origin[0] and hit.comment_line is None
                and (hit.row, hit.col) != origin[1:]):
            self.select_rectangle(origin[0], origin[1:], (hit.row, hit.col))
        if hit.comment_line is None:
            net = self.networks[hit.network]
            if hit.row < net.rows:
                self.hover_changed.emit(self.describe_cell(hit.network, hit.row, hit.col))
                self.viewport().setToolTip(self.tooltip_at(hit.network, hit.row, hit.col))
        super().mouseMoveEvent(event)

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        """End a drag selection."""
        self._drag_origin = None
        super().mouseReleaseEvent(event)

    def mouseDoubleClickEvent(self, event: QMouseEvent) -> None:
        """Double-click edits the element (in the select tool)."""
        if self.tool is Tool.SELECT:
            hit = self._hit(event.position().toPoint())
            self.cursor_cell = (hit.network, hit.row, hit.col)
            self.edit_at_cursor()
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
        menu.exec(event.globalPos())

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Arrows move, letters pick tools, ENTER edits, SPACE uses the tool, DEL deletes."""
        key = event.key()
        index, row, col = self.cursor_cell
        net = self.networks[index]
        moves = {
            Qt.Key.Key_Left: (0, -1),
            Qt.Key.Key_Right: (0, 1),
            Qt.Key.Key_Up: (-1, 0),
            Qt.Key.Key_Down: (1, 0),
        }
        if key in moves and event.modifiers() & Qt.KeyboardModifier.ShiftModifier:
            drow, dcol = moves[Qt.Key(key)]
            if self._shift_anchor is None or self._shift_anchor[0] != index:
                self._shift_anchor = (index, row, col)
            self.move_cursor(index, max(row + drow, 0), max(col + dcol, 0))
            self.select_rectangle(index, self._shift_anchor[1:], self.cursor_cell[1:])
            return
        if key not in (Qt.Key.Key_Shift, Qt.Key.Key_Control, Qt.Key.Key_Alt, Qt.Key.Key_Meta):
            self._shift_anchor = None  # any other key ends a Shift+arrows selection
        if key in moves:
            drow, dcol = moves[Qt.Key(key)]
            row += drow
            col += dcol
            if row < 0 and index > 0:
                index -= 1
                row = self.networks[index].rows - 1
            elif row >= net.rows + SPARE_ROWS and index < len(self.networks) - 1:
                index += 1
                row = 0
            self.move_cursor(index, row, col)
            return
        if key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.edit_at_cursor()
            return
        if key == Qt.Key.Key_Space:
            node = col
            self.apply_tool(Hit(index, row, col, node))
            return
        if key in (Qt.Key.Key_Delete, Qt.Key.Key_Backspace):
            self.delete_at_cursor()
            return
        if key == Qt.Key.Key_Escape:
            self.line_start = None
            self._line_item.hide()
            self.selection = None
            self._place_overlays()
            self.tool_requested.emit(Tool.SELECT)
            return
        text = event.text().upper()
        if text in KEY_TOOLS and not event.modifiers() & (
            Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.AltModifier
        ):
            self.tool_requested.emit(KEY_TOOLS[text])
            return
        super().keyPressEvent(event)

    def changeEvent(self, event: QEvent) -> None:
        """Repaint signal descriptions in the new language."""
        if event.type() == QEvent.Type.LanguageChange:
            self.viewport().update()
        super().changeEvent(event)


__all__ = ["LadderEditor", "describe_signal", "grid_top"]
