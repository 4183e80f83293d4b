"""A value a PLC table refuses is said where it was typed: the cell's editor opens again with
the text typed, and the reason shows in red just under the cell (not only at the dock's foot)."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QAbstractItemModel, QModelIndex, QPersistentModelIndex, QTimer
from PySide6.QtWidgets import QLabel, QLineEdit, QStyledItemDelegate, QTableView, QWidget

Index = QModelIndex | QPersistentModelIndex


class CellError(QLabel):
    """The reason a typed value was refused, under its cell in the table's viewport."""

    def __init__(self, view: QTableView) -> None:
        super().__init__(view.viewport())
        self.setObjectName("plcTablesCellError")
        self.setStyleSheet("QLabel { color: #ffffff; background: #c00000; padding: 2px 4px; }")
        self.setWordWrap(True)
        self.view = view
        self.hide()

    def show_at(self, index: QModelIndex, text: str) -> None:
        """Say `text` under the cell at `index` (within the viewport's width)."""
        rect = self.view.visualRect(index)
        width = max(min(self.view.viewport().width() - rect.left(), 360), 120)
        left = max(min(rect.left(), self.view.viewport().width() - width), 0)
        self.setText(text)
        self.setFixedWidth(width)
        self.adjustSize()
        top = rect.bottom() + 1
        if top + self.height() > self.view.viewport().height():  # the last row: above it
            top = max(rect.top() - self.height(), 0)
        self.move(left, top)
        self.show()
        self.raise_()


class RetypeDelegate(QStyledItemDelegate):
    """Stores a typed value through the model; when the model refuses it, the editor opens
    again with what was typed and the reason shows under the cell."""

    def __init__(self, view: QTableView, reason: Callable[[], str]) -> None:
        super().__init__(view)
        self.view = view
        self.reason = reason  # the model's last refusal, translated ("" when none)
        self.error = CellError(view)
        self.closeEditor.connect(self._closed)

    def _closed(self, _editor: QWidget, hint: QStyledItemDelegate.EndEditHint) -> None:
        if hint == QStyledItemDelegate.EndEditHint.RevertModelCache:  # Escape: given up
            self.error.hide()

    def setModelData(self, editor: QWidget, model: QAbstractItemModel, index: Index) -> None:
        """Store; on a refusal, retype."""
        text = editor.text() if isinstance(editor, QLineEdit) else ""
        if model.setData(index, text):
            self.error.hide()
            return
        why = self.reason()
        if not why:
            return
        at = QPersistentModelIndex(index)
        QTimer.singleShot(0, lambda: self._retype(at, text, why))

    def _retype(self, at: QPersistentModelIndex, text: str, why: str) -> None:
        if not at.isValid():
            return
        index = self.view.model().index(at.row(), at.column())
        self.view.setCurrentIndex(index)
        self.view.edit(index)
        editor = self.view.indexWidget(index) or self.view.focusWidget()
        if isinstance(editor, QLineEdit):
            editor.setText(text)
            editor.selectAll()
        self.error.show_at(index, why)
