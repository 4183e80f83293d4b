"""The console's tool ids (the seed manual's tool bag) and the SVG icon loader."""

from __future__ import annotations

from enum import StrEnum

from PySide6.QtGui import QIcon

from ladderworks.paths import icons_dir


class Tool(StrEnum):
    """A tool of the palette; the value is the stable id used in objectNames."""

    SELECT = "select"
    INPUT = "input"
    INPUT_NOT = "input_not"
    OUTPUT = "output"
    OUTPUT_NOT = "output_not"
    SET_COIL = "set_coil"
    RESET_COIL = "reset_coil"
    INVERT = "invert"
    OR = "or"
    LINE = "line"
    COMMENT = "comment"
    DELETE = "delete"
    FUNCTION = "function"
    ROW_BEFORE = "row_before"
    ROW_AFTER = "row_after"


def icon(name: str) -> QIcon:
    """An SVG icon from resources/icons."""
    return QIcon(str(icons_dir() / f"{name}.svg"))
