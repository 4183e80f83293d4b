"""Save of a change the program's file form cannot hold (an S7 block's drawing that is no S7
network yet, an engine change its graph does not know): the file is never overwritten, the
reason is said in the user's language and Save As is offered (once: a refusal inside that
Save As is only said)."""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui import questions
from ladderworks.gui.diagnostic_texts import diagnostic_text

translate = QCoreApplication.translate


class Window(Protocol):
    """What a refused Save uses of the main window (`FileActions`)."""

    save_as_offered: bool  # inside the Save As a refusal offered

    def warn(self, title: str, text: str) -> None:
        """A warning that does not block."""

    def show_message(self, text: str) -> None:
        """A status bar message."""

    def save_as_dialog(self) -> bool:
        """File › Save As."""


def refused(window: Window, path: Path, diagnostic: Diagnostic) -> bool:
    """Say why the program is not written to `path` and offer Save As; True when Save As
    saved it."""
    reason = diagnostic_text(diagnostic)
    if window.save_as_offered:
        window.warn(translate("MainWindow", "Save"), translate(
            "MainWindow", "{0} is not written: {1}").format(path.name, reason))
        return False
    parent = window if isinstance(window, QWidget) else None
    if questions.save_refused(parent, path, reason) != "save_as":
        window.show_message(translate("MainWindow", "Not saved: {0}").format(reason))
        return False
    window.save_as_offered = True
    try:
        return window.save_as_dialog()
    finally:
        window.save_as_offered = False
