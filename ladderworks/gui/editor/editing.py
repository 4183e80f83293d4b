"""The editor's edits at the cursor and by the tools, each pushed as an undo command."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING, cast

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QApplication

from ladderworks.core import ladder as core
from ladderworks.core.address import Address
from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.core.il import Instruction
from ladderworks.core.instructions import lookup
from ladderworks.core.ladder import (
    Coil,
    Contact,
    EditRefused,
    FunctionBox,
    LadderNetwork,
    Selection,
    Wire,
)
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.commands import NetworkEditCommand, NetworkListCommand
from ladderworks.gui.editor.step_name import StepName, editor_step
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.tools import Tool

if TYPE_CHECKING:
    from PySide6.QtCore import SignalInstance
    from PySide6.QtGui import QUndoStack
    from PySide6.QtWidgets import QWidget

    from ladderworks.gui.editor.ladder_model import LadderModel

translate = QCoreApplication.translate


class CursorEdits:
    """LadderEditor's part that turns a tool use or a menu action into an undo command on the
    model (a mixin, so the public names the window's actions call stay on the editor)."""

    if TYPE_CHECKING:  # what LadderEditor provides
        model: LadderModel
        message: SignalInstance
        cursor_cell: tuple[int, int, int]
        selection: tuple[int, Selection] | None
        function_dialog: FunctionDialog | None

        @property
        def networks(self) -> list[LadderNetwork]: ...
        @property
        def undo_stack(self) -> QUndoStack: ...
        @property
        def tool(self) -> Tool: ...
        def _place_overlays(self) -> None: ...
        def open_address_editor(self, index: int, row: int, col: int) -> None: ...
        def open_comment_editor(self, index: int, line: int) -> None: ...

    def run_edit(self, index: int, operation: Callable[[LadderNetwork], object],
                 name: StepName) -> bool:
        """Make a core edit on network `index` as an undo command named `name`; False (and a
        message) when the core refuses it."""
        try:
            edit = self.model.prepare(index, operation)
        except EditRefused as refused:
            self.message.emit(diagnostic_text(refused.diagnostic))
            return False
        self.undo_stack.push(NetworkEditCommand(self.model, index, edit, name))
        return True

    def assign_address_at_cursor(self, address: Address) -> bool:
        """Put `address` on the contact or coil at the cursor (one undo step); False if none."""
        index, row, col = self.cursor_cell
        if index >= len(self.networks) or address.bit is None:
            return False
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return False
        (r, c), _element = found
        text = str(address)
        dialect = self.model.dialect
        return self.run_edit(index, lambda n: core.set_address(n, r, c, text, dialect),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Address {0}"), text))

    def place_bit(self, index: int, row: int, col: int, element: Contact | Coil) -> None:
        """Place a contact or coil and open its address; on one of the same kind, turn it
        into `element`'s kind (NOT, SET, RST) and open its address. A coil goes to the coil
        column; a placed element is wired to its neighbours (core `place_wired`). The cursor
        goes where the element is."""
        row, col = core.target_cell(self.networks[index], row, col, element)
        found = self.networks[index].element_at(row, col)
        self.cursor_to(index, *(found[0] if found is not None else (row, col)))
        if found is not None and type(found[1]) is type(element):
            old = found[1]
            assert isinstance(old, Contact | Coil)
            if isinstance(old, Coil) and isinstance(element, Coil) and old.write != element.write:
                kind = replace(old, negated=element.negated, write=element.write)
                self.run_edit(index, lambda n: core.replace_element(n, row, col, kind),
                              editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place coil")))
            elif old.negated != element.negated:
                self.run_edit(index, lambda n: core.invert(n, row, col),
                              editor_step(QT_TRANSLATE_NOOP("LadderEditor", "NOT")))
            self.open_address_editor(index, found[0][0], found[0][1])
            return
        text = (editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place contact"))
                if isinstance(element, Contact)
                else editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place coil")))
        if self.run_edit(index, lambda n: core.place_wired(n, row, col, element), text):
            self.open_address_editor(index, row, col)

    def cursor_to(self, index: int, row: int, col: int) -> None:
        """Put the cursor on the cell where an edit put an element (no scrolling)."""
        self.cursor_cell = (index, row, col)
        self._place_overlays()

    def add_parallel(self, index: int, row: int, col: int) -> None:
        """OR: a parallel contact or coil below the one at a cell, its address opened."""
        found = self.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            self.message.emit(
                translate("LadderEditor", "Select a contact or a coil for the OR tool"))
            return
        (row, col), _old = found
        if self.run_edit(index, lambda n: core.add_parallel(n, row, col),
                         editor_step(QT_TRANSLATE_NOOP("LadderEditor", "OR"))):
            self.open_address_editor(index, row + 1, col)

    def select_element(self, index: int, row: int, col: int) -> None:
        """Select the element covering a cell (nothing on a wire or an empty cell)."""
        found = self.networks[index].element_at(row, col)
        if found is None or isinstance(found[1], Wire):
            self.selection = None
        else:
            (r, c), element = found
            cells = self.networks[index].footprint((r, c), element)
            self.selection = (index, Selection.spanning(cells[0], cells[-1]))
        self._place_overlays()

    def select_rectangle(self, index: int, corner: tuple[int, int],
                         other: tuple[int, int]) -> None:
        """Select the cells between two corners of one network (rows and columns clamped)."""
        net = self.networks[index]
        last_row = max(net.rows - 1, 0)

        def clamp(cell: tuple[int, int]) -> tuple[int, int]:
            return min(max(cell[0], 0), last_row), min(max(cell[1], 0), net.columns)

        self.selection = (index, Selection.spanning(clamp(corner), clamp(other)))
        self._place_overlays()

    def open_function_dialog(
        self, index: int, row: int, col: int, name: str, box: FunctionBox | None = None
    ) -> None:
        """The function property table; on OK the box is placed (or its parameters set)."""
        spec = box.spec if box is not None else lookup(name)
        if spec is None:
            return
        current = Instruction(box.name, params=box.params) if box is not None else None
        grid = cast("QWidget", self)
        dialog = FunctionDialog(spec, current, grid, box.comment if box is not None else "",
                                self.model.dialect)
        self.function_dialog = dialog

        def done() -> None:
            instruction = dialog.instruction
            if instruction is None:
                return
            if box is None:
                element = FunctionBox.new(spec.name, instruction.params, dialog.comment_text)
                if self.run_edit(index, lambda n: core.place_wired(n, row, col, element),
                                 editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place {0}"),
                                             spec.name)):
                    self.cursor_to(index, *core.target_cell(self.networks[index], row, col,
                                                            element))
            else:
                new_comment = dialog.comment_text != box.comment

                def params_and_comment(network: LadderNetwork) -> None:
                    core.set_params(network, row, col, instruction.params)
                    if new_comment:
                        core.set_comment(network, row, col, dialog.comment_text)

                self.run_edit(index, params_and_comment,  # one step: parameters and comment
                              editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Parameters of {0}"),
                                          spec.name))
            grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()

    # -- actions on the cursor (menus, keys) --------------------------------------------------

    def _cursor_target(self) -> tuple[int, int, int]:
        if self.selection is not None:
            index, sel = self.selection
            return index, sel.top, sel.left
        return self.cursor_cell

    def edit_at_cursor(self) -> None:
        """ENTER: edit the element at the cursor (address, function table or comment)."""
        index, row, col = self.cursor_cell
        net = self.networks[index]
        found = net.element_at(row, col)
        if found is None:
            if self.tool is Tool.COMMENT:
                self.open_comment_editor(index, len(net.comments))
            return
        (r, c), element = found
        if isinstance(element, Contact | Coil):
            self.open_address_editor(index, r, c)
        elif isinstance(element, FunctionBox):
            self.open_function_dialog(index, r, c, element.name, element)

    def delete_at_cursor(self) -> None:
        """DEL: delete the selection or the element at the cursor."""
        if self.selection is not None:
            index, sel = self.selection
            if self.run_edit(index, lambda n: core.cut(n, sel),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Delete"))):
                self.selection = None
                self._place_overlays()
            return
        index, row, col = self.cursor_cell
        self.run_edit(index, lambda n: core.delete(n, row, col),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Delete")))

    def invert_at_cursor(self) -> None:
        """NOT on the element at the cursor."""
        index, row, col = self._cursor_target()
        self.run_edit(index, lambda n: core.invert(n, row, col),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "NOT")))

    def or_at_cursor(self) -> None:
        """OR on the element at the cursor (a parallel contact or coil)."""
        index, row, col = self._cursor_target()
        self.add_parallel(index, row, col)

    def insert_row_before(self) -> None:
        """Insert an empty row before the cursor's row."""
        index, row, _ = self.cursor_cell
        self.run_edit(index, lambda n: core.insert_row(n, row),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Insert row")))

    def insert_row_after(self) -> None:
        """Insert an empty row after the cursor's row."""
        index, row, _ = self.cursor_cell
        self.run_edit(index, lambda n: core.insert_row(n, row, after=True),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Insert row")))

    def copy(self) -> None:
        """Copy the selection (or the element at the cursor) to the clipboard as grid text."""
        index, sel = self._selection_or_cursor()
        QApplication.clipboard().setText(core.copy_text(self.networks[index], sel))

    def cut(self) -> None:
        """Cut the selection (or the element at the cursor)."""
        index, sel = self._selection_or_cursor()
        text = core.copy_text(self.networks[index], sel)
        if self.run_edit(index, lambda n: core.cut(n, sel),
                         editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Cut"))):
            QApplication.clipboard().setText(text)
            self.selection = None
            self._place_overlays()

    def paste(self) -> None:
        """Paste grid text with its top-left at the cursor."""
        text = QApplication.clipboard().text()
        if not text:
            return
        index, row, col = self.cursor_cell
        self.run_edit(index, lambda n: core.paste(n, row, col, text),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Paste")))

    def delete_network(self) -> None:
        """Delete the network at the cursor."""
        index = self.cursor_cell[0]
        if index >= len(self.networks) - 1:
            return
        self.undo_stack.push(NetworkListCommand(
            self.model, index, None,
            editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Delete network"))))

    def _selection_or_cursor(self) -> tuple[int, Selection]:
        if self.selection is not None:
            return self.selection
        index, row, col = self.cursor_cell
        found = self.networks[index].element_at(row, col)
        if found is not None:
            cells = self.networks[index].footprint(*found)
            return index, Selection.spanning(cells[0], cells[-1])
        return index, Selection(row, col, row, col)
