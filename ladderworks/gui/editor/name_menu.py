"""View › Element names: show the address only, with its symbol, or with symbol and comment."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Signal
from PySide6.QtGui import QAction, QActionGroup, QGuiApplication
from PySide6.QtWidgets import QMenu, QWidget

from ladderworks.gui.editor.geometry import (
    NameDisplay,
    default_display,
    name_display,
    set_name_display,
)
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.settings import Settings

translate = QCoreApplication.translate


def _text(display: NameDisplay) -> str:
    if display is NameDisplay.ADDRESS:
        return translate("NameDisplayMenu", "&Address only")
    if display is NameDisplay.SYMBOL:
        return translate("NameDisplayMenu", "Address and &symbol")
    return translate("NameDisplayMenu", "Address, symbol and &comment")


class NameDisplayMenu(Retranslating, QMenu):
    """A choice of what every ladder view shows with each element, remembered in settings;
    `changed` tells the window's ladder views to lay their rows out again."""

    changed = Signal()

    def __init__(self, settings: Settings, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("menu_names")
        self.settings = settings
        self.group = QActionGroup(self)
        self.actions_by_display: dict[NameDisplay, QAction] = {}
        for display in NameDisplay:
            action = QAction(self)
            action.setObjectName(f"action_names_{display.value}")
            action.setCheckable(True)
            action.triggered.connect(lambda _c=False, d=display: self.choose(d))
            self.group.addAction(action)
            self.addAction(action)
            self.actions_by_display[display] = action
        try:
            chosen = NameDisplay(settings.name_display())
        except ValueError:
            screen = QGuiApplication.primaryScreen()
            chosen = default_display(screen.availableGeometry().height() if screen else 0)
        set_name_display(chosen)
        self.actions_by_display[chosen].setChecked(True)
        self.retranslate()

    def choose(self, display: NameDisplay) -> None:
        """Show `display` in every ladder view of the window and remember it."""
        self.actions_by_display[display].setChecked(True)
        self.settings.set_name_display(display.value)
        if display is name_display():
            return
        set_name_display(display)
        self.changed.emit()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setTitle(translate("NameDisplayMenu", "Element &names"))
        for display, action in self.actions_by_display.items():
            action.setText(_text(display))
