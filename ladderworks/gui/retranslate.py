"""The one way the console's widgets follow a live language switch: Qt's LanguageChange."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent

from ladderworks.gui.live_text import remake_live_texts

if TYPE_CHECKING:
    from PySide6.QtWidgets import QWidget

    _Widget = QWidget
else:
    _Widget = object


class Retranslating(_Widget):
    """A widget that sets its texts in `retranslate()`, called on Qt's LanguageChange.

    Installing a translator posts LanguageChange to every top-level window, and each widget
    passes it to its children, so the main window and every dock retranslate themselves. Helpers
    that are not widgets (on-line mode, time travel) are retranslated by the widget that owns
    them, from its own `retranslate()`; texts shown with `live_text.set_live_text` are made
    again after it. Listed first among the bases (a mixin)."""

    def retranslate(self) -> None:
        """Set every text in the current UI language."""
        raise NotImplementedError

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate on a language change."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
            remake_live_texts(self)  # the messages shown with `set_live_text`
        super().changeEvent(event)
