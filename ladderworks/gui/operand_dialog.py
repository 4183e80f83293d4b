"""The operands of an element drawn from a source's own model (an S7 box's PT, an instance,
a comparison's IN1 and IN2): one line each, as the source writes them."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QFormLayout, QLabel, QLineEdit, QWidget


class OperandDialog(QDialog):
    """One line edit per operand; `texts()` after OK."""

    def __init__(self, title: str, operands: list[tuple[str, str]],
                 parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("operand_dialog")
        self.setWindowTitle(QCoreApplication.translate("OperandDialog", "Operands of {0}")
                            .format(title))
        form = QFormLayout(self)
        hint = QLabel(QCoreApplication.translate(
            "OperandDialog", 'As TIA Portal writes them: "Start", #Timer, %MW2, T#10s, 5'), self)
        hint.setWordWrap(True)
        form.addRow(hint)
        self.edits: list[QLineEdit] = []
        for name, text in operands:
            edit = QLineEdit(text, self)
            edit.setObjectName("operand_" + name)
            self.edits.append(edit)
            form.addRow(name, edit)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                   | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)

    def texts(self) -> list[str]:
        """The operands as typed, in order."""
        return [edit.text() for edit in self.edits]
