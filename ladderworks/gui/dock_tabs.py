"""The tabs of tabbed docks show their whole title (scroll arrows rather than 'ALAR...'), and a
side group too narrow for its tabs is widened so none hides behind the arrows."""

from __future__ import annotations

from PySide6.QtCore import QChildEvent, QEvent, QObject, Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QMainWindow, QTabBar

SIDES = (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea)
MOST = 4  # a side group is widened for its tabs up to a quarter of the window's width
MARGIN = 4  # px beside the tabs: the tab bar's frame


class WholeDockTitles(QObject):
    """Watches a main window for the tab bars its layout makes for tabbed docks and keeps
    their titles whole: a narrow group scrolls its tabs instead of cutting every title, and a
    left or right group is widened to show every tab (the Turkish "Ana takım çantası" and
    "Sinyaller" under the tool palette: "Sinyaller" hid behind the arrows)."""

    def __init__(self, window: QMainWindow) -> None:
        super().__init__(window)
        self.window = window
        self._pending = False
        window.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """A tab bar polished (made, or after a style change) gets whole titles; one shown or
        the window resized, the groups are checked for room."""
        kind = event.type()
        if kind == QEvent.Type.ChildPolished and isinstance(event, QChildEvent):
            child = event.child()
            if isinstance(child, QTabBar) and child.parent() is watched:
                child.setElideMode(Qt.TextElideMode.ElideNone)
                child.setUsesScrollButtons(True)
                child.installEventFilter(self)
        elif (isinstance(watched, QTabBar) and kind == QEvent.Type.Show) or (
                watched is self.window and kind == QEvent.Type.Resize):
            # a group shown, another window size (other titles: the window's retranslate);
            # not a splitter the user drags (the group then stays as narrow as dragged)
            self._check_soon()
        return False

    def check_soon(self) -> None:
        """Check the groups once the events waiting now are done (a resize laid out)."""
        self._check_soon()

    def _check_soon(self) -> None:
        if not self._pending:
            self._pending = True
            QTimer.singleShot(0, self.widen)

    def widen(self) -> None:
        """Widen each left or right tab group whose tabs do not all show (up to MOST)."""
        self._pending = False
        window = self.window
        for bar in window.findChildren(QTabBar):
            if bar.parent() is not window or not bar.isVisible() or bar.count() < 2:
                continue
            need = bar.sizeHint().width()
            if need > window.width() // MOST:
                continue
            titles = {bar.tabText(index) for index in range(bar.count())}
            docks = [dock for dock in window.findChildren(QDockWidget)
                     if dock.isVisible() and not dock.isFloating()
                     and dock.windowTitle() in titles and window.dockWidgetArea(dock) in SIDES]
            shown = max(docks, key=lambda dock: dock.width(), default=None)  # the current tab
            if shown is not None and shown.width() < need + MARGIN:
                window.resizeDocks([shown], [need + MARGIN], Qt.Orientation.Horizontal)
