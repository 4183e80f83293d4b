"""File › Import symbols: a WinProladder comment export read as the program's symbols (names
beside addresses in the ladder, the docks and the cross reference)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from PySide6.QtCore import QCoreApplication

from ladderworks.core.dialects.fatek.comments import read_comment_file
from ladderworks.core.il import Program
from ladderworks.gui import file_dialogs
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.os_errors import os_error_text

if TYPE_CHECKING:
    from PySide6.QtWidgets import QAbstractScrollArea, QWidget

    from ladderworks.gui.document import ProgramDocument
    from ladderworks.gui.editor.ladder_model import LadderModel

translate = QCoreApplication.translate


class Host(Protocol):
    """What the import needs of the main window (File glue)."""

    document: ProgramDocument
    model: LadderModel
    editor: QAbstractScrollArea

    @property
    def path(self) -> Path | None: ...
    def warn(self, title: str, text: str) -> None: ...
    def show_message(self, text: str) -> None: ...
    def program_shown(self, program: Program) -> None: ...


def import_symbols_dialog(window: Host, parent: QWidget) -> None:
    """Ask for a comment export (a dialog over `parent`, the window) and import it."""
    start = str(window.path.parent) if window.path is not None else ""
    name = file_dialogs.open_file_name(
        parent, translate("MainWindow", "Import symbols"), start,
        translate("MainWindow", "WinProladder comment exports (*.txt);;All files (*)"))
    if name:
        import_symbols(window, name)


def import_symbols(window: Host, path: str | Path) -> bool:
    """Read `path` as the shown program's symbols; a file that does not read (its first error
    at its line) changes nothing."""
    path = Path(path)
    title = translate("MainWindow", "Import symbols")
    try:
        table, diagnostics = read_comment_file(path)
    except OSError as error:
        window.warn(title, translate("MainWindow", "Cannot read {0}: {1}").format(
            path, os_error_text(error)))
        return False
    errors = [d for d in diagnostics if d.is_error]
    if table is None or errors:
        first = (errors or diagnostics)[0]
        window.warn(title, f"{path.name}:{first.line}:{first.column}: {diagnostic_text(first)}")
        return False
    program = window.document.origin
    if program is None:
        program = window.document.origin = Program()
    program.symbols = table
    window.model.symbols = table
    window.program_shown(program)
    window.editor.viewport().update()
    warnings = "; ".join(f"{d.line}: {diagnostic_text(d)}" for d in diagnostics[:3])
    message = translate("MainWindow", "{0} symbols imported from {1}").format(
        len(table), path.name)
    window.show_message(f"{message} ({warnings})" if warnings else message)
    return True
