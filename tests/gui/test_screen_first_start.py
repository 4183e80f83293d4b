"""Issue 31 item 1: the first start on a small screen, and START/STOP always in view."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QByteArray, QRect, QSize, Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QMainWindow
from pytestqt.qtbot import QtBot

from ladderworks.gui import app
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.screen_fit import place_main_window, saved_normal_geometry
from ladderworks.gui.settings import Settings
from ladderworks.paths import EXAMPLES
from tests.gui.test_small_screen import PANEL, inside, on_the_panel

PANEL_ROOM = QRect(0, 0, 1024, 600)
DESKTOP_ROOM = QRect(0, 0, 1920, 1040)


def saved_geometry(qtbot: QtBot, rect: QRect) -> QByteArray:
    """What QWidget.saveGeometry() wrote for a window at `rect`."""
    other = QMainWindow()
    qtbot.addWidget(other)
    other.setGeometry(rect)
    return other.saveGeometry()


def test_a_first_start_opens_within_the_screen(qtbot: QtBot, settings: Settings) -> None:
    """The offscreen screen is 800×800: the window opens maximised, not 1200×800 past its
    right edge."""
    window = app.create_window(settings)
    qtbot.addWidget(window)
    window.show()
    qtbot.waitExposed(window)
    room = (window.screen() or QGuiApplication.primaryScreen()).availableGeometry()
    assert window.isMaximized()
    assert room.contains(window.frameGeometry()), (room, window.frameGeometry())
    assert inside(window, window.statusBar())


def test_a_small_screen_maximises_and_a_large_one_centres(qtbot: QtBot,
                                                           settings: Settings) -> None:
    window = MainWindow(settings, app.UiLanguage())
    qtbot.addWidget(window)
    assert not place_main_window(window, None, PANEL_ROOM)
    assert window.isMaximized()
    assert window.width() <= PANEL.width() and window.height() <= PANEL.height()
    assert not place_main_window(window, None, DESKTOP_ROOM)
    assert not window.isMaximized()
    assert window.size() == QSize(1536, 832)  # 80 % of the desktop
    assert (window.frameGeometry().center() - DESKTOP_ROOM.center()).manhattanLength() <= 4


@pytest.mark.parametrize(("room", "restored"), [(DESKTOP_ROOM, True), (PANEL_ROOM, False)])
def test_a_saved_geometry_is_restored_only_when_it_still_fits(qtbot: QtBot, settings: Settings,
                                                              room: QRect,
                                                              restored: bool) -> None:
    """A window saved at 1500×900 on the desktop comes back there, but not on the panel:
    it is maximised there instead of hanging off the screen."""
    saved = saved_geometry(qtbot, QRect(100, 50, 1500, 900))
    assert saved_normal_geometry(saved) == QRect(100, 50, 1500, 900)
    window = MainWindow(settings, app.UiLanguage())
    qtbot.addWidget(window)
    assert place_main_window(window, saved, room) is restored
    assert window.isMaximized() is not restored


def test_bytes_that_are_no_saved_geometry_give_the_first_size(qtbot: QtBot,
                                                              settings: Settings) -> None:
    window = MainWindow(settings, app.UiLanguage())
    qtbot.addWidget(window)
    assert saved_normal_geometry(QByteArray(b"not a geometry")) is None
    assert not place_main_window(window, QByteArray(b"not a geometry"), DESKTOP_ROOM)
    assert window.size().width() == 1536


@pytest.mark.parametrize("language", ["en", "tr"])
def test_start_and_stop_never_hide_behind_an_overflow(window: MainWindow, qtbot: QtBot,
                                                      language: str) -> None:
    """The PLC control screen at its narrowest on the panel, with the right-hand docks
    tabbed: its Compile, START and STOP buttons are all shown (they wrap, no "»")."""
    window.set_language(language)
    assert window.load(EXAMPLES / "spindle_override.LAD")
    on_the_panel(window, qtbot)
    docks = window.plc_docks
    for name, dock in (("action_dock_plc_diagnostic", docks.diagnostic),
                       ("action_dock_plc_control", docks.control)):
        window.actions_by_name[name].trigger()
        qtbot.waitUntil(dock.isVisible)
    control = docks.control
    window.resizeDocks([control], [control.minimumWidth()], Qt.Orientation.Horizontal)
    qtbot.wait(50)
    flow = control.toolbar
    qtbot.waitUntil(lambda: flow.hidden_buttons() == [])
    for name in ("action_plc_control_compile", "action_plc_start", "action_plc_stop"):
        button = flow.buttons[name]
        assert button.isVisible() and inside(window, button), name
    main_bar = window.menus.toolbar
    for name in ("action_plc_start", "action_plc_stop"):
        button = main_bar.widgetForAction(control.control_actions[name])
        assert button is not None and button.isVisible() and inside(window, button), name
    assert window.editor.viewport().width() >= 250  # the ladder stays usable
    window.set_language("en")
