"""File › Import symbols: a WinProladder comment export read as the program's symbols (names
beside addresses in the ladder, the docks and the cross reference)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from ladderworks.core.dialects.fatek.comments import read_comment_file
from ladderworks.core.il import Program
from ladderworks.gui import file_dialogs
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.os_errors import os_error_text

if TYPE_CHECKING:
    from ladderworks.gui.main_window import MainWindow

translate = QCoreApplication.translate


def import_symbols_dialog(window: MainWindow) -> None:
    """Ask for a comment export and import it."""
    start = str(window.path.parent) if window.path is not None else ""
    name = file_dialogs.open_file_name(
        window, translate("MainWindow", "Import symbols"), start,
        translate("MainWindow", "WinProladder comment exports (*.txt);;All files (*)"))
    if name:
        import_symbols(window, name)


def import_symbols(window: MainWindow, path: str | Path) -> bool:
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
