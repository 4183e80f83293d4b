"""The status bar's cell text kept true: the cell under the cursor as it is now."""

from __future__ import annotations

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QLabel

from ladderworks.gui.editor.view import LadderEditor


class CellStatus(QObject):
    """Describes the cursor's cell in `label` again whenever the cursor is put on a cell (a
    click, a key, an element placed in the coil column) and whenever the networks change (an
    address typed, undo, replace all): never the text of a cell as it was before an edit, nor
    of the column clicked when the coil went elsewhere. The mouse still shows the cell it
    passes over (`LadderEditor.hover_changed`) until the next of these."""

    def __init__(self, editor: LadderEditor, label: QLabel) -> None:
        super().__init__(label)
        self.editor = editor
        self.label = label
        model = editor.model
        editor.cursor_placed.connect(self.refresh)
        model.network_changed.connect(lambda _index: self.refresh())
        model.networks_changed.connect(lambda _indexes: self.refresh())
        model.network_removed.connect(lambda _index: self.refresh())
        model.networks_inserted.connect(lambda _first, _count: self.refresh())

    def refresh(self) -> None:
        """Describe the cursor's cell now (nothing while the program is shown as text)."""
        editor = self.editor
        index, row, col = editor.cursor_cell
        if editor.model.showing_text or not 0 <= index < len(editor.networks):
            return
        self.label.setText(editor.describe_cell(index, row, col))
