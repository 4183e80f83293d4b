"""One network drawn as a single scene item: rails, contacts, coils, wires, boxes, comments."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPainter, QPen
from PySide6.QtWidgets import QGraphicsItem, QStyleOptionGraphicsItem, QWidget

from ladderworks.core.dialects.spelling import Spelling
from ladderworks.core.dialects.spelling import spelling as spelling_of
from ladderworks.core.ladder import row_contacts
from ladderworks.core.ladder.model import (
    Coil,
    Contact,
    FunctionBox,
    LadderNetwork,
    Wire,
    coil_mark,
)
from ladderworks.core.ladder.open_circuit import OpenEnd, open_ends
from ladderworks.gui.editor.geometry import (
    CELL_W,
    COMMENT_H,
    LEFT,
    LISTING_LINE_H,
    cell_origin,
    grid_top,
    name_display,
    network_height,
    network_rows,
    network_width,
)
from ladderworks.gui.editor.label_text import (
    CommentedAddresses,
    SignalLookup,
    shows_comment,
    wrapped,
)
from ladderworks.gui.editor.pin_paint import paint_named_box
from ladderworks.gui.translation import instruction_label, ui_is_turkish

INK = QColor("#1a1a1a")
RAIL = QColor("#1f4e79")
COMMENT = QColor("#2e7d32")
NAME = QColor("#5b5b5b")
ERROR = QColor("#d32f2f")
BOX_FILL = QColor("#eef3fb")
NOT_SIMULATED = QColor("#b58900")  # the frame of an element kept but not simulated
EMPTY_HINT = QColor("#9e9e9e")
COMMENT_LINE_H = 12.0  # a wrapped comment line under an element


def _fonts() -> tuple[QFont, QFont, QFont]:
    label = QFont()
    label.setPointSizeF(9.5)
    label.setBold(True)
    small = QFont()
    small.setPointSizeF(7.5)
    comment = QFont()
    comment.setPointSizeF(9)
    comment.setItalic(True)
    return label, small, comment


def _element_comment_font() -> QFont:
    font = QFont()
    font.setPointSizeF(7.5)
    font.setItalic(True)
    return font


def network_tag(number: int) -> str:
    """A network's number beside its rail: N1 (network), D1 in Turkish (devre), as the status
    bar and the error list name it."""
    return QCoreApplication.translate("LadderEditor", "N{0}").format(number)


def fitted_font(font: QFont, text: str, width: float) -> QFont:
    """`font`, or a smaller copy of it in which `text` fits `width` (a large system font)."""
    wide = QFontMetricsF(font).horizontalAdvance(text)
    if wide <= width:
        return font
    smaller = QFont(font)
    smaller.setPointSizeF(max(5.0, font.pointSizeF() * width / wide))
    return smaller


class NetworkItem(QGraphicsItem):
    """Paints one LadderNetwork; its number and hints come from the view."""

    # how addresses, boxes and listings are written: the program's dialect's (Delta: X17),
    # set by whoever makes the item for a program of another dialect than the PMC's
    spelling: Spelling = spelling_of(None)

    def __init__(self, network: LadderNetwork, number: int, describe: SignalLookup) -> None:
        super().__init__()
        self.network = network
        self.number = number
        self.describe = describe
        self.error_cells: set[tuple[int, int]] = set()
        self.is_new = False  # the empty network at the end, where a new one is drawn
        self.open_ends: list[OpenEnd] = open_ends(network)  # breaks marked as the user draws
        # what is written with each element, by display and language (wrapping costs)
        self._label_cache: dict[tuple[object, ...], tuple[str, str, list[str]]] = {}
        self.rows = network_rows(network, self.commented)
        self._size = (network_width(network), network_height(network, self.rows))
        self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemUsesExtendedStyleOption, True)

    def commented(self, network: LadderNetwork) -> bool:
        """True when an element of `network` has a comment to show (taller rows)."""
        return shows_comment(network, CommentedAddresses(self.describe))

    def refresh(self) -> None:
        """The network changed (or the rows did): recompute the marks, rows and size, repaint."""
        self.open_ends = open_ends(self.network)
        self._label_cache.clear()
        self.rows = network_rows(self.network, self.commented)
        size = (network_width(self.network), network_height(self.network, self.rows))
        if size != self._size:
            self.prepareGeometryChange()
            self._size = size
        self.update()

    def boundingRect(self) -> QRectF:
        """The item's extent."""
        return QRectF(0, 0, self._size[0], self._size[1])

    def paint(self, painter: QPainter, option: QStyleOptionGraphicsItem,
              widget: QWidget | None = None) -> None:
        """Draw the network."""
        net = self.network
        rows = self.rows
        label_font, small_font, comment_font = _fonts()
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        painter.setFont(comment_font)
        painter.setPen(COMMENT)
        for index, line in enumerate(net.comments):
            painter.drawText(QRectF(LEFT, index * COMMENT_H, self._size[0] - LEFT, COMMENT_H),
                             Qt.AlignmentFlag.AlignVCenter, "// " + line)
        top = grid_top(net)
        tag = "+" if self.is_new else network_tag(self.number)
        painter.setFont(fitted_font(label_font, tag, LEFT - 10))
        painter.setPen(EMPTY_HINT if self.is_new else RAIL)
        painter.drawText(QRectF(0, top, LEFT - 8, rows.wire),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, tag)
        if net.listing is not None:
            self._paint_listing(painter, top)
            return
        bottom = top + net.rows * rows.height
        right = LEFT + (net.columns + 1) * CELL_W
        rail = QPen(EMPTY_HINT if self.is_new else RAIL, 3)
        painter.setPen(rail)
        painter.drawLine(QPointF(LEFT, top), QPointF(LEFT, bottom))
        painter.drawLine(QPointF(right, top), QPointF(right, bottom))
        if self.is_new and net.is_empty():
            grid = QPen(QColor("#e0e0e0"), 1, Qt.PenStyle.DotLine)
            painter.setPen(grid)
            for col in range(1, net.columns + 1):
                painter.drawLine(QPointF(LEFT + col * CELL_W, top), QPointF(LEFT + col * CELL_W,
                                                                          bottom))
        ink = QPen(INK, 1.6)
        painter.setPen(ink)
        for row, node in net.links:
            x = LEFT + node * CELL_W
            y1 = top + row * rows.height + rows.wire
            painter.drawLine(QPointF(x, y1), QPointF(x, y1 + rows.height))
        exposed = option.exposedRect
        for (row, col), element in net.elements():
            x, y = cell_origin(net, row, col, rows)
            if not exposed.intersects(QRectF(x - CELL_W, y, CELL_W * 4, rows.height * 8)):
                continue
            painter.setPen(ink)
            if isinstance(element, Wire):
                painter.drawLine(QPointF(x, y + rows.wire), QPointF(x + CELL_W, y + rows.wire))
            elif isinstance(element, Contact):
                self._paint_contact(painter, element, x, y, label_font, small_font)
            elif isinstance(element, Coil):
                self._paint_coil(painter, element, x, y, col, label_font, small_font)
            elif isinstance(element, FunctionBox):
                self._paint_box(painter, element, x, y, label_font, small_font)
        if self.error_cells:
            painter.setPen(QPen(ERROR, 2, Qt.PenStyle.DashLine))
            painter.setBrush(Qt.BrushStyle.NoBrush)
            for row, col in self.error_cells:
                x, y = cell_origin(net, row, col, rows)
                painter.drawRect(QRectF(x + 2, y + 2, CELL_W - 4, rows.height - 4))
        if self.open_ends and not self.is_new:
            self._paint_open_ends(painter)

    def _paint_open_ends(self, painter: QPainter) -> None:
        """A red dashed gap across an empty cell where the circuit breaks, or a red bar and
        cross on the open side of an element."""
        mid = self.rows.wire
        for mark in self.open_ends:
            x, y = cell_origin(self.network, *mark.cell, self.rows)
            if mark.gap:
                painter.setPen(QPen(ERROR, 2, Qt.PenStyle.DashLine))
                painter.drawLine(QPointF(x + 4, y + mid), QPointF(x + CELL_W - 4, y + mid))
                centre = QPointF(x + CELL_W / 2, y + mid)
            else:
                centre = QPointF(x + (3 if mark.side == "left" else CELL_W - 3), y + mid)
            painter.setPen(QPen(ERROR, 2))
            painter.drawLine(centre + QPointF(-4, -4), centre + QPointF(4, 4))
            painter.drawLine(centre + QPointF(-4, 4), centre + QPointF(4, -4))

    def label_lines(self, element: Contact | Coil) -> tuple[str, str, list[str]]:
        """(address, symbol, comment lines) drawn with an element, as the View chooses: the
        symbol is the program's (else the manual's signal name); the comment is the element's
        own, else the program's comment of the address, else the manual's text, wrapped to
        the cell in up to two lines."""
        key = (element, name_display(), self.rows, ui_is_turkish())
        cached = self._label_cache.get(key)
        if cached is None:
            cached = self._label_cache[key] = self._label_lines(element)
        return cached

    def _label_lines(self, element: Contact | Coil) -> tuple[str, str, list[str]]:
        if element.texts or (isinstance(element, Coil) and element.mark):  # as written
            first = element.texts[0] if element.texts else ""
            below = " ".join(element.texts[1:])
            if not below and element.address is not None:  # "Start" over its %I0.0
                below = self.spelling.address(element.address)
            if not self.rows.symbol:
                return first, "", []
            return first, below, []
        if isinstance(element, Contact) and element.function:  # operands above / below
            texts = row_contacts.operand_texts(element, self.spelling)
            if not self.rows.symbol:  # no line under the element: both above
                return " ".join(texts), "", []
            return texts[0] if texts else "", " ".join(texts[1:]), []
        address = self.spelling.address(element.address) if element.address is not None else "?"
        rows = self.rows
        if not rows.symbol:
            return address, "", []
        described = self.describe(element.address) if element.address is not None else None
        symbol = described[0] if described is not None else ""
        comment = element.comment or (described[1] if described is not None else "")
        if rows.comment_lines == 0:  # the symbol, else the element's comment, on one line
            return address, symbol or element.comment, []
        lines = wrapped(comment, QFontMetricsF(_element_comment_font()), CELL_W - 6,
                        rows.comment_lines) if comment else []
        return address, symbol, lines

    def _labels(self, painter: QPainter, element: Contact | Coil, x: float, y: float,
                label_font: QFont, small_font: QFont) -> None:
        """The address above the element; its symbol and comment lines under it."""
        address, symbol, lines = self.label_lines(element)
        painter.setFont(fitted_font(label_font, address, CELL_W - 2))
        painter.setPen(INK if element.address is not None or element.texts
                       or (isinstance(element, Contact) and element.function) else ERROR)
        painter.drawText(QRectF(x, y + 1, CELL_W, 16), Qt.AlignmentFlag.AlignCenter, address)
        below = y + self.rows.wire + 12
        if symbol:
            metrics = QFontMetricsF(small_font)
            painter.setFont(small_font)
            painter.setPen(NAME)
            painter.drawText(QRectF(x + 2, below, CELL_W - 4, 13), Qt.AlignmentFlag.AlignCenter,
                             metrics.elidedText(symbol, Qt.TextElideMode.ElideRight, CELL_W - 4))
        below += 13
        if lines:
            painter.setFont(_element_comment_font())
            painter.setPen(COMMENT)
            for index, line in enumerate(lines):
                painter.drawText(QRectF(x + 1, below + index * COMMENT_LINE_H, CELL_W - 2,
                                        COMMENT_LINE_H), Qt.AlignmentFlag.AlignCenter, line)

    def _paint_contact(self, painter: QPainter, element: Contact, x: float, y: float,
                       label_font: QFont, small_font: QFont) -> None:
        mid = y + self.rows.wire
        half = 20 if "\n" in element.mark else 8  # a comparison over its type: wider
        left, right = x + CELL_W / 2 - half, x + CELL_W / 2 + half
        painter.drawLine(QPointF(x, mid), QPointF(left, mid))
        painter.drawLine(QPointF(right, mid), QPointF(x + CELL_W, mid))
        painter.drawLine(QPointF(left, mid - 11), QPointF(left, mid + 11))
        painter.drawLine(QPointF(right, mid - 11), QPointF(right, mid + 11))
        if element.negated:
            painter.drawLine(QPointF(left - 3, mid + 11), QPointF(right + 3, mid - 11))
        if element.function:  # ↑ / ↓ of an edge, the operator of a comparison
            mark = row_contacts.shown_mark(element)  # a source's own: P, >= over its type
            painter.setFont(fitted_font(small_font, max(mark.split("\n"), key=len),
                                        right - left + 10))
            painter.drawText(QRectF(left - 6, mid - 11, right - left + 12, 22),
                             Qt.AlignmentFlag.AlignCenter, mark)
            if not row_contacts.simulated(element.function):  # kept, not run: amber frame
                pen = painter.pen()
                painter.setPen(QPen(NOT_SIMULATED, 1.5, Qt.PenStyle.DashLine))
                painter.drawRect(QRectF(left - 4, mid - 14, right - left + 8, 28))
                painter.setPen(pen)
        self._labels(painter, element, x, y, label_font, small_font)

    def _paint_coil(self, painter: QPainter, element: Coil, x: float, y: float, col: int,
                    label_font: QFont, small_font: QFont) -> None:
        mid = y + self.rows.wire
        mark = coil_mark(element)  # (S) / (R), as LADDER-III draws them; Fatek's (L)
        half = 10 if len(mark) < 2 else 20  # a word in it (S7's JMP, RET, PT): wider
        left, right = x + CELL_W / 2 - half, x + CELL_W / 2 + half
        painter.drawLine(QPointF(x, mid), QPointF(left, mid))
        end = x + CELL_W if col >= self.network.columns else right + 6
        painter.drawLine(QPointF(right, mid), QPointF(end, mid))
        painter.drawArc(QRectF(left, mid - 11, 14, 22), 100 * 16, 160 * 16)
        painter.drawArc(QRectF(right - 14, mid - 11, 14, 22), -80 * 16, 160 * 16)
        if element.negated:
            painter.drawLine(QPointF(left, mid + 11), QPointF(right, mid - 11))
        if mark:
            painter.setFont(fitted_font(label_font if len(mark) < 2 else small_font, mark,
                                        right - left - 4))
            painter.drawText(QRectF(left, mid - 9, right - left, 18), Qt.AlignmentFlag.AlignCenter,
                             mark)
        self._labels(painter, element, x, y, label_font, small_font)

    def _paint_box(self, painter: QPainter, box: FunctionBox, x: float, y: float,
                   label_font: QFont, small_font: QFont) -> None:
        rows = self.rows
        if box.named:  # drawn from a source's graph: TIA's pins and operands
            paint_named_box(painter, box, x, y, rows, label_font, small_font, BOX_FILL)
            return
        width = box.width * CELL_W
        height = box.height * rows.height
        rect = QRectF(x + 10, y + 6, width - 20, height - 12)
        painter.setBrush(BOX_FILL)
        if box.spec.simulated:
            painter.drawRect(rect)
        else:  # kept and drawn, not run by the simulator: a dashed amber frame
            pen = painter.pen()
            painter.setPen(QPen(NOT_SIMULATED, 1.5, Qt.PenStyle.DashLine))
            painter.drawRect(rect)
            painter.setPen(pen)
        painter.setBrush(Qt.BrushStyle.NoBrush)
        painter.setFont(small_font)
        for index, name in enumerate(box.inputs):
            pin = box.pins[index] if index < len(box.pins) else index
            py = y + pin * rows.height + rows.wire
            painter.drawLine(QPointF(x, py), QPointF(x + 10, py))
            painter.drawText(QRectF(x + 12, py - 7, 60, 14), Qt.AlignmentFlag.AlignLeft, name)
        if box.has_output:
            py = y + rows.wire
            painter.drawLine(QPointF(x + width - 10, py), QPointF(x + width, py))
            painter.drawText(QRectF(x + width - 40, py - 7, 28, 14),
                             Qt.AlignmentFlag.AlignRight, "W1")
        for offset, contact in box.outputs:  # its further output pins (Fatek's FO1, FO2 …)
            py = y + offset * rows.height + rows.wire
            painter.drawLine(QPointF(x + width - 10, py), QPointF(x + width, py))
            painter.drawText(QRectF(x + width - 40, py - 7, 28, 14),
                             Qt.AlignmentFlag.AlignRight, box.output_label(contact))
        painter.setFont(label_font)
        painter.drawText(QRectF(rect.left(), rect.top() + 2, rect.width(), 16),
                         Qt.AlignmentFlag.AlignHCenter,
                         self.spelling.name(box.spec) if self.spelling.dialect
                         else instruction_label(box.spec))
        params = " ".join(self.spelling.params(box.spec, box.params))
        painter.setFont(small_font)
        metrics = QFontMetricsF(small_font)
        if params:
            painter.drawText(QRectF(rect.left() + 4, rect.bottom() - 16, rect.width() - 8, 14),
                             Qt.AlignmentFlag.AlignHCenter,
                             metrics.elidedText(params, Qt.TextElideMode.ElideRight,
                                                rect.width() - 8))
        if box.comment and rows.symbol:
            pen = painter.pen()
            painter.setPen(NAME)
            for index, line in enumerate(wrapped(box.comment, metrics, rect.width() - 8,
                                                 max(1, rows.comment_lines))):
                painter.drawText(QRectF(rect.left() + 4, rect.top() + 18 + index * 12,
                                        rect.width() - 8, 12),
                                 Qt.AlignmentFlag.AlignHCenter, line)
            painter.setPen(pen)

    def _paint_listing(self, painter: QPainter, top: float) -> None:
        painter.setPen(QPen(EMPTY_HINT, 1, Qt.PenStyle.DashLine))
        height = max(len(self.network.listing or ()), 1) * LISTING_LINE_H
        painter.drawRect(QRectF(LEFT, top, self._size[0] - LEFT - 8, height + 4))
        painter.setPen(INK)
        font = QFont("monospace")
        font.setStyleHint(QFont.StyleHint.Monospace)
        font.setPointSizeF(9)
        painter.setFont(font)
        for index, instruction in enumerate(self.network.listing or ()):
            painter.drawText(QRectF(LEFT + 6, top + 2 + index * LISTING_LINE_H, 800,
                                    LISTING_LINE_H), Qt.AlignmentFlag.AlignVCenter,
                             self.spelling.instruction(instruction))
