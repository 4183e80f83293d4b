"""Windows sized for the screen they open on (a 1024×600 panel has no room for 900×600,
nor for the main window's 1200×800)."""

from __future__ import annotations

from PySide6.QtCore import QByteArray, QDataStream, QPoint, QRect, QSize, Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QDockWidget, QMainWindow, QWidget

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


FIRST_SIZE = QSize(1200, 800)  # the main window's size on a first start, where it fits
SMALL = QSize(1280, 720)  # a free area this narrow or this low: the main window maximised
LARGE_SHARE = 0.8  # of a large screen's free area: 1536×832 on a 1920×1040 desktop


def saved_normal_geometry(saved: QByteArray) -> QRect | None:
    """The normal (not maximised) geometry in QWidget.saveGeometry()'s bytes, or None."""
    stream = QDataStream(saved)
    stream.setVersion(QDataStream.Version.Qt_4_0)  # as saveGeometry writes it
    magic, major = stream.readUInt32(), stream.readUInt16()
    stream.readUInt16()  # minor version
    if magic != 0x1D9D0CB or major < 1:
        return None
    frame, normal = QRect(), QRect()
    stream >> frame
    stream >> normal
    ok = stream.status() == QDataStream.Status.Ok
    return normal if ok and normal.isValid() else None


def place_main_window(window: QWidget, saved: QByteArray | None, room: QRect) -> bool:
    """Size the main window for the free area `room` of its screen before it is first shown:
    the saved geometry when it still fits there (True), else 80 % of the free area (at least
    1200×800, at most 90 %), centred, and maximised when the screen is small (a 1024×600
    panel)."""
    normal = saved_normal_geometry(saved) if saved is not None else None
    if saved is not None and normal is not None and room.contains(normal):
        return window.restoreGeometry(saved)
    window.setWindowState(Qt.WindowState.WindowNoState)
    size = FIRST_SIZE.expandedTo(room.size() * LARGE_SHARE).boundedTo(room.size() * SHARE)
    window.resize(size)
    centre = room.center()
    window.move(centre.x() - size.width() // 2, centre.y() - size.height() // 2)
    if room.width() <= SMALL.width() or room.height() <= SMALL.height():
        window.setWindowState(Qt.WindowState.WindowMaximized)
    return False


LADDER_SHARE = 0.45  # a restored layout leaving the ladder less than this of the window is
SMALL_DOCK_SHARE = 3  # rebalanced: bottom docks a third of the height, side docks a third


def rebalance_docks(window: QMainWindow, ladder: QWidget) -> bool:
    """A dock layout restored from a larger screen (1920×1080 at 1024×600 left the ladder
    190 px tall): bottom docks back to a third of the window's height, right-hand ones to a
    third of its width, when the ladder has less than LADDER_SHARE of either. True if done."""
    docks = [dock for dock in window.findChildren(QDockWidget)
             if dock.isVisible() and not dock.isFloating()]
    done = False
    if ladder.height() < window.height() * LADDER_SHARE:
        bottom = [dock for dock in docks
                  if window.dockWidgetArea(dock) == Qt.DockWidgetArea.BottomDockWidgetArea]
        if bottom:
            low = window.height() // SMALL_DOCK_SHARE
            window.resizeDocks(bottom, [low] * len(bottom), Qt.Orientation.Vertical)
            done = True
    if ladder.width() < window.width() * LADDER_SHARE:
        right = [dock for dock in docks
                 if window.dockWidgetArea(dock) == Qt.DockWidgetArea.RightDockWidgetArea]
        if right:
            narrow = window.width() // SMALL_DOCK_SHARE
            window.resizeDocks(right, [narrow] * len(right), Qt.Orientation.Horizontal)
            done = True
    return done
