"""The tabs of tabbed docks show their whole title (scroll arrows rather than 'ALAR...')."""

from __future__ import annotations

from PySide6.QtCore import QChildEvent, QEvent, QObject, Qt
from PySide6.QtWidgets import QMainWindow, QTabBar


class WholeDockTitles(QObject):
    """Watches a main window for the tab bars its layout makes for tabbed docks and keeps
    their titles whole: a narrow group scrolls its tabs instead of cutting every title."""

    def __init__(self, window: QMainWindow) -> None:
        super().__init__(window)
        window.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """A tab bar polished (made, or after a style change) gets whole titles."""
        if event.type() == QEvent.Type.ChildPolished and isinstance(event, QChildEvent):
            child = event.child()
            if isinstance(child, QTabBar) and child.parent() is watched:
                child.setElideMode(Qt.TextElideMode.ElideNone)
                child.setUsesScrollButtons(True)
        return False
