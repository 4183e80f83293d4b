"""A box with named pins painted as TIA Portal draws it: the instance above, the name and the
data type inside, each pin's name at its edge and the operand wired to it outside."""

from __future__ import annotations

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QPainter

from ladderworks.core.ladder.model import FunctionBox, Pin
from ladderworks.gui.editor.geometry import CELL_W, RowMetrics

OPERAND = QColor("#1a1a1a")
TYPE = QColor("#5b5b5b")
INSTANCE = QColor("#1f4e79")
BOX_TOP = 14.0  # room above the box for its instance's name


def _elided(painter: QPainter, font: QFont, rect: QRectF, text: str,
            align: Qt.AlignmentFlag) -> None:
    painter.setFont(font)
    metrics = QFontMetricsF(font)
    painter.drawText(rect, align | Qt.AlignmentFlag.AlignVCenter,
                     metrics.elidedText(text, Qt.TextElideMode.ElideMiddle, rect.width()))


def _pin(painter: QPainter, pin: Pin, x: float, width: float, py: float, font: QFont,
         operand_font: QFont) -> None:
    pen = painter.pen()
    if pin.output:
        painter.drawLine(QPointF(x + width - 10, py), QPointF(x + width, py))
        if pin.name:
            _elided(painter, font, QRectF(x + width / 2, py - 7, width / 2 - 12, 14), pin.name,
                    Qt.AlignmentFlag.AlignRight)
        if pin.text:
            painter.setPen(OPERAND)
            _elided(painter, operand_font, QRectF(x + width + 3, py - 15, CELL_W - 6, 14),
                    pin.text, Qt.AlignmentFlag.AlignLeft)
    else:
        painter.drawLine(QPointF(x, py), QPointF(x + 10, py))
        if pin.negated:  # a negated input: a small circle at the box's edge
            painter.drawEllipse(QPointF(x + 7, py), 3, 3)
        if pin.name:
            _elided(painter, font, QRectF(x + 12, py - 7, width / 2 - 12, 14), pin.name,
                    Qt.AlignmentFlag.AlignLeft)
        if pin.text:
            painter.setPen(OPERAND)
            painter.drawLine(QPointF(x - 6, py), QPointF(x, py))
            _elided(painter, operand_font, QRectF(x - CELL_W + 2, py - 15, CELL_W - 6, 14),
                    pin.text, Qt.AlignmentFlag.AlignRight)
    painter.setPen(pen)


def paint_named_box(painter: QPainter, box: FunctionBox, x: float, y: float, rows: RowMetrics,
                    title_font: QFont, small_font: QFont, fill: QColor) -> None:
    """Paint a box with named pins anchored at the cell whose top-left is (x, y)."""
    width = box.width * CELL_W
    height = box.height * rows.height
    rect = QRectF(x + 10, y + BOX_TOP, width - 20, height - BOX_TOP - 6)
    painter.setBrush(fill)
    painter.drawRect(rect)
    painter.setBrush(Qt.BrushStyle.NoBrush)
    pen = painter.pen()
    if box.instance:
        painter.setPen(INSTANCE)
        _elided(painter, small_font, QRectF(x - CELL_W / 2, y, width + CELL_W, BOX_TOP),
                box.instance, Qt.AlignmentFlag.AlignHCenter)
        painter.setPen(pen)
    painter.setFont(title_font)
    metrics = QFontMetricsF(title_font)
    painter.drawText(QRectF(rect.left() + 20, rect.top() + 1, rect.width() - 40, 14),
                     Qt.AlignmentFlag.AlignHCenter,
                     metrics.elidedText(box.title, Qt.TextElideMode.ElideRight,
                                        rect.width() - 40))
    if box.type_name:
        painter.setPen(TYPE)
        _elided(painter, small_font, QRectF(rect.left() + 20, rect.top() + 15,
                                            rect.width() - 40, 13), box.type_name,
                Qt.AlignmentFlag.AlignHCenter)
        painter.setPen(pen)
    for pin in box.named:
        py = y + pin.row * rows.height + rows.wire
        _pin(painter, pin, x, width, py, small_font, small_font)
