"""A jump's target in the middle of the view: Find, the cross reference and the error list."""

from __future__ import annotations

from PySide6.QtCore import QPointF, QRectF
from PySide6.QtWidgets import QGraphicsView


def centre_on(view: QGraphicsView, rect: QRectF) -> None:
    """Scroll `view` so the scene's `rect` is in its middle vertically and wholly in view
    sideways (ensureVisible alone leaves a cell below the view at its bottom edge)."""
    middle = view.mapToScene(view.viewport().rect().center())
    view.centerOn(QPointF(middle.x(), rect.center().y()))
    view.ensureVisible(rect, 20, 20)
