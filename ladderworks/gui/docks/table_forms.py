"""The PLC tables' forms: INSERT's row form, and the field that adds any device to a Delta or
Fatek program's device tables (as WPLSoft's device monitor)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtCore import QCoreApplication, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.gui.docks.table_entries import DATA_WIDTHS, TableKind

translate = QCoreApplication.translate


class InsertRowDialog(QDialog):
    """The INSERT form of a table: its fields, validated when OK is pressed."""

    def __init__(
        self,
        kind: TableKind,
        fields: list[str],
        accept_texts: Callable[[list[str]], str | None],
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("plcTablesInsertDialog")
        self.kind = kind
        self._accept_texts = accept_texts
        self.setWindowTitle(translate("PlcTables", "INSERT"))
        layout = QVBoxLayout(self)
        form = QFormLayout()
        self.fields: list[QLineEdit | QComboBox] = []
        for index, label in enumerate(fields):
            field: QLineEdit | QComboBox
            if kind is TableKind.DATA and index == 1:
                field = QComboBox(self)
                field.addItems([str(width) for width in DATA_WIDTHS])
            else:
                field = QLineEdit(self)
            field.setObjectName(f"plcTablesField_{index}")
            form.addRow(label, field)
            self.fields.append(field)
        layout.addLayout(form)
        self.error = QLabel(self)
        self.error.setObjectName("plcTablesFormError")
        self.error.setStyleSheet("color:#c00000;")
        self.error.setWordWrap(True)
        layout.addWidget(self.error)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self
        )
        buttons.accepted.connect(self.try_accept)
        buttons.rejected.connect(self.reject)
        layout.addWidget(buttons)

    def set_texts(self, texts: Sequence[str]) -> None:
        """Fill the fields."""
        for field, text in zip(self.fields, texts, strict=False):
            if isinstance(field, QComboBox):
                field.setCurrentText(text)
            else:
                field.setText(text)

    def texts(self) -> list[str]:
        """What the fields hold."""
        return [
            field.currentText() if isinstance(field, QComboBox) else field.text()
            for field in self.fields
        ]

    def try_accept(self) -> None:
        """OK: insert the row, or show why not and stay open."""
        problem = self._accept_texts(self.texts())
        if problem is None:
            self.accept()
        else:
            self.error.setText(problem)


class DeviceAdder(QWidget):
    """`Add devices: [D500, T5, D0-D9] [Add]` over a Delta/Fatek program's device tables, and
    the reason under it when one is refused."""

    add_requested = Signal(str)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        row = QHBoxLayout()
        self.label = QLabel(self)
        self.field = QLineEdit(self)
        self.field.setObjectName("plcTablesAddField")
        self.field.setClearButtonEnabled(True)
        self.label.setBuddy(self.field)
        self.button = QPushButton(self)
        self.button.setObjectName("plcTablesAddButton")
        self.field.returnPressed.connect(lambda: self.add_requested.emit(self.field.text()))
        self.button.clicked.connect(lambda: self.add_requested.emit(self.field.text()))
        row.addWidget(self.label)
        row.addWidget(self.field, 1)
        row.addWidget(self.button)
        layout.addLayout(row)
        self.error = QLabel(self)
        self.error.setObjectName("plcTablesAddError")
        self.error.setStyleSheet("color:#c00000;")
        self.error.setWordWrap(True)
        self.error.hide()
        layout.addWidget(self.error)

    def say(self, text: str) -> None:
        """The reason a device was refused, under the field ("" hides it)."""
        self.error.setText(text)
        self.error.setVisible(bool(text))

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.label.setText(translate("PlcTables", "&Add:"))
        self.field.setPlaceholderText(translate("PlcTables", "devices, e.g. D500, T5, D0-D9"))
        self.button.setText(translate("PlcTables", "Add"))
        self.field.setToolTip(translate(
            "PlcTables", "Any timer, counter or register of the PLC, used by the program or "
            "not; a value is typed in its cell as 100, K100 or H64"))
