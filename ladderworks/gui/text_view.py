"""The text view: a program shown as instruction-list text (files that failed to parse)."""

from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase, QTextCursor
from PySide6.QtWidgets import QPlainTextEdit, QWidget


class ProgramTextView(QPlainTextEdit):
    """Plain-text editor for `.LAD` text, with a jump to a line and column."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("text_view")
        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setStyleHint(QFont.StyleHint.Monospace)
        self.setFont(font)
        self.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)

    def go_to(self, line: int, column: int = 1) -> None:
        """Put the cursor at 1-based `line`, `column` and show it."""
        block = self.document().findBlockByNumber(max(line - 1, 0))
        cursor = QTextCursor(block)
        cursor.movePosition(QTextCursor.MoveOperation.Right, QTextCursor.MoveMode.MoveAnchor,
                            max(min(column - 1, block.length() - 1), 0))
        self.setTextCursor(cursor)
        self.centerCursor()
        self.setFocus()

    def cursor_line(self) -> int:
        """1-based line of the cursor."""
        return self.textCursor().blockNumber() + 1
