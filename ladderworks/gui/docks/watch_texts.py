"""The watch table's display formats by name, as TIA Portal calls them, marked for translation."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.core.watch.values import Format

FORMAT_NAMES: dict[Format, str] = {
    Format.BOOL: QT_TRANSLATE_NOOP("WatchTable", "Bool"),
    Format.DEC: QT_TRANSLATE_NOOP("WatchTable", "DEC"),
    Format.SDEC: QT_TRANSLATE_NOOP("WatchTable", "DEC+/-"),
    Format.HEX: QT_TRANSLATE_NOOP("WatchTable", "Hex"),
    Format.BIN: QT_TRANSLATE_NOOP("WatchTable", "Bin"),
    Format.REAL: QT_TRANSLATE_NOOP("WatchTable", "Floating-point number"),
    Format.TIME: QT_TRANSLATE_NOOP("WatchTable", "Time"),
    Format.DATE: QT_TRANSLATE_NOOP("WatchTable", "Date"),
    Format.TOD: QT_TRANSLATE_NOOP("WatchTable", "Time of day"),
    Format.CHAR: QT_TRANSLATE_NOOP("WatchTable", "Character"),
    Format.STRING: QT_TRANSLATE_NOOP("WatchTable", "String"),
}


def format_name(fmt: Format) -> str:
    """A display format's name in the UI language."""
    return QCoreApplication.translate("WatchTable", FORMAT_NAMES[fmt])
