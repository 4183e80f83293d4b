"""A program opened as a folder of exports (TIA's: an OB with its FCs/FBs, DBs and tag tables):
File › Open folder, and what Save does for it — nothing while it is unchanged, and a changed
program goes under a file name (the folder and its exports are never written over)."""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from ladderworks.gui import file_dialogs

translate = QCoreApplication.translate


class Window(Protocol):
    """What the folder's File actions use of the main window (`FileActions`)."""

    @property
    def path(self) -> Path | None:
        """The open program's file or folder."""

    def maybe_save(self) -> bool:
        """Ask to save unsaved changes; False when the user cancels."""

    def load(self, path: str | Path) -> bool:
        """Open a program."""

    def is_modified(self) -> bool:
        """True when there are unsaved changes."""

    def show_message(self, text: str) -> None:
        """A status bar message."""

    def warn(self, title: str, text: str) -> None:
        """A warning that does not block."""

    def save_as_dialog(self) -> bool:
        """File › Save As."""


def open_dialog(window: Window) -> None:
    """File › Open folder: choose a folder of exports and open it as one program."""
    if not window.maybe_save():
        return
    name = file_dialogs.open_folder_name(
        window if isinstance(window, QWidget) else None,
        translate("MainWindow", "Open a folder of exported blocks"),
        str(window.path.parent if window.path else ""))
    if name:
        window.load(name)


def save(window: Window, path: Path) -> bool:
    """Save of a program opened as the folder `path`: unchanged, nothing is written (True);
    changed, Save As names the file."""
    if not window.is_modified():
        window.show_message(translate("MainWindow", "{0}: no changes to save").format(
            path.name))
        return True
    window.warn(translate("MainWindow", "Save"), translate(
        "MainWindow", "{0} is a folder of exported blocks: save the changed program "
        "under a file name").format(path.name))
    return window.save_as_dialog()
