"""The function property table: a dialog built from the instruction table for one function."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QHeaderView,
    QLabel,
    QLineEdit,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.functions import check_params, operand_params, operand_texts
from ladderworks.core.dialects.operand_ranges import operand_ranges
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il import Instruction
from ladderworks.core.il.printer import print_instruction
from ladderworks.core.instructions import InstructionSpec, Param, ParamKind
from ladderworks.core.ladder.edits import function_params
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.help_browser import InstructionHelp
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.translation import instruction_label, instruction_title, param_label

FORMS = "mode"  # a Fatek row's forms, typed as P, D or DP (core/dialects/fatek/editing.py)


def allowed_text(param: Param, dialect: str = "seed", spec: InstructionSpec | None = None
                 ) -> str:
    """What may be typed for `param` in a program of `dialect`, from the instruction table (a
    dialect row's operand: the ranges its reader takes, `T0–T255`)."""
    dialect_program = dialects.get(dialect) is not None
    if dialect_program and spec is not None and spec.dialect == dialect \
            and param.name != FORMS:
        params = operand_params(spec)
        ranges = operand_ranges(spec.name, dialect)
        if param in params and params.index(param) < len(ranges) \
                and ranges[params.index(param)]:
            return ", ".join(ranges[params.index(param)])
    if dialect_program and param.kind is ParamKind.NUMBER and param.name == FORMS:
        return QCoreApplication.translate(
            "FunctionDialog", "empty, P (on the rising edge), D (32-bit) or DP")
    if dialect_program and param.kind in (ParamKind.LABEL, ParamKind.PROGRAM):
        return QCoreApplication.translate("FunctionDialog", "P{0} to P{1}").format(
            param.lo, param.hi)
    if param.kind is ParamKind.NUMBER:
        if param.choices:
            return QCoreApplication.translate("FunctionDialog", "one of {0}").format(
                ", ".join(str(c) for c in param.choices))
        return QCoreApplication.translate("FunctionDialog", "{0} to {1}").format(
            param.lo, param.highest(dialect))
    if dialects.get(dialect) is not None and param.kind in (ParamKind.ADDRESS, ParamKind.VALUE):
        return (QCoreApplication.translate("FunctionDialog", "a device of this PLC")
                if param.kind is ParamKind.ADDRESS else
                QCoreApplication.translate("FunctionDialog", "a constant or a device of this PLC"))
    if param.kind is ParamKind.ADDRESS:
        if isinstance(param.width, int):
            return QCoreApplication.translate(
                "FunctionDialog", "byte address ({0} bytes)").format(param.width)
        return QCoreApplication.translate("FunctionDialog", "byte address")
    if param.kind is ParamKind.VALUE:
        return QCoreApplication.translate("FunctionDialog", "constant or byte address")
    if param.kind is ParamKind.MASK:
        return QCoreApplication.translate("FunctionDialog", "up to 4 binary digits, e.g. 1111")
    if param.kind is ParamKind.PROGRAM:
        return QCoreApplication.translate("FunctionDialog", "P{0} to P{1}").format(
            param.lo, param.hi)
    if param.kind is ParamKind.LABEL:
        return QCoreApplication.translate("FunctionDialog", "L{0} to L{1}").format(
            param.lo, param.hi)
    if param.kind is ParamKind.RAW:
        return QCoreApplication.translate(
            "FunctionDialog", "constant or address, kept as written")
    return QCoreApplication.translate("FunctionDialog", "values separated by spaces")


def check_function(spec: InstructionSpec, values: list[str], dialect: str = "seed") -> tuple[
        Instruction | None, list[Diagnostic]]:
    """Build the instruction from typed values, checked by the core's parser with the ranges
    of a program of `dialect` (a LADDER-III program: the 30i's; a Delta/Fatek row: by the
    dialect's reader, in its spelling)."""
    if spec.dialect:
        params, diagnostics = check_params(spec, values, spec.dialect)
        if params is None or diagnostics:
            return None, diagnostics
        return Instruction(spec.name, params=params), []
    params, diagnostics = function_params(spec.name, [v.strip() for v in values if v.strip()],
                                          dialect)
    if params is None or diagnostics:
        return None, diagnostics
    return Instruction(spec.name, params=params), []


def _value_text(param: Param, value: object) -> str:
    if param.kind is ParamKind.MASK and isinstance(value, int):
        return f"{value:04b}"
    return str(value)


class FunctionDialog(Retranslating, QDialog):
    """The property table of one functional instruction; OK only with valid parameters."""

    def __init__(self, spec: InstructionSpec, instruction: Instruction | None = None,
                 parent: QWidget | None = None, comment: str = "",
                 dialect: str = "seed") -> None:
        super().__init__(parent)
        self.setObjectName("function_dialog")
        self.spec = spec
        self.dialect = dialect  # the program's: a FANUC program takes the 30i ranges
        self.instruction: Instruction | None = None
        self.comment_text = comment
        layout = QVBoxLayout(self)
        self._title = QLabel(self)
        self._title.setWordWrap(True)
        layout.addWidget(self._title)
        self._no_params = QLabel(self)
        self._no_params.setObjectName("function_no_params")
        layout.addWidget(self._no_params)
        self.table = QTableWidget(self)
        self.table.setObjectName("function_table")
        self.table.setColumnCount(3)
        self.table.verticalHeader().hide()
        self.table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        layout.addWidget(self.table)
        self._comment_label = QLabel(self)
        layout.addWidget(self._comment_label)
        self.comment = QLineEdit(self)
        self.comment.setObjectName("function_comment")
        self.comment.setText(comment)
        layout.addWidget(self.comment)
        self.warning = QLabel(self)
        self.warning.setObjectName("function_warning")
        self.warning.setWordWrap(True)
        self.warning.setStyleSheet("color: #b00020; font-weight: bold;")
        self.warning.hide()
        layout.addWidget(self.warning)
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
            | QDialogButtonBox.StandardButton.Help, self)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        self.buttons.helpRequested.connect(self.show_help)
        self.help_window: InstructionHelp | None = None
        layout.addWidget(self.buttons)
        self._params = list(operand_params(spec))  # a dialect's: the operands of its line
        self.table.setRowCount(len(self._params))
        current = instruction.param_map() if instruction is not None else {}
        spelled = (operand_texts(spec, instruction.params)
                   if spec.dialect and instruction is not None else [])  # Delta's `K5`, `D10`
        for row, param in enumerate(self._params):
            name_item = QTableWidgetItem()
            name_item.setFlags(Qt.ItemFlag.ItemIsEnabled)
            self.table.setItem(row, 0, name_item)
            value = current.get(param.name)
            if row < len(spelled):
                text = spelled[row]
            elif isinstance(value, tuple):
                text = " ".join(str(v) for v in value)
            else:
                text = _value_text(param, value) if value is not None else ""
            self.table.setItem(row, 1, QTableWidgetItem(text))
            hint = QTableWidgetItem()
            hint.setFlags(Qt.ItemFlag.ItemIsEnabled)
            self.table.setItem(row, 2, hint)
        self.retranslate()
        # every parameter row visible without scrolling (at most 5 rows: no instruction has more)
        rows = sum(self.table.rowHeight(row) for row in range(self.table.rowCount()))
        header = self.table.horizontalHeader().sizeHint().height()
        self.table.setMinimumHeight(header + rows + 2 * self.table.frameWidth() + 2)
        self.table.setVisible(bool(self._params))  # SPE: nothing to fill in
        self._no_params.setVisible(not self._params)
        self.adjustSize()
        self.resize(max(self.width(), 560), self.height())
        if self._params:
            self.table.setCurrentCell(0, 1)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        name, title = instruction_label(self.spec), instruction_title(self.spec)
        if self.spec.dialect:
            name = spelling(self.spec.dialect).name(self.spec)
        self.setWindowTitle(f"{name} — {title}")
        self._title.setText(QCoreApplication.translate(
            "FunctionDialog", "{0} — {1}: fill in the parameters").format(name, title)
            if self._params else f"{name} — {title}")
        self._no_params.setText(QCoreApplication.translate(
            "FunctionDialog", "This instruction has no parameters."))
        self._comment_label.setText(QCoreApplication.translate(
            "FunctionDialog", "Comment (shown with the box, written after // in the file):"))
        self.table.setHorizontalHeaderLabels([
            QCoreApplication.translate("FunctionDialog", "Parameter"),
            QCoreApplication.translate("FunctionDialog", "Value"),
            QCoreApplication.translate("FunctionDialog", "Allowed"),
        ])
        for row, param in enumerate(self._params):
            self._cell(row, 0).setText(param_label(param.name))
            self._cell(row, 2).setText(allowed_text(param, self.dialect, self.spec))

    def show_help(self) -> InstructionHelp:
        """The Help button: this instruction's reference entry, beside the dialog."""
        if self.help_window is None:
            self.help_window = InstructionHelp(self)
        self.help_window.show_instruction(self.spec.name)
        self.help_window.show()
        return self.help_window

    def set_value(self, name: str, text: str) -> None:
        """Type `text` into the row of parameter `name`."""
        for row, param in enumerate(self._params):
            if param.name == name:
                self._cell(row, 1).setText(text)
                return
        raise KeyError(name)

    def values(self) -> list[str]:
        """The typed values, row by row."""
        return [self._cell(row, 1).text() for row in range(self.table.rowCount())]

    def accept(self) -> None:
        """Check with the core; on an error show the warning, mark the row and stay open."""
        self.table.setCurrentCell(-1, -1)
        instruction, diagnostics = check_function(self.spec, self.values(), self.dialect)
        for row in range(self.table.rowCount()):
            self._cell(row, 1).setBackground(QColor(Qt.GlobalColor.transparent))
        if instruction is None:
            messages = [diagnostic_text(d) for d in diagnostics] or [
                QCoreApplication.translate("FunctionDialog", "The parameters are not valid")]
            self.warning.setText("\n".join(messages))
            self.warning.show()
            bad = self._bad_row(diagnostics)
            if bad is not None:
                self._cell(bad, 1).setBackground(QColor("#ffd6d6"))
                self.table.setCurrentCell(bad, 1)
            return
        self.warning.hide()
        self.instruction = instruction
        self.comment_text = self.comment.text().strip()
        super().accept()

    def _cell(self, row: int, column: int) -> QTableWidgetItem:
        """The table's item at (row, column): every cell gets one when the dialog is built."""
        item = self.table.item(row, column)
        assert item is not None, (row, column)
        return item

    def _bad_row(self, diagnostics: list[Diagnostic]) -> int | None:
        for diagnostic in diagnostics:
            index = diagnostic.args.get("index")
            if isinstance(index, int):
                return min(max(index - 1, 0), len(self._params) - 1)
        return 0 if self._params else None

    def instruction_text(self) -> str:
        """The accepted instruction as one line of text."""
        return print_instruction(self.instruction) if self.instruction else ""


