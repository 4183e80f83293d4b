"""The PLC diagnostic's network drawings, letting a due PLC scan run before each paints.

A repaint of the diagnostic draws every network on screen in one Qt paint event (about 3 ms a
network of S41_F036); the real-time scan thread, due in the middle, waited for the interpreter.
Each item calls its view's `before_paint` (the dock's `SnapshotGate.yield_to_scan`) first.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QStyleOptionGraphicsItem, QWidget

from ladderworks.gui.editor.labelled_item import LabelledNetworkItem


class YieldingNetworkItem(LabelledNetworkItem):
    """A network with its label, painted after a due scan (`before_paint`)."""

    before_paint: Callable[[], None] = staticmethod(lambda: None)

    def paint(self, painter: QPainter, option: QStyleOptionGraphicsItem,
              widget: QWidget | None = None) -> None:
        """Draw the network and its label, after a due scan."""
        self.before_paint()
        super().paint(painter, option, widget)
