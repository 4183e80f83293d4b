"""A program opened as a folder of exports (TIA's: an OB with its FCs/FBs, DBs and tag tables):
File › Open folder, and what Save does for it — nothing while it is unchanged; a change is
written into the entry block's own file in the folder (no other file), in its form, unless its
dialect refuses it (save_refusal.py) or the file changed on disk meanwhile (asked first); a
folder whose entry block has no file of its own asks for a file name."""

from __future__ import annotations

from pathlib import Path
from typing import Protocol

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from ladderworks.gui import file_dialogs, questions
from ladderworks.gui.document import ProgramDocument
from ladderworks.gui.files import ReadOnlyFile
from ladderworks.gui.os_errors import os_error_text

translate = QCoreApplication.translate


class Window(Protocol):
    """What the folder's File actions use of the main window (`FileActions`)."""

    @property
    def path(self) -> Path | None:
        """The open program's file or folder."""

    @property
    def document(self) -> ProgramDocument:
        """The open program's file state (a folder's entry file)."""

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

    def bytes_to_save(self, path: Path) -> tuple[bytes | None, bool]:
        """The bytes Save writes to `path`, whether networks are kept as drawings."""

    def after_save(self, path: Path, drafts: bool, message: str = "") -> None:
        """The program is saved as `path`."""

    def save_answer(self) -> bool:
        """What Save returns when `bytes_to_save` wrote nothing (True: Save As saved it)."""

    def write_companions(self) -> None:
        """Write the files Save writes beside the program's (an S7 block's `.s7res`)."""


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
    changed, its entry block's file in the folder is written (only that file)."""
    if not window.is_modified():
        window.show_message(translate("MainWindow", "{0}: no changes to save").format(
            path.name))
        return True
    document = window.document
    entry = document.entry
    if entry is None:
        window.warn(translate("MainWindow", "Save"), translate(
            "MainWindow", "{0} is a folder of exported blocks: save the changed program "
            "under a file name").format(path.name))
        return window.save_as_dialog()
    if document.entry_changed_on_disk():
        answer = questions.changed_outside(window if isinstance(window, QWidget) else None,
                                           entry)
        if answer == "reload":
            window.load(path)
            return False
        if answer == "save_as":
            return window.save_as_dialog()
        if answer != "keep":
            return False
    data, drafts = window.bytes_to_save(entry)
    if data is None:  # declined, or refused with Save As offered (save_refusal.py)
        return window.save_answer()
    try:
        document.write_entry(data)
        window.write_companions()  # the .s7res of a changed title
    except ReadOnlyFile:
        window.warn(translate("MainWindow", "Save"), translate(
            "MainWindow", "{0} is read-only and is not replaced.").format(entry))
        return False
    except OSError as error:
        window.warn(translate("MainWindow", "Save"), translate(
            "MainWindow", "Cannot write {0}: {1}").format(entry, os_error_text(error)))
        return False
    window.after_save(path, drafts, translate(
        "MainWindow", "Saved {0} in the folder {1} (its other files are unchanged)").format(
        entry.name, path.name))
    return True
