"""QApplication start-up: settings, translators and the main window."""

from __future__ import annotations

import sys
from collections.abc import Sequence

from PySide6.QtWidgets import QApplication

from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.refcount_guard import guard_singletons
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage, system_language


def create_window(settings: Settings | None = None) -> MainWindow:
    """The main window (with its PLC docks) in the remembered or the system's UI language."""
    settings = settings if settings is not None else Settings()
    language = UiLanguage()
    language.apply(settings.language() or system_language())
    window = MainWindow(settings, language)
    return window


def main(argv: Sequence[str] | None = None) -> int:
    """Start the IDE (optionally opening the files named on the command line)."""
    args = list(argv) if argv is not None else sys.argv
    guard_singletons()
    app = QApplication.instance() or QApplication(args)
    app.setApplicationName("LadderWorks")
    app.setOrganizationName("LadderWorks")
    window = create_window()
    window.show()
    for name in args[1:]:
        if not name.startswith("-"):
            window.load(name)
            break
    return app.exec()
