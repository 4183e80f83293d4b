"""The console's tools (the seed manual's tool bag): ids, icons, keys and translated names."""

from __future__ import annotations

from enum import StrEnum

from PySide6.QtCore import QCoreApplication
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


# Icon file (resources/icons/*.svg) and the letter key that picks the tool in the grid.
TOOL_ICONS: dict[Tool, str] = {
    Tool.SELECT: "select",
    Tool.INPUT: "contact",
    Tool.INPUT_NOT: "contact_not",
    Tool.OUTPUT: "coil",
    Tool.OUTPUT_NOT: "coil_not",
    Tool.SET_COIL: "coil_set",
    Tool.RESET_COIL: "coil_reset",
    Tool.INVERT: "invert",
    Tool.OR: "or",
    Tool.LINE: "line",
    Tool.COMMENT: "comment",
    Tool.DELETE: "delete",
    Tool.FUNCTION: "function",
    Tool.ROW_BEFORE: "row_before",
    Tool.ROW_AFTER: "row_after",
}

TOOL_KEYS: dict[Tool, str] = {
    Tool.SELECT: "S",
    Tool.INPUT: "I",
    Tool.INPUT_NOT: "N",
    Tool.OUTPUT: "O",
    Tool.OUTPUT_NOT: "W",
    Tool.SET_COIL: "E",  # sEt: S is the select tool
    Tool.RESET_COIL: "U",  # Unset: R is the OR tool
    Tool.INVERT: "T",
    Tool.OR: "R",
    Tool.LINE: "L",
    Tool.COMMENT: "C",
    Tool.DELETE: "D",
    Tool.FUNCTION: "F",
    Tool.ROW_BEFORE: "B",
    Tool.ROW_AFTER: "A",
}

KEY_TOOLS: dict[str, Tool] = {key: tool for tool, key in TOOL_KEYS.items()}


def icon(name: str) -> QIcon:
    """An SVG icon from resources/icons."""
    return QIcon(str(icons_dir() / f"{name}.svg"))


def tool_icon(tool: Tool) -> QIcon:
    """The palette icon of `tool`."""
    return icon(TOOL_ICONS[tool])


def tool_name(tool: Tool) -> str:
    """The tool's name in the current UI language (the manual's words in Turkish)."""
    names = {
        Tool.SELECT: QCoreApplication.translate("Tool", "Select"),
        Tool.INPUT: QCoreApplication.translate("Tool", "Input"),
        Tool.INPUT_NOT: QCoreApplication.translate("Tool", "NOT input"),
        Tool.OUTPUT: QCoreApplication.translate("Tool", "Output"),
        Tool.OUTPUT_NOT: QCoreApplication.translate("Tool", "NOT output"),
        Tool.SET_COIL: QCoreApplication.translate("Tool", "SET coil"),
        Tool.RESET_COIL: QCoreApplication.translate("Tool", "RST coil"),
        Tool.INVERT: QCoreApplication.translate("Tool", "NOT"),
        Tool.OR: QCoreApplication.translate("Tool", "OR"),
        Tool.LINE: QCoreApplication.translate("Tool", "Line"),
        Tool.COMMENT: QCoreApplication.translate("Tool", "Comment"),
        Tool.DELETE: QCoreApplication.translate("Tool", "Delete"),
        Tool.FUNCTION: QCoreApplication.translate("Tool", "Function"),
        Tool.ROW_BEFORE: QCoreApplication.translate("Tool", "Insert row before"),
        Tool.ROW_AFTER: QCoreApplication.translate("Tool", "Insert row after"),
    }
    return names[tool]


def tool_help(tool: Tool) -> str:
    """One sentence on how the tool is used (status tip and tooltip)."""
    helps = {
        Tool.SELECT: QCoreApplication.translate(
            "Tool", "Click an element or drag over cells to select; right-click: cut, copy, paste"),
        Tool.INPUT: QCoreApplication.translate(
            "Tool", "Click a cell to place a contact (RD / AND), type its address, ENTER"),
        Tool.INPUT_NOT: QCoreApplication.translate(
            "Tool", "Click a cell to place a NOT contact (RD.NOT / AND.NOT)"),
        Tool.OUTPUT: QCoreApplication.translate(
            "Tool", "Click a cell to place a coil (WRT), type its address, ENTER"),
        Tool.OUTPUT_NOT: QCoreApplication.translate(
            "Tool", "Click a cell to place a NOT coil (WRT.NOT)"),
        Tool.SET_COIL: QCoreApplication.translate(
            "Tool", "Click a cell to place a SET coil (bit := 1 while the logic is 1)"),
        Tool.RESET_COIL: QCoreApplication.translate(
            "Tool", "Click a cell to place an RST coil (bit := 0 while the logic is 1)"),
        Tool.INVERT: QCoreApplication.translate(
            "Tool", "Click a contact or coil to turn it into its inverse"),
        Tool.OR: QCoreApplication.translate(
            "Tool", "Click a contact or coil to add a parallel one below it"),
        Tool.LINE: QCoreApplication.translate(
            "Tool", "Click a first point, then a second point: a horizontal or vertical wire"),
        Tool.COMMENT: QCoreApplication.translate(
            "Tool", "Click the start of an empty row, type the comment, ENTER"),
        Tool.DELETE: QCoreApplication.translate("Tool", "Click an element to delete it"),
        Tool.FUNCTION: QCoreApplication.translate(
            "Tool", "Choose a function in the list, click the diagram, fill its table"),
        Tool.ROW_BEFORE: QCoreApplication.translate(
            "Tool", "Click a cell to insert an empty row before it"),
        Tool.ROW_AFTER: QCoreApplication.translate(
            "Tool", "Click a cell to insert an empty row after it"),
    }
    return helps[tool]
