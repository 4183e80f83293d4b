"""QApplication start-up: settings, translators and the main window."""

from __future__ import annotations

import sys
from collections.abc import Sequence

from PySide6.QtWidgets import QApplication, QMainWindow


def main(argv: Sequence[str] | None = None) -> int:
    """Start the IDE and run the event loop."""
    app = QApplication(list(argv) if argv is not None else sys.argv)
    app.setApplicationName("LadderWorks")
    window = QMainWindow()
    window.setWindowTitle("LadderWorks")
    window.resize(1200, 800)
    window.show()
    return app.exec()
