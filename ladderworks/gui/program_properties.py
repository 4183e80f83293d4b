"""File › Program properties: the program's PMC model (chosen here), and its title, system
parameters, I/O modules, sections and text form, read-only (LADDER-III's `%@0`, `%@1`, `%@5`)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHeaderView,
    QTableWidget,
    QTableWidgetItem,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.core.il.program import FANUC, SEED, Program
from ladderworks.core.models import MODELS, model_of
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.translation import ui_is_turkish

translate = QCoreApplication.translate

# The models' titles in the UI language (a model registered later shows its English title).
MODEL_TITLES: dict[str, str] = {
    SEED: QT_TRANSLATE_NOOP("ProgramProperties", "LadderWorks (seed manual)"),
    FANUC: QT_TRANSLATE_NOOP("ProgramProperties", "FANUC Series 30i-A PMC (memory-B)"),
}


def model_title(key: str) -> str:
    """A model's title in the UI language (a dialect's own title for its one model)."""
    title = MODEL_TITLES.get(key)
    if title:
        return translate("ProgramProperties", title)
    found = dialects.get(key)
    if found is not None:
        return found.title_tr if ui_is_turkish() else found.title
    return model_of(key).title


# The `%@1` title items, in the order of the PMC title screen (FANUC-PMC.md §2).
TITLE_ITEMS: dict[int, Callable[[], str]] = {
    1: lambda: translate("ProgramProperties", "Machine-tool builder"),
    2: lambda: translate("ProgramProperties", "Machine-tool name"),
    3: lambda: translate("ProgramProperties", "PMC & NC type"),
    4: lambda: translate("ProgramProperties", "Program number"),
    5: lambda: translate("ProgramProperties", "Edition"),
    6: lambda: translate("ProgramProperties", "Drawing number"),
    7: lambda: translate("ProgramProperties", "Date"),
    8: lambda: translate("ProgramProperties", "Designed by"),
    9: lambda: translate("ProgramProperties", "ROM written by"),
    10: lambda: translate("ProgramProperties", "Remarks"),
}


def title_rows(program: Program) -> list[tuple[str, str, str]]:
    """(item number, meaning, text) of the ten title items (empty when absent) and any other
    `%@1` line, by item number; nothing for a program without a title."""
    if not program.title:
        return []
    rows = []
    for number in sorted(set(program.title) | set(TITLE_ITEMS)):
        meaning = TITLE_ITEMS.get(number)
        rows.append((str(number), meaning() if meaning else "", program.title.get(number, "")))
    return rows


def general_rows(program: Program, path: Path | None) -> list[tuple[str, str]]:
    """(property, value): file, PMC model, text form, networks, steps, symbols, messages."""
    form = program.form
    ends = {"\r\n": "CR LF", "\r": "CR", "\n": "LF"}.get(form.newline, repr(form.newline))
    other = dialects.of(program)
    dialect = ((other.title_tr if ui_is_turkish() else other.title) if other is not None
               else model_title(program.dialect))  # a Delta program: its own title
    yes, no = translate("ProgramProperties", "yes"), translate("ProgramProperties", "no")
    symbols = program.symbols
    return [
        (translate("ProgramProperties", "File"), str(path) if path else
         translate("ProgramProperties", "(not saved)")),
        (translate("ProgramProperties", "PMC model"), dialect),
        (translate("ProgramProperties", "Encoding"), form.encoding),
        (translate("ProgramProperties", "Byte order mark"), yes if form.bom else no),
        (translate("ProgramProperties", "Line ends"), ends),
        (translate("ProgramProperties", "Framed in %@A … %@E"), yes if program.framed else no),
        (translate("ProgramProperties", "Networks"), str(len(program.networks))),
        (translate("ProgramProperties", "Steps"),
         str(sum(len(n.instructions) for n in program.networks))),
        (translate("ProgramProperties", "Symbols (%@2)"),
         str(len(symbols) if symbols is not None else 0)),
        (translate("ProgramProperties", "Messages (%@4)"), str(len(program.messages))),
    ]


def section_rows(program: Program) -> list[tuple[str, str, str]]:
    """(header, line count, first line) of each section kept besides the ladder."""
    rows = []
    for section in program.sections():
        first = next((line.strip() for line in section.lines if line.strip()), "")
        rows.append((section.title, str(len(section.lines)), first))
    return rows


def _table(parent: QWidget, name: str, headers: list[str],
           rows: Sequence[tuple[str, ...]]) -> QTableWidget:
    table = QTableWidget(len(rows), len(headers), parent)
    table.setObjectName(name)
    table.setHorizontalHeaderLabels(headers)
    table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
    table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
    table.setAlternatingRowColors(True)
    table.setWordWrap(False)
    table.verticalHeader().hide()
    for row, values in enumerate(rows):
        for column, text in enumerate(values):
            item = QTableWidgetItem(text)
            item.setToolTip(text)
            table.setItem(row, column, item)
    table.resizeColumnsToContents()
    table.horizontalHeader().setStretchLastSection(True)
    table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
    return table


class ProgramPropertiesDialog(Retranslating, QDialog):
    """Read-only tabs: General, Title (`%@1`), System parameters (`%@0`), I/O modules (`%@5`),
    Sections."""

    def __init__(self, program: Program, path: Path | None, parent: QWidget | None = None,
                 choose_model: Callable[[str], None] | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dialog_program_properties")
        self.program = program
        self.path = path
        self.choose_model = choose_model  # makes a model the program's (None: read-only)
        self.model_combo = QComboBox(self)
        self.model_combo.setObjectName("properties_model")
        self.model_combo.activated.connect(self._model_chosen)
        form = QFormLayout()
        self.model_label_text = translate("ProgramProperties", "PMC model")
        form.addRow(self.model_label_text, self.model_combo)
        self.model_form = form
        self.tabs = QTabWidget(self)
        self.tabs.setObjectName("properties_tabs")
        self.tables: dict[str, QTableWidget] = {}
        self._fill()
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        buttons.rejected.connect(self.reject)
        buttons.accepted.connect(self.accept)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.tabs, 1)
        layout.addWidget(buttons)
        self.resize(720, 440)

    def retranslate(self) -> None:
        """Rebuild the tabs in the new language on a live switch (the shown tab stays)."""
        self._fill()

    def _fill_models(self) -> None:
        """Every family's models (another family's is taken when the program's instructions
        read back the same there); an unknown model is shown read-only."""
        combo = self.model_combo
        combo.clear()
        current = self.program.dialect
        models = list(MODELS.values()) if current in MODELS else []
        for model in models or [model_of(current)]:
            combo.addItem(model_title(model.key), model.key)
        combo.setCurrentIndex(max(combo.findData(current), 0))
        combo.setEnabled(self.choose_model is not None and len(models) > 1)
        combo.setToolTip(translate(
            "ProgramProperties", "The PLC the program is written for: its address map and "
            "the ranges of its instructions. A model of another PLC family is taken when every "
            "instruction reads back the same in that family's text."))
        label = self.model_form.labelForField(combo)
        if label is not None:
            label.setProperty("text", translate("ProgramProperties", "PMC model"))

    def _model_chosen(self, index: int) -> None:
        key = self.model_combo.itemData(index)
        if self.choose_model is not None and key and key != self.program.dialect:
            self.choose_model(key)  # another family: the window shows a new program, or says no
            self.program = getattr(self.parentWidget(), "program_info", self.program)
            self._fill()

    def _fill(self) -> None:
        program, path = self.program, self.path
        self.setWindowTitle(translate("ProgramProperties", "Program properties"))
        self._fill_models()
        shown = self.tabs.currentIndex()
        while self.tabs.count():
            page = self.tabs.widget(0)
            self.tabs.removeTab(0)
            if page is not None:
                page.deleteLater()
        pages: list[tuple[str, str, list[str], Sequence[tuple[str, ...]]]] = [
            ("properties_general", translate("ProgramProperties", "General"),
             [translate("ProgramProperties", "Property"),
              translate("ProgramProperties", "Value")],
             general_rows(program, path)),
            ("properties_title", translate("ProgramProperties", "Title (%@1)"),
             [translate("ProgramProperties", "Item"), translate("ProgramProperties", "Meaning"),
              translate("ProgramProperties", "Text")],
             title_rows(program)),
            ("properties_system", translate("ProgramProperties", "System parameters (%@0)"),
             [translate("ProgramProperties", "Item"), translate("ProgramProperties", "Value")],
             sorted(program.system_params.items())),
            ("properties_io", translate("ProgramProperties", "I/O modules (%@5)"),
             [translate("ProgramProperties", "Address"), translate("ProgramProperties", "Group"),
              translate("ProgramProperties", "Base"), translate("ProgramProperties", "Slot"),
              translate("ProgramProperties", "Module")],
             [(m.address, str(m.group), str(m.base), str(m.slot), m.name)
              for m in program.io_modules]),
            ("properties_sections", translate("ProgramProperties", "Sections"),
             [translate("ProgramProperties", "Header"), translate("ProgramProperties", "Lines"),
              translate("ProgramProperties", "First line")],
             section_rows(program)),
        ]
        for name, title, headers, rows in pages:
            table = _table(self.tabs, name, headers, rows)
            self.tables[name] = table
            self.tabs.addTab(table, title)
        self.tabs.setCurrentIndex(max(shown, 0))

    def texts(self, name: str) -> list[list[str]]:
        """The cells of one tab's table, row by row (for tests)."""
        table = self.tables[name]
        rows = [[table.item(r, c) for c in range(table.columnCount())]
                for r in range(table.rowCount())]
        return [[item.text() if item is not None else "" for item in row] for row in rows]
