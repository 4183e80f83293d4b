"""The instruction help window: every instruction of the table and its reference entry."""

from __future__ import annotations

import re
from functools import lru_cache

from PySide6.QtCore import QCoreApplication, QSize, Qt
from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import (
    QDialog,
    QHBoxLayout,
    QLineEdit,
    QListWidget,
    QListWidgetItem,
    QSplitter,
    QTextBrowser,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.il.textform import split_lines
from ladderworks.core.instructions import ALL, InstructionSpec, lookup
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.screen_fit import fit_to_screen, keep_on_screen
from ladderworks.gui.translation import instruction_title, ui_is_turkish
from ladderworks.paths import help_pages

translate = QCoreApplication.translate
STK = ".STK"  # a row that pushes: its entry is its plain form's (RD.STK is RD's own)

_ANCHOR = re.compile(r'\s*<a id="([^"]+)"></a>')  # one or more at a heading's end
# where a rule comes from ([seed], [pmc; X22], [choice]): for the docs' readers, not the user
_SOURCE_MARK = re.compile(r"\s*\[(?:seed|pmc|choice)(?:;[^\]]*)?\]")


def without_source_marks(text: str) -> str:
    """The reference text without the provenance marks of `docs/instructions.md`."""
    return _SOURCE_MARK.sub("", text)


@lru_cache(maxsize=2)
def reference_sections(language: str = "en") -> dict[str, str]:
    """The markdown of each instruction's entry in the reference of `language` (the PMC's
    page and each dialect's), by help key; a heading with several anchors serves each."""
    sections: dict[str, str] = {}
    keys: list[str] = []
    lines: list[str] = []

    def close() -> None:
        for key in keys:
            sections[key] = "\n".join(lines).strip() + "\n"

    for path in help_pages(language):
        text = path.read_text("utf-8") if path.exists() else ""
        for line in split_lines(text):
            heading = line.startswith(("## ", "### "))
            if heading:
                close()
                keys = _ANCHOR.findall(line)
                lines = [without_source_marks(_ANCHOR.sub("", line)).rstrip().replace(
                    "### ", "## ", 1)]
                continue
            if keys:
                lines.append(without_source_marks(line))
        close()
        keys = []
    return sections


def listed_rows() -> list[tuple[InstructionSpec, str]]:
    """Every instruction the help lists, with its entry's text: the PMC's, then each
    dialect's rows as the dialect writes them (`CNT (Delta DVP)`; a row that pushes, `.STK`,
    is its plain form's entry)."""
    rows = [(spec, f"{spec.name} — {instruction_title(spec)}") for spec in ALL]
    for dialect in dialects.every():
        for spec in dialect.rows:
            if not spec.name.endswith(STK):
                name = dialect.instruction_name(spec)
                rows.append((spec, f"{name} ({dialect.title}) — {instruction_title(spec)}"))
    return rows


class InstructionHelp(Retranslating, QDialog):
    """A non-modal window: the instruction list on the left, the chosen entry on the right."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dialog_instruction_help")
        fit_to_screen(self, QSize(900, 600))
        self.filter = QLineEdit(self)
        self.filter.setObjectName("help_filter")
        self.filter.setClearButtonEnabled(True)
        self.filter.textChanged.connect(self._apply_filter)
        self.list = QListWidget(self)
        self.list.setObjectName("help_list")
        self.browser = QTextBrowser(self)
        self.browser.setObjectName("help_text")
        self.browser.setOpenExternalLinks(False)
        left = QWidget(self)
        column = QVBoxLayout(left)
        column.setContentsMargins(0, 0, 0, 0)
        column.addWidget(self.filter)
        column.addWidget(self.list)
        splitter = QSplitter(Qt.Orientation.Horizontal, self)
        splitter.addWidget(left)
        splitter.addWidget(self.browser)
        splitter.setStretchFactor(1, 3)
        layout = QHBoxLayout(self)
        layout.addWidget(splitter)
        self._fill()
        self.list.currentItemChanged.connect(self._on_current)
        self.retranslate()

    def _fill(self) -> None:
        self.list.clear()
        for spec, text in listed_rows():
            item = QListWidgetItem(text)
            item.setToolTip(text)
            item.setData(Qt.ItemDataRole.UserRole, spec.name)
            self.list.addItem(item)
        # the longest name whole: the list is as wide as its widest entry
        scroll = self.list.verticalScrollBar().sizeHint().width()
        self.list.setMinimumWidth(self.list.sizeHintForColumn(0) + scroll
                                  + 2 * self.list.frameWidth() + 8)

    def showEvent(self, event: QShowEvent) -> None:
        """Shown wholly on the screen, not centred half off it over a larger main window."""
        super().showEvent(event)
        keep_on_screen(self)

    def show_instruction(self, name: str) -> bool:
        """Select and show the entry of instruction `name` (a dialect's pushing form, `.STK`:
        its plain form's); False if there is none."""
        self.filter.clear()
        for wanted in (name, name[: -len(STK)] if name.endswith(STK) else name):
            spec = lookup(wanted)
            for row in range(self.list.count()):
                item = self.list.item(row)
                if spec is not None and item.data(Qt.ItemDataRole.UserRole) == spec.name:
                    self.list.setCurrentItem(item)
                    self._show(spec)
                    return True
        return False

    def shown_name(self) -> str | None:
        """The instruction whose entry is shown."""
        item = self.list.currentItem()
        return None if item is None else str(item.data(Qt.ItemDataRole.UserRole))

    def _on_current(self, item: QListWidgetItem | None, _previous: object = None) -> None:
        if item is not None:
            spec = lookup(str(item.data(Qt.ItemDataRole.UserRole)))
            if spec is not None:
                self._show(spec)

    def _show(self, spec: InstructionSpec) -> None:
        language = "tr" if ui_is_turkish() else "en"
        section = (reference_sections(language).get(spec.help_key)
                   or reference_sections("en").get(spec.help_key))
        if section is None:
            section = "## " + spec.name + "\n\n" + translate(
                "InstructionHelp", "No reference entry for this instruction.")
        self.browser.setMarkdown(section)

    def _apply_filter(self, text: str) -> None:
        needle = text.strip().casefold()
        for row in range(self.list.count()):
            item = self.list.item(row)
            item.setHidden(bool(needle) and needle not in item.text().casefold())

    def retranslate(self) -> None:
        """Set the texts in the current language."""
        self.setWindowTitle(translate("InstructionHelp", "Instruction reference"))
        self.filter.setPlaceholderText(translate("InstructionHelp", "Search, e.g. TMR"))
        shown = self.shown_name()
        self._fill()
        if shown is not None:
            self.show_instruction(shown)
