"""Undo commands on the ladder model: redo() makes the change, undo() takes it back."""

from __future__ import annotations

from ladderworks.core.ladder import Edit, LadderNetwork
from ladderworks.gui.editor.ladder_model import LadderModel, is_blank
from ladderworks.gui.editor.step_name import NamedCommand, StepName


class NetworkEditCommand(NamedCommand):
    """A change to one network: `edit` (from `LadderModel.prepare`) is applied by redo().

    When the change draws into the blank network at the end, a new blank one is inserted after
    it (before it when the drawing is the program's END, which stays last), and removed again on
    undo, so there is always room for the next network.
    """

    def __init__(self, model: LadderModel, index: int, edit: Edit, name: StepName) -> None:
        super().__init__(name)
        self._model = model
        self._index = index
        self._edit = edit  # redo() applies it and keeps the inverse for undo(), and so on
        self._appended: int | None = None  # where a new blank network was inserted

    def redo(self) -> None:
        """Make the change."""
        model = self._model
        blank = model.blank_index()
        self._edit = model.apply(self._index, self._edit)
        self._appended = None
        if self._index == blank and not is_blank(model.networks[blank]):
            end = model.keeps_end(model.networks[blank]) and blank == len(model.networks) - 1
            self._appended = blank if end else blank + 1
            model.insert_network(self._appended, LadderNetwork())

    def undo(self) -> None:
        """Take the change back."""
        model = self._model
        if self._appended is not None:
            model.remove_network(self._appended)
        self._edit = model.apply(self._index, self._edit)


class NetworkListCommand(NamedCommand):
    """Insert or remove a whole network (delete network, paste network)."""

    def __init__(self, model: LadderModel, index: int, network: LadderNetwork | None,
                 name: StepName) -> None:
        super().__init__(name)
        self._model = model
        self._index = index
        self._network = network  # None: remove the network at index
        self._removed: LadderNetwork | None = None

    def redo(self) -> None:
        """Insert (or remove) the network."""
        if self._network is not None:
            self._model.insert_network(self._index, self._network)
        else:
            self._removed = self._model.remove_network(self._index)

    def undo(self) -> None:
        """Remove (or put back) the network."""
        if self._network is not None:
            self._model.remove_network(self._index)
        elif self._removed is not None:
            self._model.insert_network(self._index, self._removed)
