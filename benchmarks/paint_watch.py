"""Shared by the open benchmarks: an event filter that notes when a viewport has been painted."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject


class PaintWatch(QObject):
    """Notes when the watched widget has been painted."""

    def __init__(self) -> None:
        super().__init__()
        self.painted = False

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Any paint event counts."""
        if event.type() == QEvent.Type.Paint:
            self.painted = True
        return False


if __name__ == "__main__":  # `make bench` runs every script here: nothing to measure alone
    pass
