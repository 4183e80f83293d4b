"""The ladder editor's editing operations, each one undo step with one name: the tools, the
menus, the keys and the in-place editor all call them."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QApplication

from ladderworks.core import ladder as core
from ladderworks.core.address import Address
from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP, Diagnostic
from ladderworks.core.dialects.functions import is_contact, placed_params
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il import Instruction
from ladderworks.core.instruction_fields import Flow
from ladderworks.core.instructions import FUNCTIONS, InstructionSpec, lookup
from ladderworks.core.ladder import (
    WIRE,
    Coil,
    Contact,
    EditRefused,
    Element,
    FunctionBox,
    LadderNetwork,
    Selection,
    Wire,
)
from ladderworks.core.ladder.output_pins import set_output_pins, shown_pins
from ladderworks.core.ladder.source_model import source_model
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.commands import NetworkEditCommand, NetworkListCommand
from ladderworks.gui.editor.grid_view import GridView
from ladderworks.gui.editor.ladder_model import ends_program
from ladderworks.gui.editor.step_name import StepName, editor_step
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.operand_dialog import OperandDialog
from ladderworks.gui.output_pins_dialog import OutputPinsDialog

translate = QCoreApplication.translate

OpenAddress = Callable[[int, int, int, bool], None]  # network, row, column, just placed
# the two names more than one operation gives its step
DELETE = editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Delete"))  # an element, a selection
PLACE_COIL = editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place coil"))  # new, or its kind


def shown_name(spec: InstructionSpec) -> str:
    """A row's name as the program's text writes it (`LD=`, `FUN 11 (+)`; the PMC's own)."""
    return spelling(spec.dialect).name(spec) if spec.dialect else spec.name


def _place_step(title: str) -> StepName:
    """The undo step of placing a box or a dialect's contact called `title`."""
    return editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place {0}"), title)


def _params_step(title: str) -> StepName:
    """The undo step of changing the operands of a box or a dialect's contact."""
    return editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Parameters of {0}"), title)


def _address_step(text: str) -> StepName:
    """The undo step of a contact's or coil's new address (or S7 operand) `text`."""
    return editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Address {0}"), text)


def _keeping_end(operation: Callable[[LadderNetwork], object]
                 ) -> Callable[[LadderNetwork], object]:
    """`operation` on the program's last network, END, refused when END would not be left."""
    def kept(network: LadderNetwork) -> object:
        result = operation(network)
        if not ends_program(network):
            raise EditRefused("edit-end-kept")
        return result
    return kept


class LadderEdits:
    """Turns a tool use, a menu action or a key into an undo command on the grid's model; a
    refused edit becomes the grid's status message. `open_address` opens the in-place
    address editor of a cell (a placed contact or coil gets its address typed next)."""

    def __init__(self, grid: GridView, open_address: OpenAddress) -> None:
        self.grid = grid
        self.open_address = open_address
        self.function_name = FUNCTIONS[0].name  # what the function tool places (the palette's)
        self.function_dialog: FunctionDialog | None = None
        self.output_pins_dialog: OutputPinsDialog | None = None
        self.operand_dialog: OperandDialog | None = None  # an S7 element's operands

    def run_edit(self, index: int, operation: Callable[[LadderNetwork], object],
                 name: StepName) -> bool:
        """Make a core edit on network `index` as an undo command named `name`; False (and a
        message) when the core refuses it."""
        model = self.grid.model
        if index == len(model.networks) - 1 and model.end_is_last():
            operation = _keeping_end(operation)
        try:
            edit = model.prepare(index, operation)
        except EditRefused as refused:
            self.grid.message.emit(diagnostic_text(refused.diagnostic))
            return False
        model.undo_stack.push(NetworkEditCommand(model, index, edit, name))
        return True

    # -- one operation each, at a cell -----------------------------------------------------

    def set_address(self, index: int, row: int, col: int, text: str | Address,
                    comment: str | None = None) -> bool:
        """The address of a contact or coil, and its new `comment` (None: kept): one step."""
        dialect = self.grid.model.dialect  # its map: a seed program's is the seed's
        shown = self.grid.spell_address(text) if isinstance(text, Address) else text

        def address_and_comment(network: LadderNetwork) -> None:
            core.set_address(network, row, col, text, dialect)
            if comment is not None:
                core.set_comment(network, row, col, comment)

        return self.run_edit(index, address_and_comment,
                             _address_step(shown))

    def set_operand(self, index: int, row: int, col: int, text: str, address: Address | None,
                    comment: str | None = None) -> bool:
        """The operand of a contact or coil drawn from a source's own model (S7's "Start"),
        and its new `comment` (None: kept): one step."""

        def operand_and_comment(network: LadderNetwork) -> None:
            core.set_operand(network, row, col, text, address)
            if comment is not None:
                core.set_comment(network, row, col, comment)

        return self.run_edit(index, operand_and_comment,
                             _address_step(text))

    def set_comments(self, index: int, lines: list[str]) -> bool:
        """A network's comment lines."""
        return self.run_edit(index, lambda n: core.set_network_comments(n, lines),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Comment")))

    def invert(self, index: int, row: int, col: int) -> bool:
        """NOT: the contact or coil at a cell becomes its inverse."""
        return self.run_edit(index, lambda n: core.invert(n, row, col),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "NOT")))

    def delete(self, index: int, row: int, col: int) -> bool:
        """Delete the element at a cell."""
        return self.run_edit(index, lambda n: core.delete(n, row, col), DELETE)

    def insert_row(self, index: int, row: int, after: bool = False) -> bool:
        """An empty row before (or after) `row`."""
        return self.run_edit(index, lambda n: core.insert_row(n, row, after=after),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Insert row")))

    def draw_line(self, index: int, start: tuple[int, int], end: tuple[int, int]) -> bool:
        """A wire between two grid nodes (row, node)."""
        return self.run_edit(index, lambda n: core.draw_line(n, start, end),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Line")))

    def place_bit(self, index: int, row: int, col: int, element: Contact | Coil) -> None:
        """Place a contact or coil and open its address; on one of the same kind, turn it
        into `element`'s kind (NOT, SET, RST) and open its address. A coil goes to the coil
        column; a placed element is wired to its neighbours (core `place_wired`). The cursor
        goes where the element is."""
        grid = self.grid
        row, col = core.target_cell(grid.networks[index], row, col, element)
        found = grid.networks[index].element_at(row, col)
        grid.cursor_to(index, *(found[0] if found is not None else (row, col)))
        if found is not None and type(found[1]) is type(element):
            old = found[1]
            assert isinstance(old, Contact | Coil)
            if isinstance(old, Coil) and isinstance(element, Coil) and old.write != element.write:
                kind = replace(old, negated=element.negated, write=element.write,
                               row=element.row)
                self.run_edit(index, lambda n: core.replace_element(n, row, col, kind),
                              PLACE_COIL)
            elif old.negated != element.negated:
                self.invert(index, row, col)
            self.open_address(index, found[0][0], found[0][1], False)
            return
        text = (editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Place contact"))
                if isinstance(element, Contact)
                else PLACE_COIL)
        if self.run_edit(index, lambda n: core.place_wired(n, row, col, element), text):
            self.open_address(index, row, col, True)  # ESC takes it away again

    def add_parallel(self, index: int, row: int, col: int) -> None:
        """OR: a parallel contact or coil below the one at a cell, its address opened."""
        found = self.grid.networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            self.grid.message.emit(
                translate("LadderEditor", "Select a contact or a coil for the OR tool"))
            return
        (row, col), _old = found
        if self.run_edit(index, lambda n: core.add_parallel(n, row, col),
                         editor_step(QT_TRANSLATE_NOOP("LadderEditor", "OR"))):
            self.open_address(index, row + 1, col, True)

    def open_function_dialog(
        self, index: int, row: int, col: int, name: str, box: FunctionBox | None = None
    ) -> None:
        """The function property table; on OK the box is placed (or its parameters set). A
        dialect's edge or comparison row (`is_contact`) is placed as a contact."""
        if self.open_operand_dialog(index, row, col, name, box):
            return  # drawn from its source's own model (S7): TIA's element and operands
        spec = box.spec if box is not None else lookup(name)
        if spec is None:
            return
        if is_contact(spec):
            self.open_contact_dialog(index, row, col, spec.name)
            return
        grid = self.grid
        current = Instruction(box.name, params=box.params) if box is not None else None
        dialog = FunctionDialog(spec, current, grid, box.comment if box is not None else "",
                                grid.model.dialect)
        self.function_dialog = dialog

        def done() -> None:
            instruction = dialog.instruction
            if instruction is None:
                return
            if box is None:
                others = [(cell.spec, cell.params) for network in grid.networks
                          for cell in network.cells.values() if isinstance(cell, FunctionBox)]
                params = placed_params(spec, instruction.params, others)  # Fatek: its FO byte
                element = FunctionBox.new(spec.name, params, dialog.comment_text)
                if self.run_edit(index, lambda n: core.place_wired(n, row, col, element),
                                 _place_step(shown_name(spec))):
                    grid.cursor_to(index, *core.target_cell(grid.networks[index], row, col,
                                                            element))
            else:
                new_comment = dialog.comment_text != box.comment

                def params_and_comment(network: LadderNetwork) -> None:
                    core.set_params(network, row, col, instruction.params)
                    if new_comment:
                        core.set_comment(network, row, col, dialog.comment_text)

                self.run_edit(index, params_and_comment,  # one step: parameters and comment
                              _params_step(shown_name(spec)))
            grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()

    def open_contact_dialog(self, index: int, row: int, col: int, name: str,
                            contact: Contact | None = None) -> None:
        """The operands of a dialect's edge or comparison contact (row `name`); on OK the
        contact is placed at the cell (or, given `contact`, its operands and comment set)."""
        if self.open_operand_dialog(index, row, col, name, contact):
            return
        spec = lookup(contact.function if contact is not None else name)
        if spec is None:
            return
        grid = self.grid
        current = Instruction(spec.name, params=contact.params) if contact is not None else None
        dialog = FunctionDialog(spec, current, grid, contact.comment if contact else "",
                                grid.model.dialect)
        self.function_dialog = dialog

        def done() -> None:
            instruction = dialog.instruction
            if instruction is None:
                return
            if contact is None:
                element = Contact(None, False, dialog.comment_text, (), spec.name,
                                  instruction.params)
                if self.run_edit(index, lambda n: core.place_row_contact(n, row, col, element),
                                 _place_step(shown_name(spec))):
                    grid.cursor_to(index, *core.target_cell(grid.networks[index], row, col,
                                                            element))
            else:
                changed = replace(contact, params=instruction.params,
                                  comment=dialog.comment_text)
                self.run_edit(index, lambda n: core.replace_element(n, row, col, changed),
                              _params_step(shown_name(spec)))
            grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()

    def open_operand_dialog(self, index: int, row: int, col: int, name: str,
                            element: Element | None = None) -> bool:
        """In a program drawn from its source's own model (S7): the element palette row
        `name` places (or `element`) with its operands typed in a dialog, placed (or changed)
        on OK. False for any other program."""
        model = source_model(self.grid.model.document.origin)
        if model is None:
            return False
        element = element if element is not None else model.palette(name)
        spec = lookup(name)
        if element is None and spec is not None and spec.flow is Flow.LABEL:
            return self._label_dialog(index, spec.title)  # S7's LABEL: the network's label
        if element is None or isinstance(element, Wire):
            self.grid.message.emit(translate(
                "LadderEditor", "This instruction is not placed from the palette in this "
                "program"))
            return True
        placing = self.grid.networks[index].element_at(row, col) is None or \
            self.grid.networks[index].element_at(row, col) == ((row, col), WIRE)
        title = element.title if isinstance(element, FunctionBox) else \
            element.mark.split("\n")[0] or name
        dialog = OperandDialog(title, model.operands(element), self.grid)
        self.operand_dialog = dialog
        step = _place_step(title) if placing else _params_step(title)

        def done() -> None:
            changed = model.with_operands(element, dialog.texts())
            if not placing:
                self.run_edit(index, lambda n: core.replace_element(n, row, col, changed), step)
            else:  # a comparison at the rail as TIA has it (no leading always-on contact)
                self.run_edit(index, lambda n: core.place_wired(n, row, col, changed), step)
            self.grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()
        return True

    def _label_dialog(self, index: int, title: str) -> bool:
        """The network's jump label typed in a dialog, set on OK (one undo step); a name the
        source cannot hold is said and nothing changes."""
        model = source_model(self.grid.model.document.origin)
        assert model is not None
        dialog = OperandDialog(title, [("label", self.grid.networks[index].label)], self.grid)
        self.operand_dialog = dialog

        def done() -> None:
            label = model.label(dialog.texts()[0])
            if isinstance(label, Diagnostic):
                self.grid.message.emit(diagnostic_text(label))
                return
            self.run_edit(index, lambda n: core.set_label(n, label),
                          editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Label {0}"), label))
            self.grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()
        return True

    # -- at the cursor (menus, keys) -------------------------------------------------------

    def _cursor_target(self) -> tuple[int, int, int]:
        if self.grid.selection is not None:
            index, sel = self.grid.selection
            return index, sel.top, sel.left
        return self.grid.cursor_cell

    def assign_address_at_cursor(self, address: Address) -> bool:
        """Put `address` on the contact or coil at the cursor (one undo step); False if none."""
        index, row, col = self.grid.cursor_cell
        networks = self.grid.networks
        if index >= len(networks) or address.bit is None:
            return False
        found = networks[index].element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return False
        (r, c), _element = found
        return self.set_address(index, r, c, address)

    def delete_at_cursor(self) -> None:
        """DEL: delete the selection or the element at the cursor."""
        grid = self.grid
        if grid.selection is not None:
            index, sel = grid.selection
            if self.run_edit(index, lambda n: core.cut(n, sel), DELETE):
                grid.selection = None
                grid.place_overlays()
            return
        self.delete(*grid.cursor_cell)

    def invert_at_cursor(self) -> None:
        """NOT on the element at the cursor."""
        self.invert(*self._cursor_target())

    def or_at_cursor(self) -> None:
        """OR on the element at the cursor (a parallel contact or coil)."""
        self.add_parallel(*self._cursor_target())

    def output_pins_at_cursor(self) -> None:
        """The output pins dialog for the box at the cursor (Fatek's FO1 … FO7); on OK the
        box shows the checked ones (one undo step). A message when no such box is there."""
        index, row, col = self._cursor_target()
        networks = self.grid.networks
        found = networks[index].element_at(row, col) if index < len(networks) else None
        box = found[1] if found is not None else None
        if not isinstance(box, FunctionBox) or box.output_byte() is None:
            self.grid.message.emit(diagnostic_text(Diagnostic(
                "edit-no-pins", {"row": row, "col": col})))
            return
        dialect = self.grid.model.dialect
        name = spelling(dialect).name(box.spec) if dialect else box.name
        dialog = OutputPinsDialog(name, shown_pins(box), self.grid)
        self.output_pins_dialog = dialog

        def done() -> None:
            bits = dialog.bits()
            self.run_edit(index, lambda n: set_output_pins(n, row, col, bits),
                          editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Output pins")))
            self.grid.setFocus()

        dialog.accepted.connect(done)
        dialog.open()

    def insert_row_before(self) -> None:
        """Insert an empty row before the cursor's row."""
        index, row, _ = self.grid.cursor_cell
        self.insert_row(index, row)

    def insert_row_after(self) -> None:
        """Insert an empty row after the cursor's row."""
        index, row, _ = self.grid.cursor_cell
        self.insert_row(index, row, after=True)

    def copy(self) -> None:
        """Copy the selection (or the element at the cursor) to the clipboard as grid text."""
        index, sel = self._selection_or_cursor()
        QApplication.clipboard().setText(core.copy_text(self.grid.networks[index], sel))

    def cut(self) -> None:
        """Cut the selection (or the element at the cursor)."""
        grid = self.grid
        index, sel = self._selection_or_cursor()
        text = core.copy_text(grid.networks[index], sel)
        if self.run_edit(index, lambda n: core.cut(n, sel),
                         editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Cut"))):
            QApplication.clipboard().setText(text)
            grid.selection = None
            grid.place_overlays()

    def paste(self) -> None:
        """Paste grid text with its top-left at the cursor."""
        text = QApplication.clipboard().text()
        if not text:
            return
        index, row, col = self.grid.cursor_cell
        self.run_edit(index, lambda n: core.paste(n, row, col, text),
                      editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Paste")))

    def delete_network(self) -> None:
        """Delete the network at the cursor."""
        grid = self.grid
        index = grid.cursor_cell[0]
        if index == len(grid.networks) - 1 and grid.model.end_is_last():
            self.grid.message.emit(diagnostic_text(EditRefused("edit-end-kept").diagnostics[0]))
            return
        if index >= grid.model.blank_index():
            return
        grid.undo_stack.push(NetworkListCommand(
            grid.model, index, None,
            editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Delete network"))))

    def _selection_or_cursor(self) -> tuple[int, Selection]:
        grid = self.grid
        if grid.selection is not None:
            return grid.selection
        index, row, col = grid.cursor_cell
        found = grid.networks[index].element_at(row, col)
        if found is not None:
            cells = grid.networks[index].footprint(*found)
            return index, Selection.spanning(cells[0], cells[-1])
        return index, Selection(row, col, row, col)
