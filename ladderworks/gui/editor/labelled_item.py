"""A network item that also shows the network's LADDER-III label (`N00012`) under its number."""

from __future__ import annotations

from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QFont, QPainter
from PySide6.QtWidgets import QStyleOptionGraphicsItem, QWidget

from ladderworks.gui.editor.geometry import LEFT, grid_top
from ladderworks.gui.editor.network_item import RAIL, NetworkItem, fitted_font


class LabelledNetworkItem(NetworkItem):
    """Paints the network, then its label (if it was read with one) left of the rail."""

    def paint(self, painter: QPainter, option: QStyleOptionGraphicsItem,
              widget: QWidget | None = None) -> None:
        """Draw the network and its label."""
        super().paint(painter, option, widget)
        label = self.network.label
        if not label:
            return
        font = QFont()
        font.setPointSizeF(7)
        painter.setFont(fitted_font(font, label, LEFT - 5))
        painter.setPen(RAIL)
        top = grid_top(self.network) + self.rows.wire
        painter.drawText(QRectF(0, top - 2, LEFT - 3, 14),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, label)
