"""The output pins dialog: which of a box's FO outputs (FO1 … FO7) it shows on its right side."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QCheckBox, QDialog, QDialogButtonBox, QLabel, QVBoxLayout, QWidget

from ladderworks.core.ladder.output_pins import PIN_BITS
from ladderworks.gui.retranslate import Retranslating


class OutputPinsDialog(Retranslating, QDialog):
    """Check boxes FO1 … FO7, checked for the pins the box shows; `bits()` after OK."""

    def __init__(self, name: str, shown: tuple[int, ...], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("output_pins_dialog")
        self.name = name
        layout = QVBoxLayout(self)
        self._label = QLabel()
        self._label.setWordWrap(True)
        layout.addWidget(self._label)
        self.boxes: dict[int, QCheckBox] = {}
        for bit in PIN_BITS:
            box = QCheckBox(f"FO{bit}")
            box.setChecked(bit in shown)
            self.boxes[bit] = box
            layout.addWidget(box)
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                        | QDialogButtonBox.StandardButton.Cancel)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        layout.addWidget(self.buttons)
        self.retranslate()

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(QCoreApplication.translate("OutputPinsDialog", "Output pins"))
        self._label.setText(QCoreApplication.translate(
            "OutputPinsDialog", "The outputs {0} shows on its right side (FO0 is its first "
            "output, always shown); draw each pin's coils on its row:").format(self.name))

    def bits(self) -> tuple[int, ...]:
        """The checked outputs' bits."""
        return tuple(bit for bit, box in self.boxes.items() if box.isChecked())
