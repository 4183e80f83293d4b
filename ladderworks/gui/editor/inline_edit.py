"""In-place editing on the grid: an element's address (and `// comment`), a comment line."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QRectF, Qt
from PySide6.QtGui import QKeyEvent, QUndoCommand
from PySide6.QtWidgets import QLabel, QLineEdit

from ladderworks.core import ladder as core
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.ladder import Coil, Contact, EditRefused
from ladderworks.core.ladder.source_model import source_model
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.geometry import CELL_W, COMMENT_H, LEFT, cell_origin
from ladderworks.gui.editor.grid_view import GridView
from ladderworks.gui.editor.ladder_edits import LadderEdits

translate = QCoreApplication.translate


class InlineEdit(QObject):
    """A line edit over the grid; ENTER commits through the editing operations (an undo
    step), ESC cancels, a refused address is shown under it and the edit stays open."""

    def __init__(self, editor: GridView, edits: LadderEdits) -> None:
        super().__init__(editor)
        self.editor = editor
        self.edits = edits
        self.line_edit = QLineEdit(editor.viewport())
        self.line_edit.setObjectName("inline_editor")
        self.line_edit.hide()
        self.line_edit.installEventFilter(self)
        self.message = QLabel(editor.viewport())
        self.message.setObjectName("inline_message")
        self.message.setStyleSheet(
            "background: #fff3f3; color: #b00020; border: 1px solid #b00020; padding: 2px;"
        )
        self.message.hide()
        self.target: tuple[str, int, int, int] | None = None  # kind, network, row, col
        self.placed_step: int | None = None  # the undo index right after placing the element

    def open_address(self, index: int, row: int, col: int, placed: bool = False) -> None:
        """Edit the address (and `// comment`) of the contact or coil at a cell; `placed`: the
        element was placed by the step just pushed, which ESC takes back."""
        net = self.editor.networks[index]
        found = net.element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return
        element = found[1]
        text = self.editor.spell_address(element.address) if element.address is not None else ""
        own = source_model(self.editor.model.document.origin) is not None
        if own:  # the operand as the source writes it ("Start")
            text = element.texts[0] if element.texts else text
        if element.comment:
            text += "  // " + element.comment
        x, y = cell_origin(net, row, col, self.editor.layout_.rows[index])
        rect = QRectF(x - 10, self.editor.layout_.tops[index] + y, CELL_W + 60, 24)
        hint = translate("LadderEditor", 'Operand, e.g. "Start", %I0.1, #Run (// comment)') \
            if own else translate("LadderEditor", "Address or symbol, e.g. X2.1 (// comment)")
        self._open(("address", index, row, col), text, rect, hint)
        self.placed_step = self.editor.undo_stack.index() if placed else None

    def open_comment(self, index: int, line: int) -> None:
        """Edit (or add) network comment line `line`."""
        net = self.editor.networks[index]
        text = net.comments[line] if line < len(net.comments) else ""
        rect = QRectF(LEFT, self.editor.layout_.tops[index] + line * COMMENT_H,
                      (net.columns + 1) * CELL_W, 24)
        self._open(("comment", index, line, 0), text, rect, translate("LadderEditor", "Comment"))

    def _open(self, target: tuple[str, int, int, int], text: str, rect: QRectF,
              placeholder: str) -> None:
        self.target = target
        editor = self.editor
        editor.ensureVisible(rect, 20, 20)
        top_left = editor.mapFromScene(rect.topLeft())
        width = int(rect.width() * editor.zoom())
        width = min(max(width, 140), editor.viewport().width())
        left = max(min(top_left.x(), editor.viewport().width() - width), 0)  # the coil column
        self.line_edit.setGeometry(left, top_left.y(), width, 26)  # stays in view by a dock
        self.line_edit.setPlaceholderText(placeholder)
        self.line_edit.setText(text)
        self.line_edit.selectAll()
        self.message.hide()
        self.line_edit.show()
        self.line_edit.setFocus()

    def close(self) -> None:
        """Hide the edit without a change."""
        self.target = None
        self.placed_step = None
        had_focus = self.line_edit.hasFocus()  # hiding it moves the focus on: ask first
        self.line_edit.hide()
        self.message.hide()
        if had_focus:
            self.editor.setFocus()

    def cancel(self) -> None:
        """ESC: close the edit; an element placed for it and still without an address goes
        again, and so does its undo step (no step is left to redo either)."""
        target, step = self.target, self.placed_step
        self.close()
        stack = self.editor.undo_stack
        if target is None or step is None or stack.index() != step:
            return
        found = self.editor.networks[target[1]].element_at(target[2], target[3])
        element = found[1] if found is not None else None
        if not isinstance(element, Contact | Coil) or element.address is not None:
            return
        stack.undo()
        dropped = QUndoCommand()  # pushing an obsolete command drops the redo step, adds none
        dropped.setObsolete(True)
        stack.push(dropped)

    def _refuse(self, diagnostic: Diagnostic) -> None:
        text = diagnostic_text(diagnostic)
        self.message.setText(text)
        room = self.editor.viewport().width()
        self.message.setMinimumWidth(0)
        self.message.setMaximumWidth(16777215)
        self.message.setWordWrap(False)
        self.message.adjustSize()
        if self.message.width() > room:  # a narrow ladder: the text wraps, whole
            self.message.setWordWrap(True)
            self.message.setFixedWidth(room)
            self.message.adjustSize()
        geometry = self.line_edit.geometry()
        left = max(min(geometry.left(), room - self.message.width()), 0)  # not under a dock
        self.message.move(left, geometry.bottom() + 2)
        self.message.show()
        self.message.raise_()
        self.editor.message.emit(text)

    def commit(self) -> None:
        """ENTER: the typed address (or comment line) becomes an undo step."""
        target = self.target
        if target is None:
            return
        kind, index, row, col = target
        text = self.line_edit.text()
        if kind == "comment":
            self._commit_comment(index, row, text)
            return
        address_text, _, comment = text.partition("//")
        address_text = address_text.strip()
        comment = comment.strip()
        if not address_text:
            self.close()
            return
        editor = self.editor
        found = editor.networks[index].element_at(row, col)
        assert found is not None
        element = found[1]
        assert isinstance(element, Contact | Coil)
        model = source_model(editor.model.document.origin)
        if model is not None:  # drawn from the source's own model (S7): its operand as written
            operand = model.operand(address_text)
            if isinstance(operand, Diagnostic):
                self._refuse(operand)
                return
            self.edits.set_operand(index, row, col, operand[0], operand[1],
                                   comment if comment != element.comment else None)
            self.close()
            return
        typed = editor.typed_bit(address_text, element)
        if isinstance(typed, Diagnostic):  # a dialect's reader refuses it (`OUT X0`, `X8`)
            self._refuse(typed)
            return
        try:
            core.edits.to_address(typed, (row, col), dialect=editor.model.dialect)
        except EditRefused as refused:
            self._refuse(refused.diagnostic)
            return
        self.edits.set_address(index, row, col, typed,
                               comment if comment != element.comment else None)
        self.close()

    def _commit_comment(self, index: int, line: int, text: str) -> None:
        lines = list(self.editor.networks[index].comments)
        if line < len(lines):
            if text.strip():
                lines[line] = text.rstrip()
            else:
                del lines[line]
        elif text.strip():
            lines.append(text.rstrip())
        else:
            self.close()
            return
        self.close()
        self.edits.set_comments(index, lines)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """ENTER in the line edit commits it, ESC cancels it."""
        if watched is self.line_edit and event.type() == QEvent.Type.KeyPress:
            assert isinstance(event, QKeyEvent)
            if event.key() == Qt.Key.Key_Escape:
                self.cancel()
                return True
            if event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
                # consumed here: an ignored ENTER would reach the grid and open the editor again
                self.commit()
                return True
        return super().eventFilter(watched, event)
