"""Undo steps named in words that follow a live language switch (Edit › Undo Delete)."""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QUndoCommand, QUndoStack


@dataclass(frozen=True, slots=True)
class StepName:
    """An undo step's name kept untranslated (its source is marked with QT_TRANSLATE_NOOP, so
    lupdate finds it): `text()` says it in the current UI language, `{0}` filled with `args`."""

    context: str
    source: str
    args: tuple[str, ...] = ()

    def text(self) -> str:
        """The name in the current UI language."""
        return QCoreApplication.translate(self.context, self.source).format(*self.args)


def editor_step(source: str, *args: object) -> StepName:
    """A step of the ladder editor (context LadderEditor), e.g. `Place {0}` with `TMR`."""
    return StepName("LadderEditor", source, tuple(str(arg) for arg in args))


class NamedCommand(QUndoCommand):
    """An undo command whose text is a StepName, said again on a language switch."""

    def __init__(self, name: StepName) -> None:
        super().__init__(name.text())
        self.name = name

    def retranslate(self) -> None:
        """The step's name in the current UI language."""
        self.setText(self.name.text())


def retranslate_steps(stack: QUndoStack) -> None:
    """Say every named step of `stack` in the current UI language (Edit › Undo follows)."""
    for index in range(stack.count()):
        command = stack.command(index)
        if isinstance(command, NamedCommand):
            command.retranslate()
