"""The tool palette dock (the manual's main tool bag): tool buttons and the function list."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QSize, Qt, Signal
from PySide6.QtGui import QAction, QFont, QStandardItemModel
from PySide6.QtWidgets import (
    QComboBox,
    QDockWidget,
    QFrame,
    QLabel,
    QScrollArea,
    QSizePolicy,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.core.dialects.functions import is_contact, same_operation
from ladderworks.core.dialects.functions import palette_groups as dialect_groups
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.instructions import InstructionSpec, lookup, palette_groups
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.translation import instruction_title

# The title of each palette group, by the rows' `source` (a source without one shows its name).
GROUP_TITLES = {"seed": QT_TRANSLATE_NOOP("ToolPalette", "Seed manual instructions"),
                "pmc": QT_TRANSLATE_NOOP("ToolPalette", "FANUC PMC instructions"),
                "delta": QT_TRANSLATE_NOOP("ToolPalette", "Delta DVP instructions"),
                "fatek": QT_TRANSLATE_NOOP("ToolPalette", "Fatek FBs instructions"),
                "delta.structure": QT_TRANSLATE_NOOP("ToolPalette", "Delta DVP program structure"),
                "delta.contacts": QT_TRANSLATE_NOOP("ToolPalette", "Delta DVP contacts"),
                "fatek.structure": QT_TRANSLATE_NOOP("ToolPalette", "Fatek FBs program structure"),
                "fatek.contacts": QT_TRANSLATE_NOOP("ToolPalette", "Fatek FBs contacts"),
                "s7": QT_TRANSLATE_NOOP("ToolPalette", "Siemens S7-1200 instructions"),
                "s7.structure": QT_TRANSLATE_NOOP("ToolPalette", "S7-1200 program structure"),
                "s7.contacts": QT_TRANSLATE_NOOP("ToolPalette", "S7-1200 contacts")}


def function_groups(dialect: str | None) -> tuple[tuple[str, tuple[InstructionSpec, ...]], ...]:
    """The palette's groups for a program of `dialect`: its own boxes, program structure and
    contacts (`dialects.functions.palette_groups`), else the PMC's rows."""
    return dialect_groups(dialect) or palette_groups()


def entry_name(spec: InstructionSpec) -> str:
    """A palette entry's name as the program's text writes it: `TMR`, `FUN 11 (+)`; a contact
    by each of its forms, `LD= / AND= / OR=`."""
    if not spec.dialect:
        return spec.name
    spell = spelling(spec.dialect)
    if is_contact(spec):
        return " / ".join(spell.name(row) for row in same_operation(spec))
    return spell.name(spec)


class ToolPalette(Retranslating, QDockWidget):
    """A dock with one button per tool action and the drop-down of functional instructions."""

    function_chosen = Signal(str)  # instruction name

    def __init__(self, actions: list[QAction], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dock_palette")
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.setSpacing(2)
        self.buttons: list[QToolButton] = []
        for action in actions:
            button = QToolButton(body)
            button.setObjectName("button_" + action.objectName())
            button.setDefaultAction(action)
            button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)
            button.setIconSize(QSize(24, 24))
            button.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
            button.setAutoRaise(True)
            # no Tab stop: letter keys in the grid and the Tools menu pick tools, and Tab from
            # the grid reaches the function list at once rather than after fifteen buttons
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            layout.addWidget(button)
            self.buttons.append(button)
        self._function_label = QLabel(body)
        layout.addSpacing(6)
        layout.addWidget(self._function_label)
        self.functions = QComboBox(body)
        self.functions.setObjectName("function_combo")
        self._groups: list[tuple[int, str]] = []  # rows of the group titles (not choosable)
        self.dialect: str | None = None  # the program's: its boxes are offered
        self._fill(None)
        self.functions.currentIndexChanged.connect(self._on_function)
        self.functions.activated.connect(self._on_function)  # chosen again: the tool again
        layout.addWidget(self.functions)
        layout.addStretch(1)
        body.setMaximumWidth(230)
        scroll = QScrollArea(self)  # fifteen tools: scroll rather than overlap on small screens
        scroll.setObjectName("palette_scroll")
        scroll.setWidget(body)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setMaximumWidth(body.maximumWidth() + scroll.verticalScrollBar().sizeHint().width())
        self.setWidget(scroll)
        self.retranslate()

    def _fill(self, dialect: str | None) -> None:
        self.functions.clear()
        self._groups = []
        for source, specs in function_groups(dialect):
            self._add_group_title(source)
            for spec in specs:
                self.functions.addItem(spec.name, spec.name)
        self.functions.setCurrentIndex(1)

    def set_dialect(self, dialect: str | None) -> None:
        """Offer the functional instructions of a program of `dialect` (the PMC's for
        "seed"/"fanuc"); the first is chosen when the list changes."""
        if function_groups(dialect) == function_groups(self.dialect):
            self.dialect = dialect
            return
        self.dialect = dialect
        blocked = self.functions.blockSignals(True)
        self._fill(dialect)
        self.functions.blockSignals(blocked)
        self.retranslate()

    def _add_group_title(self, source: str) -> None:
        """A bold, disabled row naming the group of instructions below it (their `source`)."""
        row = self.functions.count()
        self.functions.addItem("", None)
        model = self.functions.model()
        assert isinstance(model, QStandardItemModel)
        item = model.item(row)
        item.setEnabled(False)
        font = QFont(item.font())
        font.setBold(True)
        item.setFont(font)
        self._groups.append((row, source))

    def current_function(self) -> str:
        """The instruction name chosen in the drop-down."""
        return str(self.functions.currentData())

    def set_function(self, name: str) -> None:
        """Choose `name` in the drop-down."""
        index = self.functions.findData(name)
        if index < 0:
            raise KeyError(name)
        self.functions.setCurrentIndex(index)

    def _on_function(self, _index: int) -> None:
        self.function_chosen.emit(self.current_function())

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(QCoreApplication.translate("ToolPalette", "Tools"))
        self._function_label.setText(QCoreApplication.translate("ToolPalette", "Function:"))
        for row, source in self._groups:
            title = QCoreApplication.translate("ToolPalette", GROUP_TITLES.get(source, source))
            self.functions.setItemText(row, f"— {title} —")
        titles = {row for row, _ in self._groups}
        for index in range(self.functions.count()):
            if index in titles:
                continue
            spec = lookup(str(self.functions.itemData(index)))
            assert spec is not None
            title = instruction_title(spec)
            self.functions.setItemText(index, f"{entry_name(spec)} — {title}")
            self.functions.setItemData(index, title, Qt.ItemDataRole.ToolTipRole)
