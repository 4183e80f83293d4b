"""Putting a utility dock into the console: dock area, View-menu toggle, menu lookup, error text."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QDockWidget, QMainWindow, QMenu

from ladderworks.core.address import AddressError
from ladderworks.gui.diagnostic_texts import diagnostic_text

translate = QCoreApplication.translate


def find_menu(window: QMainWindow, name: str) -> QMenu | None:
    """The window's menu with objectName `name` (`menu_view`, `menu_file`, `menu_plc`)."""
    return window.findChild(QMenu, name)


def register_action(window: QMainWindow, action: QAction) -> None:
    """Make an action findable by objectName in the console's `actions_by_name`, if it has one."""
    actions = getattr(window, "actions_by_name", None)
    if isinstance(actions, dict):
        actions[action.objectName()] = action


def add_dock(window: QMainWindow, dock: QDockWidget, toggle_name: str,
             area: Qt.DockWidgetArea = Qt.DockWidgetArea.BottomDockWidgetArea) -> QAction:
    """Dock `dock` in `window` and put its show/hide toggle (objectName `toggle_name`) in View."""
    window.addDockWidget(area, dock)
    toggle = dock.toggleViewAction()
    toggle.setObjectName(toggle_name)
    register_action(window, toggle)
    view = find_menu(window, "menu_view")
    if view is not None:
        view.addAction(toggle)
    return toggle


def insert_before(menu: QMenu | None, action: QAction, before_name: str) -> None:
    """Put `action` in `menu` before the action named `before_name` (at the end if none)."""
    if menu is None:
        return
    for existing in menu.actions():
        if existing.objectName() == before_name:
            menu.insertAction(existing, action)
            return
    menu.addAction(action)


def address_error_text(error: AddressError) -> str:
    """An address error in the current UI language (the console's diagnostic texts)."""
    return diagnostic_text(error.diagnostic)
