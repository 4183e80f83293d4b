"""QApplication start-up: arguments, Qt's system libraries, translators and the main window."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence

from PySide6.QtCore import QCoreApplication, QTimer
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QApplication

from ladderworks import version
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.qt_libraries import missing_libraries, missing_libraries_text, uses_xcb
from ladderworks.gui.refcount_guard import guard_singletons
from ladderworks.gui.screen_fit import place_main_window
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage, system_language


def create_window(settings: Settings | None = None) -> MainWindow:
    """The main window (with its PLC docks) in the remembered or the system's UI language,
    placed on its screen (the saved geometry if it fits, maximised on a small screen)."""
    settings = settings if settings is not None else Settings()
    language = UiLanguage()
    language.apply(settings.language() or system_language())
    window = MainWindow(settings, language)
    screen = window.screen() or QGuiApplication.primaryScreen()
    place_main_window(window, settings.window_state()[0], screen.availableGeometry())
    return window


def parse_arguments(arguments: Sequence[str]) -> argparse.Namespace:
    """The IDE's own options (Qt's, like -platform, are left to Qt); --version exits here."""
    parser = argparse.ArgumentParser(prog="ladderworks", description="LadderWorks ladder IDE")
    parser.add_argument("--version", action="version", version=f"%(prog)s {version()}")
    parser.add_argument("--quit-after", type=int, metavar="MS",
                        help="close the IDE after MS milliseconds (start-up checks)")
    parser.add_argument("files", nargs="*", metavar="FILE", help="a .LAD program to open")
    return parser.parse_known_args(list(arguments))[0]


def explain_missing_libraries(sonames: list[str]) -> None:
    """Print the missing xcb libraries and their packages on stderr, in the UI language."""
    app = QCoreApplication.instance() or QCoreApplication(["ladderworks"])
    app.setApplicationName("LadderWorks")
    language = UiLanguage()  # its translators stay installed while it lives
    language.apply(Settings().language() or system_language())
    print(missing_libraries_text(sonames), file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    """Start the IDE (optionally opening the file named on the command line)."""
    args = list(argv) if argv is not None else sys.argv
    parse_arguments(args[1:])
    if uses_xcb(os.environ, sys.platform):
        missing = missing_libraries()
        if missing:
            explain_missing_libraries(missing)
            return 1
    guard_singletons()
    app = QApplication.instance() or QApplication(args)
    app.setApplicationName("LadderWorks")
    app.setOrganizationName("LadderWorks")
    options = parse_arguments(QCoreApplication.arguments()[1:])
    window = create_window()
    window.show()
    restored = window.offer_recovery()  # copies left by a session that crashed or was killed
    if options.files and not restored:
        window.load(options.files[0])
    if options.quit_after is not None:
        QTimer.singleShot(options.quit_after, window.close)
        QTimer.singleShot(options.quit_after, app.quit)
    return app.exec()
