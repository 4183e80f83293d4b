"""Loading another program into the PLC: what becomes of the forced signals (keep / release)."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from ladderworks.gui import questions
from ladderworks.gui.plc_session import PlcSession

translate = QCoreApplication.translate

Origin = tuple[str, str]  # (dialect, the file or the untitled drawing it came from)


def forced_count(session: PlcSession) -> int:
    """The forced signals a load would carry over (passive elements never carry over)."""
    return sum(1 for entry in session.run.forces() if entry.kind == "force")


def forces_on_load(parent: QWidget | None, session: PlcSession, origin: Origin) -> str | None:
    """'keep' or 'release' the forces when loading the program from `origin`, None to cancel.

    The same program compiled again (same family, same file: the edit-compile cycle) keeps
    them, as the core's reload does; another program asks — never kept silently."""
    count = forced_count(session)
    if count == 0 or session.loaded_origin == origin:
        return "keep"
    return questions.forces_on_load(parent, count)
