"""Edit › Undo and Redo named after the step they take back or make again ("Undo Delete")."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtGui import QAction, QUndoStack

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.gui.editor.step_name import retranslate_steps

translate = QCoreApplication.translate

UNDO = QT_TRANSLATE_NOOP("MainWindow", "&Undo")
REDO = QT_TRANSLATE_NOOP("MainWindow", "&Redo")
UNDO_STEP = QT_TRANSLATE_NOOP("MainWindow", "&Undo {0}")
REDO_STEP = QT_TRANSLATE_NOOP("MainWindow", "&Redo {0}")


class UndoTexts(QObject):
    """Keeps the Undo and Redo actions' texts naming the stack's next steps, in the UI
    language (the window calls `retranslate()` on a language switch). A child of the stack:
    it goes with it."""

    def __init__(self, stack: QUndoStack, undo: QAction, redo: QAction) -> None:
        super().__init__(stack)
        self.stack = stack
        self.undo = undo
        self.redo = redo
        stack.undoTextChanged.connect(self._name_undo)  # the names come with the signals:
        stack.redoTextChanged.connect(self._name_redo)  # a stack going away says "" too
        self.update()

    def _name_undo(self, name: str) -> None:
        _name(self.undo, UNDO_STEP, UNDO, name)

    def _name_redo(self, name: str) -> None:
        _name(self.redo, REDO_STEP, REDO, name)

    def update(self) -> None:
        """Name the stack's next steps on the actions."""
        self._name_undo(self.stack.undoText())
        self._name_redo(self.stack.redoText())

    def retranslate(self) -> None:
        """Say the stack's steps, and so the actions, in the current UI language."""
        retranslate_steps(self.stack)
        self.update()


def _name(action: QAction, step: str, plain: str, name: str) -> None:
    """`&Undo Delete` (`&Undo` when there is no step), also as the tooltip."""
    text = (translate("MainWindow", step).format(name) if name
            else translate("MainWindow", plain))
    action.setText(text)
    action.setToolTip(text.replace("&", ""))
