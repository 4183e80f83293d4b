"""Blocking questions about the program's file, with translated buttons (tests answer `ask`)."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QAbstractButton, QMessageBox, QWidget

from ladderworks.core.il.textform import EncodeError

translate = QCoreApplication.translate

Role = QMessageBox.ButtonRole


def ask(parent: QWidget | None, title: str, text: str,
        choices: list[tuple[str, str, QMessageBox.ButtonRole]]) -> str | None:
    """Ask with one button per (key, label, role); the chosen key, or None when closed.

    The first choice is the default; the one with the reject role answers Escape."""
    box = QMessageBox(QMessageBox.Icon.Question, title, text, QMessageBox.StandardButton.NoButton,
                      parent)
    box.setObjectName("question_box")
    buttons: dict[QAbstractButton, str] = {}
    for index, (key, label, role) in enumerate(choices):
        button = box.addButton(label, role)
        button.setObjectName(f"button_{key}")
        buttons[button] = key
        if index == 0:
            box.setDefaultButton(button)
    box.exec()
    return buttons.get(box.clickedButton())


def _cancel() -> tuple[str, str, QMessageBox.ButtonRole]:
    return ("cancel", translate("Questions", "Cancel"), Role.RejectRole)


def _save_as() -> tuple[str, str, QMessageBox.ButtonRole]:
    return ("save_as", translate("Questions", "Save As..."), Role.AcceptRole)


def changed_outside(parent: QWidget | None, path: Path) -> str | None:
    """The file changed on disk since it was opened: 'reload', 'keep', 'save_as' or cancel."""
    return ask(parent, translate("Questions", "File changed on disk"), translate(
        "Questions",
        "{0} was changed by another program since you opened it. Reload it (your unsaved "
        "changes are lost), keep your version (overwrite the other change), or save yours "
        "under another name?").format(path.name), [
        ("reload", translate("Questions", "Reload"), Role.DestructiveRole),
        ("keep", translate("Questions", "Keep mine"), Role.AcceptRole),
        _save_as(), _cancel()])


def read_only(parent: QWidget | None, path: Path) -> str | None:
    """The file is read-only: 'save_as' or cancel."""
    return ask(parent, translate("Questions", "Read-only file"), translate(
        "Questions",
        "{0} is read-only and is not replaced. Save the program under another name?",
    ).format(path.name), [_save_as(), _cancel()])


def save_refused(parent: QWidget | None, path: Path, reason: str) -> str | None:
    """A change the file's own form cannot hold (an S7 block): 'save_as' or cancel; the file
    is not overwritten either way."""
    return ask(parent, translate("Questions", "Change not saved"), translate(
        "Questions",
        "{0} is not overwritten: {1}. Save the program under another name?").format(
        path.name, reason), [_save_as(), _cancel()])


def encoding(parent: QWidget | None, path: Path, error: EncodeError) -> str | None:
    """A character the file's encoding cannot hold: 'utf8' or cancel (never written as ?)."""
    return ask(parent, translate("Questions", "Character not in the file's encoding"), translate(
        "Questions",
        "Line {0}, column {1}: the character '{2}' (U+{3:04X}) cannot be written in {4}, the "
        "encoding of {5}. Save the whole file as UTF-8 instead?").format(
        error.line, error.column, error.char, ord(error.char), error.encoding, path.name), [
        ("utf8", translate("Questions", "Save as UTF-8"), Role.AcceptRole), _cancel()])


def restore(parent: QWidget | None, name: str, when: str) -> str | None:
    """A recovery copy from a session that ended without saving: 'restore', 'discard', later."""
    return ask(parent, translate("Questions", "Recover unsaved work"), translate(
        "Questions",
        "LadderWorks ended without saving {0}. A recovery copy from {1} was found. "
        "Restore it?").format(name, when), [
        ("restore", translate("Questions", "Restore"), Role.AcceptRole),
        ("discard", translate("Questions", "Discard"), Role.DestructiveRole),
        ("later", translate("Questions", "Not now"), Role.RejectRole)])


def reload_running(parent: QWidget | None) -> str | None:
    """Compile while the PLC runs: 'reload' (at the next scan boundary) or cancel."""
    return ask(parent, translate("Questions", "The PLC is running"), translate(
        "Questions",
        "The PLC is running. Load the new program now? It is loaded between two scans and "
        "the PLC runs on with it; forces stay."), [
        ("reload", translate("Questions", "Reload now"), Role.AcceptRole), _cancel()])


def forces_on_load(parent: QWidget | None, count: int) -> str | None:
    """Another program goes into the PLC while signals are forced: 'keep', 'release' or
    cancel."""
    return ask(parent, translate("Questions", "Forced signals"), translate(
        "Questions",
        "{0} signal(s) are forced in the PLC for the program it has now. Another program is "
        "being loaded: keep these signals forced, or release them?").format(count), [
        ("release", translate("Questions", "Release the forces"), Role.AcceptRole),
        ("keep", translate("Questions", "Keep them forced"), Role.AcceptRole), _cancel()])
