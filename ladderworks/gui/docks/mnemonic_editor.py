"""The mnemonic (.MOD) editor: line numbers, highlighting, inline diagnostics, compile stripes."""

from __future__ import annotations

import re

from PySide6.QtCore import QRect, QSize, Qt
from PySide6.QtGui import (
    QColor,
    QFont,
    QPainter,
    QPaintEvent,
    QResizeEvent,
    QSyntaxHighlighter,
    QTextCharFormat,
    QTextCursor,
    QTextDocument,
    QTextFormat,
)
from PySide6.QtWidgets import QPlainTextEdit, QTextEdit, QWidget

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.instructions import ALL, SUB_KEYWORD

STRIPE = QColor(0, 170, 0, 70)  # lines already converted ("green stripes")
ERROR_LINE = QColor(211, 47, 47, 40)

_WORD = re.compile(r"[A-Za-z][A-Za-z0-9.]*")
_ADDRESS = re.compile(r"\b[XYFGRADTCKxyfgradtck]\d+(?:\.\d)?\b")
_NUMBER = re.compile(r"\b\d+\b")


def _format(colour: str, bold: bool = False, italic: bool = False) -> QTextCharFormat:
    fmt = QTextCharFormat()
    fmt.setForeground(QColor(colour))
    if bold:
        fmt.setFontWeight(QFont.Weight.Bold)
    fmt.setFontItalic(italic)
    return fmt


class MnemonicHighlighter(QSyntaxHighlighter):
    """Instructions in bold blue, addresses dark red, numbers teal, comments green."""

    def __init__(self, document: QTextDocument) -> None:
        super().__init__(document)
        self.names = {spec.name for spec in ALL} | {SUB_KEYWORD}
        self.instruction = _format("#0d47a1", bold=True)
        self.address = _format("#880e4f")
        self.number = _format("#00695c")
        self.comment = _format("#2e7d32", italic=True)
        self.section = _format("#6a1b9a", bold=True)

    def highlightBlock(self, text: str) -> None:
        """Colour one line."""
        stripped = text.lstrip()
        if stripped.startswith("%"):
            self.setFormat(0, len(text), self.section)
            return
        if stripped.startswith((",", "//")):
            self.setFormat(0, len(text), self.comment)
            return
        code_end = text.find("//")
        code = text if code_end < 0 else text[:code_end]
        for match in _NUMBER.finditer(code):
            self.setFormat(match.start(), match.end() - match.start(), self.number)
        for match in _ADDRESS.finditer(code):
            self.setFormat(match.start(), match.end() - match.start(), self.address)
        first = _WORD.match(code.lstrip())
        if first and first.group(0).upper() in self.names:
            start = len(code) - len(code.lstrip())
            self.setFormat(start, len(first.group(0)), self.instruction)
        if code_end >= 0:
            self.setFormat(code_end, len(text) - code_end, self.comment)


class _LineNumbers(QWidget):
    def __init__(self, editor: MnemonicEditor) -> None:
        super().__init__(editor)
        self.editor = editor

    def sizeHint(self) -> QSize:
        return QSize(self.editor.number_width(), 0)

    def paintEvent(self, event: QPaintEvent) -> None:
        self.editor.paint_numbers(event)


class MnemonicEditor(QPlainTextEdit):
    """A plain-text editor for mnemonic code with the compile screen's decorations."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("mnemonicEditor")
        font = QFont("monospace")
        font.setStyleHint(QFont.StyleHint.Monospace)
        font.setPointSizeF(10)
        self.setFont(font)
        self.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        self.highlighter = MnemonicHighlighter(self.document())
        self.numbers = _LineNumbers(self)
        self.converted_lines = 0  # lines 1..n are striped green
        self.diagnostics: list[Diagnostic] = []
        self.blockCountChanged.connect(lambda _n: self._update_margin())
        self.updateRequest.connect(self._scroll_numbers)
        self._update_margin()

    # -- line numbers ----------------------------------------------------------------------

    def number_width(self) -> int:
        """Width of the line-number margin."""
        digits = max(3, len(str(self.blockCount())))
        return 10 + self.fontMetrics().horizontalAdvance("9") * digits

    def _update_margin(self) -> None:
        self.setViewportMargins(self.number_width(), 0, 0, 0)

    def _scroll_numbers(self, rect: QRect, dy: int) -> None:
        if dy:
            self.numbers.scroll(0, dy)
        else:
            self.numbers.update(0, rect.y(), self.numbers.width(), rect.height())

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Keep the margin beside the text."""
        super().resizeEvent(event)
        rect = self.contentsRect()
        self.numbers.setGeometry(QRect(rect.left(), rect.top(), self.number_width(),
                                       rect.height()))

    def paint_numbers(self, event: QPaintEvent) -> None:
        """Paint the line numbers (errors in red, converted lines on green)."""
        painter = QPainter(self.numbers)
        painter.fillRect(event.rect(), QColor("#f2f2f2"))
        error_lines = {d.line for d in self.diagnostics if d.line and d.is_error}
        block = self.firstVisibleBlock()
        number = block.blockNumber() + 1
        top = round(self.blockBoundingGeometry(block).translated(self.contentOffset()).top())
        height = round(self.blockBoundingRect(block).height())
        while block.isValid() and top <= event.rect().bottom():
            if block.isVisible():
                if number <= self.converted_lines:
                    painter.fillRect(QRect(0, top, self.numbers.width(), height), STRIPE)
                painter.setPen(QColor("#c62828") if number in error_lines else QColor("#777"))
                painter.drawText(QRect(0, top, self.numbers.width() - 5, height),
                                 Qt.AlignmentFlag.AlignRight, str(number))
            block = block.next()
            top += height
            number += 1

    # -- decorations -------------------------------------------------------------------------

    def set_converted(self, lines: int) -> None:
        """Stripe lines 1..`lines` green (the part of the program already converted)."""
        self.converted_lines = lines
        self._decorate()

    def set_diagnostics(self, diagnostics: list[Diagnostic]) -> None:
        """Underline the diagnostics' positions (wavy red for errors) and tint their lines."""
        self.diagnostics = list(diagnostics)
        self._decorate()

    def _decorate(self) -> None:
        selections: list[QTextEdit.ExtraSelection] = []
        doc = self.document()
        if self.converted_lines:
            cursor = QTextCursor(doc)
            end = doc.findBlockByNumber(min(self.converted_lines, doc.blockCount()) - 1)
            cursor.setPosition(end.position() + end.length() - 1,
                               QTextCursor.MoveMode.KeepAnchor)
            stripe = QTextEdit.ExtraSelection()
            stripe.format.setBackground(STRIPE)
            stripe.format.setProperty(QTextFormat.Property.FullWidthSelection, True)
            stripe.cursor = cursor
            selections.append(stripe)
        for diagnostic in self.diagnostics:
            if not diagnostic.line:
                continue
            block = doc.findBlockByNumber(diagnostic.line - 1)
            if not block.isValid():
                continue
            line = QTextEdit.ExtraSelection()
            line.format.setBackground(ERROR_LINE)
            line.format.setProperty(QTextFormat.Property.FullWidthSelection, True)
            line.cursor = QTextCursor(block)
            selections.append(line)
            mark = QTextEdit.ExtraSelection()
            cursor = QTextCursor(block)
            column = max(diagnostic.column or 1, 1) - 1
            cursor.setPosition(block.position() + min(column, max(block.length() - 1, 0)))
            cursor.movePosition(QTextCursor.MoveOperation.EndOfWord,
                                QTextCursor.MoveMode.KeepAnchor)
            if not cursor.hasSelection():
                cursor.movePosition(QTextCursor.MoveOperation.EndOfBlock,
                                    QTextCursor.MoveMode.KeepAnchor)
            mark.format.setUnderlineStyle(QTextCharFormat.UnderlineStyle.WaveUnderline)
            mark.format.setUnderlineColor(QColor("#d32f2f") if diagnostic.is_error
                                          else QColor("#f9a825"))
            mark.cursor = cursor
            selections.append(mark)
        self.setExtraSelections(selections)
        self.numbers.update()

    def go_to_line(self, line: int) -> None:
        """Put the cursor on a line and show it."""
        block = self.document().findBlockByNumber(max(line, 1) - 1)
        if block.isValid():
            self.setTextCursor(QTextCursor(block))
            self.centerCursor()
