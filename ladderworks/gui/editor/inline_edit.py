"""In-place editing on the grid: an element's address (and `// comment`), a comment line."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QRectF, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QLabel, QLineEdit

from ladderworks.core import ladder as core
from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP, Diagnostic
from ladderworks.core.ladder import Coil, Contact, EditRefused, LadderNetwork
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.geometry import CELL_W, COMMENT_H, LEFT, cell_origin
from ladderworks.gui.editor.step_name import editor_step

if TYPE_CHECKING:
    from ladderworks.gui.editor.view import LadderEditor

translate = QCoreApplication.translate


class InlineEdit(QObject):
    """A line edit over the grid; ENTER commits through the editor's undo commands, ESC
    cancels, a refused address is shown under it and the edit stays open."""

    def __init__(self, editor: LadderEditor) -> None:
        super().__init__(editor)
        self.editor = editor
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

    def open_address(self, index: int, row: int, col: int) -> None:
        """Edit the address (and `// comment`) of the contact or coil at a cell."""
        net = self.editor.networks[index]
        found = net.element_at(row, col)
        if found is None or not isinstance(found[1], Contact | Coil):
            return
        element = found[1]
        text = str(element.address) if element.address is not None else ""
        if element.comment:
            text += "  // " + element.comment
        x, y = cell_origin(net, row, col, self.editor.layout_.rows[index])
        rect = QRectF(x - 10, self.editor.layout_.tops[index] + y, CELL_W + 60, 24)
        self._open(("address", index, row, col), text, rect,
                   translate("LadderEditor", "Address or symbol, e.g. X2.1 (// comment)"))

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
        self.line_edit.setGeometry(top_left.x(), top_left.y(), max(width, 140), 26)
        self.line_edit.setPlaceholderText(placeholder)
        self.line_edit.setText(text)
        self.line_edit.selectAll()
        self.message.hide()
        self.line_edit.show()
        self.line_edit.setFocus()

    def close(self) -> None:
        """Hide the edit without a change."""
        self.target = None
        had_focus = self.line_edit.hasFocus()  # hiding it moves the focus on: ask first
        self.line_edit.hide()
        self.message.hide()
        if had_focus:
            self.editor.setFocus()

    def _refuse(self, diagnostic: Diagnostic) -> None:
        text = diagnostic_text(diagnostic)
        self.message.setText(text)
        self.message.adjustSize()
        geometry = self.line_edit.geometry()
        self.message.move(geometry.left(), geometry.bottom() + 2)
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
        address_text = editor.resolve_address(address_text)
        try:
            core.edits.to_address(address_text, (row, col), dialect=editor.model.dialect)
        except EditRefused as refused:
            self._refuse(refused.diagnostic)
            return
        found = editor.networks[index].element_at(row, col)
        assert found is not None
        element = found[1]
        assert isinstance(element, Contact | Coil)
        new_comment = comment != element.comment

        def address_and_comment(network: LadderNetwork) -> None:
            core.set_address(network, row, col, address_text, editor.model.dialect)
            if new_comment:
                core.set_comment(network, row, col, comment)

        editor.run_edit(index, address_and_comment,  # one step: the address and its comment
                        editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Address {0}"),
                                    address_text))
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
        self.editor.run_edit(index, lambda n: core.set_network_comments(n, lines),
                             editor_step(QT_TRANSLATE_NOOP("LadderEditor", "Comment")))

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """ENTER in the line edit commits it, ESC cancels it."""
        if watched is self.line_edit and event.type() == QEvent.Type.KeyPress:
            assert isinstance(event, QKeyEvent)
            if event.key() == Qt.Key.Key_Escape:
                self.close()
                return True
            if event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
                # consumed here: an ignored ENTER would reach the grid and open the editor again
                self.commit()
                return True
        return super().eventFilter(watched, event)
