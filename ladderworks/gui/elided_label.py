"""A one-line label that shows '…' where its text does not fit, the whole text as tooltip."""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtGui import QPainter, QPaintEvent
from PySide6.QtWidgets import QLabel


class ElidedLabel(QLabel):
    """The status bar's cell text: as wide as its text where there is room; a long symbol
    and comment end in '…' rather than being cut without a sign, and never widen the
    window."""

    def setText(self, text: str) -> None:
        """The text, and the same as tooltip (the whole of it, where it is cut)."""
        super().setText(text)
        self.setToolTip(text)

    def shown_text(self) -> str:
        """The text as painted at the label's width."""
        return self.fontMetrics().elidedText(self.text(), Qt.TextElideMode.ElideRight,
                                             self.contentsRect().width())

    def minimumSizeHint(self) -> QSize:
        """As low as a line; as narrow as the minimum width set."""
        return QSize(self.minimumWidth(), super().minimumSizeHint().height())

    def paintEvent(self, _event: QPaintEvent) -> None:
        """The elided text, vertically centred."""
        painter = QPainter(self)
        painter.drawText(self.contentsRect(),
                         int(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter),
                         self.shown_text())
        painter.end()
