"""A label's text made by a function, made again after a live language switch.

The remaking is part of the one retranslation path: `Retranslating.changeEvent` calls
`remake_live_texts` after the widget's own `retranslate()`."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QLabel, QWidget


class _Remaker(QObject):
    """Kept with one label: the function that made its text, and the text it made."""

    def __init__(self, label: QLabel) -> None:
        super().__init__(label)
        self.label = label
        self.make: Callable[[], str] | None = None
        self.made = ""

    def remake(self) -> None:
        """Remake the text (unless the label was given another text since)."""
        if self.make is not None and self.label.text() == self.made:
            self.made = self.make()
            self.label.setText(self.made)


def remake_live_texts(widget: QWidget) -> None:
    """Remake every live text in `widget` and below it, in the current language."""
    for remaker in widget.findChildren(_Remaker):
        remaker.remake()


def set_live_text(label: QLabel, make: Callable[[], str]) -> None:
    """Show `make()` in `label` now and again in the new language after each switch."""
    remaker = label.findChild(_Remaker)
    if remaker is None:
        remaker = _Remaker(label)
    remaker.make = make
    remaker.made = make()
    label.setText(remaker.made)
