"""Calling a function again when the window's UI language changes (for texts set by installers)."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QWidget


class Retranslated(QObject):
    """Calls `retranslate` now and on every LanguageChange event of `window`."""

    def __init__(self, window: QWidget, retranslate: Callable[[], None]) -> None:
        super().__init__(window)
        self._retranslate = retranslate
        window.installEventFilter(self)
        retranslate()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Pass LanguageChange on."""
        if event.type() == QEvent.Type.LanguageChange:
            self._retranslate()
        return False
