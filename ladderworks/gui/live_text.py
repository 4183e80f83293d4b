"""A label's text made by a function, made again after a live language switch."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QLabel


class _Remaker(QObject):
    """Watches one label; on LanguageChange it remakes the text it set, if still shown."""

    def __init__(self, label: QLabel) -> None:
        super().__init__(label)
        self.label = label
        self.make: Callable[[], str] | None = None
        self.made = ""
        label.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Remake the text (unless the label was given another text since)."""
        if (event.type() == QEvent.Type.LanguageChange and self.make is not None
                and self.label.text() == self.made):
            self.made = self.make()
            self.label.setText(self.made)
        return False


def set_live_text(label: QLabel, make: Callable[[], str]) -> None:
    """Show `make()` in `label` now and again in the new language after each switch."""
    remaker = label.findChild(_Remaker)
    if remaker is None:
        remaker = _Remaker(label)
    remaker.make = make
    remaker.made = make()
    label.setText(remaker.made)
