"""Shared by the window benchmarks: the console shown offscreen, and an event filter that notes
when a viewport has been painted."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QObject, QSettings
from PySide6.QtWidgets import QApplication

if TYPE_CHECKING:
    from ladderworks.gui.main_window import MainWindow


def shown_console(folder: Path, names: str | None = None) -> MainWindow:
    """The main window in English at 1200×800, shown, its settings in `folder` (`names`: the
    View › Element names choice, as if made)."""
    from ladderworks.gui.main_window import MainWindow
    from ladderworks.gui.settings import Settings
    from ladderworks.gui.translation import UiLanguage

    settings = Settings(QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat))
    if names is not None:
        settings.set_name_display(names)
    language = UiLanguage()
    language.apply("en")
    window = MainWindow(settings, language)
    window.resize(1200, 800)
    window.show()
    QApplication.processEvents()
    return window


class PaintWatch(QObject):
    """Notes when the watched widget has been painted."""

    def __init__(self) -> None:
        super().__init__()
        self.painted = False

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Any paint event counts."""
        if event.type() == QEvent.Type.Paint:
            self.painted = True
        return False


if __name__ == "__main__":  # `make bench` runs every script here: nothing to measure alone
    pass
