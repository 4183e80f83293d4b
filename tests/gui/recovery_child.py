"""The IDE started by test_recovery: `python3 -m ladderworks`'s main with one unsaved edit.

It opens the file named on the command line, inverts the first contact (Edit > NOT), prints
`COPIED <path>` when the recovery copy is written, and waits to be killed."""

from __future__ import annotations

import sys

from PySide6.QtCore import QTimer

from ladderworks.gui import app
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings

_create_window = app.create_window


def _window_with_an_edit(settings: Settings | None = None) -> MainWindow:
    window = _create_window(settings)

    def edit() -> None:
        window.autosaver.copied.connect(lambda path: print("COPIED", path, flush=True))
        window.editor.move_cursor(0, 0, 0)
        window.actions_by_name["action_invert"].trigger()

    QTimer.singleShot(0, edit)  # after main() has opened the file
    return window


if __name__ == "__main__":
    app.create_window = _window_with_an_edit
    sys.exit(app.main(sys.argv))
