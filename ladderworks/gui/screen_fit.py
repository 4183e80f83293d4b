"""Windows sized for the screen they open on (a 1024×600 panel has no room for 900×600)."""

from __future__ import annotations

from PySide6.QtCore import QPoint, QSize
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QWidget

SHARE = 0.9  # of the screen's free area: room for the title bar and the panel's task bar


def fit_to_screen(window: QWidget, wanted: QSize) -> None:
    """Resize `window` to `wanted`, or less on a screen that has not that much room."""
    anchor = window.parentWidget() or window
    screen = anchor.screen() or QGuiApplication.primaryScreen()
    room = screen.availableGeometry().size() * SHARE
    window.resize(wanted.boundedTo(room))


def keep_on_screen(window: QWidget) -> None:
    """Move a shown window wholly onto its screen's free area (a dialog centred on a main
    window larger than the screen would stick out of it)."""
    room = (window.screen() or QGuiApplication.primaryScreen()).availableGeometry()
    frame = window.frameGeometry()
    x = max(room.left(), min(frame.left(), room.right() + 1 - frame.width()))
    y = max(room.top(), min(frame.top(), room.bottom() + 1 - frame.height()))
    if (x, y) != (frame.left(), frame.top()):
        window.move(window.pos() + QPoint(x - frame.left(), y - frame.top()))
