"""Edit › Find / Replace (Ctrl+F / Ctrl+H): addresses and symbols across the program."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import (
    QCheckBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP, Refused
from ladderworks.core.ladder import Coil, Contact, Edit
from ladderworks.core.ladder.find_replace import (
    Found,
    Query,
    find,
    parse_query,
    replacement_address,
    replacements,
)
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.network_item import network_tag
from ladderworks.gui.editor.step_name import NamedCommand, StepName
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.family_words import replace_example, xref_example
from ladderworks.gui.find_texts import TextHit, find_in_texts
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate


class ReplaceAllCommand(NamedCommand):
    """Replace all: the edits of every network it touches, one undo step."""

    def __init__(self, editor: LadderEditor, edits: list[tuple[int, Edit]],
                 name: StepName) -> None:
        super().__init__(name)
        self._editor = editor
        self._edits = edits  # applied by redo; redo keeps the inverses for undo

    def _apply(self) -> None:
        self._edits = self._editor.model.apply_many(self._edits)

    def redo(self) -> None:
        """Replace the addresses."""
        self._apply()

    def undo(self) -> None:
        """Put the old addresses back."""
        self._apply()


def _position(hit: Found | TextHit) -> tuple[int, int, int]:
    """Where a hit is in program order (a network comment line before the network's cells)."""
    if isinstance(hit, TextHit) and hit.comment_line is not None:
        return hit.network, -1, hit.comment_line
    row, col = hit.cell if hit.cell is not None else (0, 0)
    return hit.network, row, col


class FindReplaceDialog(Retranslating, QDialog):
    """Find next/previous, Replace, Replace all over the editor's networks; hits move its
    cursor."""

    def __init__(self, editor: LadderEditor, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dialog_find_replace")
        self.editor = editor
        self.find_text = QLineEdit(self)
        self.find_text.setObjectName("find_text")
        self.find_text.setClearButtonEnabled(True)
        self.replace_text = QLineEdit(self)
        self.replace_text.setObjectName("replace_text")
        editor.model.document_reset.connect(self._family_texts)  # another program's family
        self.replace_text.setClearButtonEnabled(True)
        self.message = QLabel(self)
        self.message.setObjectName("find_message")
        self.message.setWordWrap(True)
        self._find_label = QLabel(self)
        self._replace_label = QLabel(self)
        form = QFormLayout()
        form.addRow(self._find_label, self.find_text)
        form.addRow(self._replace_label, self.replace_text)
        self.in_texts = QCheckBox(self)  # comments and the manual's signal descriptions too
        self.in_texts.setObjectName("find_in_texts")
        self.in_texts.toggled.connect(lambda _on: self.message.clear())
        form.addRow(self.in_texts)
        self.buttons = QDialogButtonBox(self)
        self.find_next_button = self._button("find_next", self.find_next)
        self.find_previous_button = self._button("find_previous", self.find_previous)
        self.replace_button = self._button("replace_one", self.replace_one)
        self.replace_all_button = self._button("replace_all", self.replace_all)
        self.close_button = self._button("find_close", self.close)
        self.find_next_button.setDefault(True)  # ENTER in a field: Find next
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.message)
        layout.addWidget(self.buttons)
        self.find_text.textChanged.connect(lambda _text: self.message.clear())
        # the hits of the last search, kept while the drawing is unchanged (a real program
        # has 140,000 cells: Find next again is then immediate)
        self._generation = 0
        editor.undo_stack.indexChanged.connect(self._drawing_changed)
        self._cache: tuple[object, int, str, list[Found]] | None = None
        self._text_cache: tuple[object, int, str, str, list[TextHit]] | None = None
        self.retranslate()

    def _button(self, name: str, slot: object) -> QPushButton:
        button = QPushButton(self)
        button.setObjectName(name)
        button.setAutoDefault(False)
        self.buttons.addButton(button, QDialogButtonBox.ButtonRole.ActionRole)
        button.clicked.connect(slot)
        return button

    def start(self, replacing: bool) -> None:
        """Show the dialog, the find field filled with the address at the cursor when empty."""
        if not self.find_text.text().strip():
            address = self._address_at_cursor()
            if address:
                self.find_text.setText(address)
        self.show()
        self.raise_()
        self.activateWindow()
        field = self.replace_text if replacing and self.find_text.text() else self.find_text
        field.setFocus()
        field.selectAll()

    def _address_at_cursor(self) -> str:
        index, row, col = self.editor.cursor_cell
        if index >= len(self.editor.networks):
            return ""
        found = self.editor.networks[index].element_at(row, col)
        if found is not None and isinstance(found[1], Contact | Coil) and found[1].address:
            return self.editor.spell_address(found[1].address)
        return ""

    # -- finding -------------------------------------------------------------------------

    def query(self) -> Query | None:
        """The query typed in the find field (None when blank)."""
        return parse_query(self.find_text.text(), self.editor.model.symbols,
                           self.editor.model.dialect)

    def hits(self) -> list[Found]:
        """Every place the query finds, in program order (the whole program is laid out)."""
        query = self.query()
        if query is None:
            return []
        self.editor.finish_loading()
        networks = self.editor.networks  # a new list for each program shown
        cache = self._cache
        if (cache is not None and cache[0] is networks and cache[1] == self._generation
                and cache[2] == self.find_text.text()):
            return cache[3]
        hits = find(networks, query, self.editor.model.symbols)
        self._cache = (networks, self._generation, self.find_text.text(), hits)
        return hits

    def found(self) -> list[Found | TextHit]:
        """What Find next / previous go through: the address hits, and with "Also in comments
        and signal descriptions" the places whose texts hold the words, in program order."""
        hits: list[Found | TextHit] = list(self.hits())
        if not self.in_texts.isChecked() or not self.find_text.text().strip():
            return hits
        self.editor.finish_loading()
        networks, text = self.editor.networks, self.find_text.text()
        language = QCoreApplication.translate("FindReplace", "Find:")  # descriptions follow it
        cache = self._text_cache
        if (cache is not None and cache[0] is networks and cache[1] == self._generation
                and cache[2] == text and cache[3] == language):
            more = cache[4]
        else:
            more = find_in_texts(networks, text, self.editor.model.symbols)
            self._text_cache = (networks, self._generation, text, language, more)
        seen = {_position(hit) for hit in hits}
        return sorted(hits + [hit for hit in more if _position(hit) not in seen], key=_position)

    def _drawing_changed(self, _index: int) -> None:
        self._generation += 1

    def find_next(self) -> Found | TextHit | None:
        """Move the editor's cursor to the next hit after it (wrapping round); None if none."""
        hits = self.found()
        if not hits:
            self._say(translate("FindReplace", "Not found"))
            return None
        here = self.editor.cursor_cell
        number = next((k for k, hit in enumerate(hits) if _position(hit) > here), 0)
        self._go_to(hits, number)
        return hits[number]

    def find_previous(self) -> Found | TextHit | None:
        """Move the editor's cursor to the hit before it (wrapping round); None if none."""
        hits = self.found()
        if not hits:
            self._say(translate("FindReplace", "Not found"))
            return None
        here = self.editor.cursor_cell
        before = [k for k, hit in enumerate(hits) if _position(hit) < here]
        number = before[-1] if before else len(hits) - 1
        self._go_to(hits, number)
        return hits[number]

    def find_again(self, forward: bool) -> Found | TextHit | None:
        """Find next (F3) or previous (Shift+F3) with the text already typed; the message
        says "Not found" for none."""
        return self.find_next() if forward else self.find_previous()

    def _go_to(self, hits: list[Found | TextHit], number: int) -> None:
        hit = hits[number]
        self.editor.selection = None
        network, row, col = _position(hit)
        self.editor.jump_to(network, max(row, 0), col if row >= 0 else 0)  # in mid-view
        label = self.editor.networks[hit.network].label
        where = translate("FindReplace", "network {0}").format(hit.network + 1)
        if label:  # the LADDER-III label beside the number the console shows (N15)
            where = translate("FindReplace", "{0} ({1})").format(network_tag(hit.network + 1),
                                                                 label)
        what = (self.editor.spell_address(hit.address) if hit.address is not None
                else translate("FindReplace", "network comment"))
        self._say(translate("FindReplace", "{0} of {1}: {2}, {3}").format(
            number + 1, len(hits), where, what))

    def _current(self, hits: list[Found]) -> list[Found]:
        """The hits at the editor's cursor."""
        here = self.editor.cursor_cell
        return [hit for hit in hits if _position(hit) == here]

    def _say(self, text: str) -> None:
        self.message.setText(text)

    # -- replacing -----------------------------------------------------------------------

    def _new_address(self, query: Query | None) -> Address | None:
        try:
            return replacement_address(self.replace_text.text(), query, self.editor.model.symbols,
                                       self.editor.model.dialect)
        except Refused as refused:
            self._say(diagnostic_text(refused.diagnostic))
            return None

    def replace_one(self) -> bool:
        """Replace the hit at the cursor (one undo step), then find the next; False if none."""
        query = self.query()
        new = self._new_address(query)
        if new is None or query is None:
            return False
        hits = self.hits()
        current = self._current(hits)
        if not current:
            self.find_next()
            return False
        [(index, edit)] = replacements(self.editor.networks, current, query, new,
                                       self.replace_text.text(), self.editor.spell_address)
        name = StepName("FindReplace", QT_TRANSLATE_NOOP("FindReplace", "Replace {0} with {1}"),
                        (query.text, str(new)))
        self.editor.edits.run_edit(index, edit.apply, name)
        if self.hits():
            self.find_next()
        else:
            self._say(translate("FindReplace", "Replaced; no more found"))
        return True

    def replace_all(self) -> int:
        """Replace every hit: one undo step; the number of places replaced."""
        query = self.query()
        new = self._new_address(query)
        if new is None or query is None:
            return 0
        hits = self.hits()
        if not hits:
            self._say(translate("FindReplace", "Not found"))
            return 0
        edits = replacements(self.editor.networks, hits, query, new, self.replace_text.text(),
                             self.editor.spell_address)
        self.editor.undo_stack.push(ReplaceAllCommand(
            self.editor, edits,
            StepName("FindReplace", QT_TRANSLATE_NOOP("FindReplace", "Replace all {0} with {1}"),
                     (query.text, str(new)))))
        self._say(translate("FindReplace", "{0} replaced in {1} networks").format(
            len(hits), len(edits)))
        return len(hits)

    # -- language ------------------------------------------------------------------------

    def _family_texts(self) -> None:
        """The fields' examples in the devices of the program's family."""
        dialect = self.editor.model.dialect
        self.find_text.setPlaceholderText(translate(
            "FindReplace", "Address, symbol or words, {0}").format(xref_example(dialect)))
        self.replace_text.setPlaceholderText(translate(
            "FindReplace", "Address or symbol, {0}").format(replace_example(dialect)))

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("FindReplace", "Find and replace"))
        self._find_label.setText(translate("FindReplace", "Find:"))
        self._replace_label.setText(translate("FindReplace", "Replace with:"))
        self._family_texts()
        self.find_next_button.setText(translate("FindReplace", "Find &next"))
        self.find_previous_button.setText(translate("FindReplace", "Find &previous"))
        self.replace_button.setText(translate("FindReplace", "&Replace"))
        self.replace_all_button.setText(translate("FindReplace", "Replace &all"))
        self.close_button.setText(translate("FindReplace", "Close"))
        self.in_texts.setText(translate("FindReplace", "Also in comments and signal descriptions"))
        self.in_texts.setToolTip(translate(
            "FindReplace", "Find the words in the elements' comments, the program's comments "
            "of its addresses, the manual's signal descriptions and the network comments"))
