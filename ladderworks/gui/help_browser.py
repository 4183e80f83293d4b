"""The instruction help window: every instruction of the table and its reference entry."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import NamedTuple

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
from ladderworks.core.instructions import ALL, BASIC, Kind, lookup
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.screen_fit import fit_to_screen, keep_on_screen
from ladderworks.gui.translation import instruction_title, ui_is_turkish
from ladderworks.paths import help_pages

translate = QCoreApplication.translate
KEY_ROLE = Qt.ItemDataRole.UserRole + 1  # a list item's reference key
SEARCH_ROLE = Qt.ItemDataRole.UserRole + 2  # what the search looks in (casefolded)
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


LIST_WIDTH = 340  # the widest the list's text gets, in pixels


class Entry(NamedTuple):
    """One line of the help's list: the instruction it names ("" for a dialect's contacts and
    coils), the key of its reference entry and its text."""

    name: str
    key: str
    text: str
    also: str = ""  # more names the search finds it by (a dialect's every contact and coil)


def basic_key(dialect: str) -> str:
    """The key of a dialect's entry for its contacts, coils and blocks (the table's rows)."""
    return f"instr-{dialect}-basic"


def listed_rows() -> list[Entry]:
    """Every instruction the help lists: the PMC's, then each dialect's contacts and coils (one
    entry, in its spelling: `LD, LDI, … (Delta DVP)`) and its rows as it writes them
    (`CNT (Delta DVP)`; a row that pushes, `.STK`, is its plain form's entry)."""
    rows = [Entry(spec.name, spec.help_key, f"{spec.name} — {instruction_title(spec)}")
            for spec in ALL]
    for dialect in dialects.every():
        names = list(dict.fromkeys(dialect.instruction_name(spec) for spec in BASIC))
        title = translate("InstructionHelp", "Contacts, coils and blocks")
        rows.append(Entry("", basic_key(dialect.name),  # the list stays narrow: 3 names shown
                          f"{', '.join(names[:3])}… ({dialect.title}) — {title}",
                          " ".join(names)))
        for spec in dialect.rows:
            if not spec.name.endswith(STK):
                name = dialect.instruction_name(spec)
                rows.append(Entry(spec.name, spec.help_key,
                                  f"{name} ({dialect.title}) — {instruction_title(spec)}"))
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
        for entry in listed_rows():
            item = QListWidgetItem(entry.text)
            item.setToolTip(entry.text)
            item.setData(Qt.ItemDataRole.UserRole, entry.name)
            item.setData(KEY_ROLE, entry.key)
            item.setData(SEARCH_ROLE, f"{entry.text} {entry.also}".casefold())
            self.list.addItem(item)
        # as wide as its widest entry, up to LIST_WIDTH: a longer title runs past the edge (its
        # tooltip shows it whole) so that the entry's text keeps its room on a small screen
        scroll = self.list.verticalScrollBar().sizeHint().width()
        self.list.setMinimumWidth(min(self.list.sizeHintForColumn(0), LIST_WIDTH) + scroll
                                  + 2 * self.list.frameWidth() + 8)

    def showEvent(self, event: QShowEvent) -> None:
        """Shown wholly on the screen, not centred half off it over a larger main window."""
        super().showEvent(event)
        keep_on_screen(self)

    def show_instruction(self, name: str, dialect: str | None = None) -> bool:
        """Select and show the entry of instruction `name` (a dialect's pushing form, `.STK`:
        its plain form's; a contact or coil of a `dialect` program: that dialect's entry of
        contacts and coils); False if there is none."""
        self.filter.clear()
        spec = lookup(name)
        basic = spec is not None and spec.kind is Kind.BASIC and not spec.dialect
        if basic and dialects.get(dialect) is not None and \
                self._select(KEY_ROLE, basic_key(str(dialect))):
            return True
        return any(self._select(Qt.ItemDataRole.UserRole, wanted) for wanted in (
            name, name[: -len(STK)] if name.endswith(STK) else name))

    def _select(self, role: int, value: str) -> bool:
        """Select and show the first item whose `role` data is `value`."""
        for row in range(self.list.count()):
            item = self.list.item(row)
            if value and item.data(role) == value:
                self.list.setCurrentItem(item)
                self._show(item)
                return True
        return False

    def shown_name(self) -> str | None:
        """The instruction whose entry is shown ("" for a dialect's contacts and coils)."""
        item = self.list.currentItem()
        return None if item is None else str(item.data(Qt.ItemDataRole.UserRole))

    def shown_key(self) -> str | None:
        """The key of the entry shown."""
        item = self.list.currentItem()
        return None if item is None else str(item.data(KEY_ROLE))

    def _on_current(self, item: QListWidgetItem | None, _previous: object = None) -> None:
        if item is not None:
            self._show(item)

    def _show(self, item: QListWidgetItem) -> None:
        key = str(item.data(KEY_ROLE))
        language = "tr" if ui_is_turkish() else "en"
        section = reference_sections(language).get(key) or reference_sections("en").get(key)
        if section is None:
            section = "## " + item.text() + "\n\n" + translate(
                "InstructionHelp", "No reference entry for this instruction.")
        self.browser.setMarkdown(section)

    def _apply_filter(self, text: str) -> None:
        needle = text.strip().casefold()
        for row in range(self.list.count()):
            item = self.list.item(row)
            item.setHidden(bool(needle) and needle not in str(item.data(SEARCH_ROLE)))

    def retranslate(self) -> None:
        """Set the texts in the current language."""
        self.setWindowTitle(translate("InstructionHelp", "Instruction reference"))
        self.filter.setPlaceholderText(translate("InstructionHelp", "Search, e.g. TMR"))
        shown = self.shown_key()
        self._fill()
        if shown is not None:
            self._select(KEY_ROLE, shown)
