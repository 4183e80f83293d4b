"""Live power flow painted over a network drawing: green wires, contacts, coils and boxes."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QPainter, QPen
from PySide6.QtWidgets import QGraphicsItem, QStyleOptionGraphicsItem, QWidget

from ladderworks.core.address import Address
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork, Wire
from ladderworks.gui.docks.cell_map import NetworkPower
from ladderworks.gui.editor.geometry import (
    CELL_W,
    LEFT,
    RowMetrics,
    cell_origin,
    grid_top,
    network_height,
    network_width,
)
from ladderworks.gui.editor.pin_paint import BOX_TOP

LIVE = QColor("#00a000")
LIVE_FILL = QColor(0, 200, 0, 70)
PASSIVE = QColor("#757575")
FORCED = QColor("#e65100")
FOUND = QColor("#1565c0")
MONITORED = QColor("#00796b")  # a box pin's live value (S7 monitoring)

translate = QCoreApplication.translate

# Value shown inside a function box for one parameter address (None: not shown).
ValueText = Callable[[Address], str | None]


class PowerOverlay(QGraphicsItem):
    """Paints one network's live state on top of its NetworkItem (same position and size)."""

    def __init__(self, network: LadderNetwork, rows: RowMetrics) -> None:
        super().__init__()
        self.network = network
        self.rows = rows  # the network's rows, as its drawing has them
        self.power = NetworkPower()
        self.values: dict[tuple[int, int], list[str]] = {}  # box anchor -> parameter values
        self.marked: set[tuple[int, int]] = set()  # cells found by a search
        self.setZValue(5)
        self.setAcceptedMouseButtons(Qt.MouseButton.NoButton)

    def boundingRect(self) -> QRectF:
        """Same extent as the network's drawing."""
        return QRectF(0, 0, network_width(self.network), network_height(self.network, self.rows))

    def set_rows(self, rows: RowMetrics) -> None:
        """The network's rows changed height (View › Element names)."""
        self.prepareGeometryChange()
        self.rows = rows
        self.update()

    def set_state(self, power: NetworkPower, values: dict[tuple[int, int], list[str]]) -> bool:
        """New live state; repaints (and returns True) only when something shown changed."""
        if power == self.power and values == self.values:
            return False
        self.power = power
        self.values = values
        self.update()
        return True

    def paint(self, painter: QPainter, option: QStyleOptionGraphicsItem,
              widget: QWidget | None = None) -> None:
        """Draw the energised parts in green, tags for PASİF and forced elements."""
        net = self.network
        if net.listing is not None:
            return
        power = self.power
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        top = grid_top(net)
        live = QPen(LIVE, 3.2)
        painter.setPen(live)
        if (0, 0) in power.nodes:
            painter.drawLine(QPointF(LEFT, top), QPointF(LEFT, top + net.rows * self.rows.height))
        for row, node in net.links:
            if (row, node) in power.nodes:
                x = LEFT + node * CELL_W
                y = top + row * self.rows.height + self.rows.wire
                painter.drawLine(QPointF(x, y), QPointF(x, y + self.rows.height))
        small = QFont()
        small.setPointSizeF(7.5)
        small.setBold(True)
        for (row, col), element in net.elements():
            x, y = cell_origin(net, row, col, self.rows)
            mid = y + self.rows.wire
            painter.setPen(live)
            painter.setBrush(Qt.BrushStyle.NoBrush)
            if isinstance(element, Wire):
                if (row, col) in power.nodes:
                    painter.drawLine(QPointF(x, mid), QPointF(x + CELL_W, mid))
            elif isinstance(element, Contact):
                self._contact(painter, row, col, x, y, mid, 20 if "\n" in element.mark else 8)
            elif isinstance(element, Coil):
                self._coil(painter, row, col, x, y, mid)
            elif isinstance(element, FunctionBox):
                self._box(painter, element, row, col, x, y, small)
            if (row, col) in power.disabled:
                self._tag(painter, x, y, translate("PlcDiagnostic", "PASSIVE"), PASSIVE, small)
            elif (row, col) in power.forced:
                self._tag(painter, x, y, f"F{power.forced[(row, col)]}", FORCED, small)
            if (row, col) in self.marked:
                painter.setPen(QPen(FOUND, 2.5))
                painter.setBrush(Qt.BrushStyle.NoBrush)
                painter.drawRoundedRect(QRectF(x + 1, y + 1, CELL_W - 2, self.rows.height - 2),
                                        4, 4)

    def _contact(self, painter: QPainter, row: int, col: int, x: float, y: float,
                 mid: float, half: float = 8) -> None:
        power = self.power
        left, right = x + CELL_W / 2 - half, x + CELL_W / 2 + half  # a comparison: wider
        if (row, col) in power.nodes:
            painter.drawLine(QPointF(x, mid), QPointF(left, mid))
        if (row, col) in power.closed:
            painter.fillRect(QRectF(left, mid - 11, right - left, 22), LIVE_FILL)
            painter.drawLine(QPointF(left, mid - 11), QPointF(left, mid + 11))
            painter.drawLine(QPointF(right, mid - 11), QPointF(right, mid + 11))
        if (row, col + 1) in power.nodes and (row, col) in power.nodes:
            painter.drawLine(QPointF(right, mid), QPointF(x + CELL_W, mid))

    def _coil(self, painter: QPainter, row: int, col: int, x: float, y: float,
              mid: float) -> None:
        left, right = x + CELL_W / 2 - 10, x + CELL_W / 2 + 10
        if (row, col) in self.power.nodes:
            painter.drawLine(QPointF(x, mid), QPointF(left, mid))
        if (row, col) in self.power.coils:
            painter.setBrush(QBrush(LIVE_FILL))
            painter.drawEllipse(QRectF(left, mid - 11, right - left, 22))
            painter.setBrush(Qt.BrushStyle.NoBrush)

    def _box(self, painter: QPainter, box: FunctionBox, row: int, col: int, x: float,
             y: float, small: QFont) -> None:
        width = box.width * CELL_W
        pins = self.power.box_pins.get((row, col), [])
        for index, on in enumerate(pins):
            if on:
                pin = box.pins[index] if index < len(box.pins) else index
                py = y + pin * self.rows.height + self.rows.wire
                painter.drawLine(QPointF(x, py), QPointF(x + 10, py))
        active = bool(pins) and pins[-1]  # ACT is the last control input
        top = 6.0
        if box.named:  # a source's box (S7): its main input first, under its instance
            active, top = bool(pins) and pins[0], BOX_TOP
        if active or (row, col) in self.power.box_out:
            painter.drawRect(QRectF(x + 10, y + top, width - 20,
                                    box.height * self.rows.height - top - 6))
        if (row, col) in self.power.box_out:
            py = y + self.rows.wire
            painter.drawLine(QPointF(x + width - 10, py), QPointF(x + width, py))
        values = self.values.get((row, col))
        if values and box.named:  # a source's box (S7): each pin's value beside its operand
            self._pin_values(painter, box, x, y, width, values, small)
        elif values:
            painter.setFont(small)
            painter.setPen(QPen(QColor("#004d40")))
            text = " ".join(values)
            painter.drawText(QRectF(x + 12, y + 20, width - 24, 14),
                             Qt.AlignmentFlag.AlignHCenter, text)

    def _pin_values(self, painter: QPainter, box: FunctionBox, x: float, y: float,
                    width: float, values: list[str], font: QFont) -> None:
        """Each named pin's live value under its operand: left of an input, right of an
        output (as TIA shows PT, ET, CV in monitoring)."""
        painter.setFont(font)
        painter.setPen(QPen(MONITORED))
        for pin, text in zip(box.named, values, strict=False):
            if not text:
                continue
            py = y + pin.row * self.rows.height + self.rows.wire
            if pin.output:
                rect = QRectF(x + width + 3, py + 1, CELL_W - 6, 13)
                align = Qt.AlignmentFlag.AlignLeft
            else:
                rect = QRectF(x - CELL_W + 2, py + 1, CELL_W - 6, 13)
                align = Qt.AlignmentFlag.AlignRight
            painter.drawText(rect, align | Qt.AlignmentFlag.AlignTop, text)

    def _tag(self, painter: QPainter, x: float, y: float, text: str, colour: QColor,
             font: QFont) -> None:
        painter.setFont(font)
        rect = QRectF(x + CELL_W - 44, y + 17, 42, 13)
        painter.setPen(Qt.PenStyle.NoPen)
        painter.setBrush(QBrush(colour))
        painter.drawRoundedRect(rect, 3, 3)
        painter.setPen(QPen(QColor("#ffffff")))
        painter.drawText(rect, Qt.AlignmentFlag.AlignCenter, text)
        painter.setBrush(Qt.BrushStyle.NoBrush)
