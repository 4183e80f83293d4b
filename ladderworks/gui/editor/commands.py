"""Undo commands: each redo/undo applies a core edit and keeps the inverse it returns."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtGui import QUndoCommand

from ladderworks.core.ladder import Edit, LadderNetwork

if TYPE_CHECKING:
    from ladderworks.gui.editor.view import LadderEditor


class NetworkEditCommand(QUndoCommand):
    """A change to one network made by a core edit operation (already applied when pushed).

    When the change draws into the empty network at the end, a new empty one is appended (and
    removed again on undo), so there is always room for the next network.
    """

    def __init__(self, editor: LadderEditor, index: int, undo_edit: Edit, text: str) -> None:
        super().__init__(text)
        self._editor = editor
        self._index = index
        self._edit = undo_edit
        self._done = True
        network = editor.networks[index]
        self._appended: LadderNetwork | None = None
        if index == len(editor.networks) - 1 and not (network.is_empty() and not network.comments):
            self._appended = LadderNetwork()

    def redo(self) -> None:
        """Apply the change (the first call finds it already applied)."""
        if self._done:
            self._done = False
        else:
            self._edit = self._edit.apply(self._editor.networks[self._index])
        if self._appended is not None:
            self._editor.insert_network(len(self._editor.networks), self._appended)
        self._editor.network_changed(self._index)

    def undo(self) -> None:
        """Apply the inverse edit."""
        if self._appended is not None:
            self._editor.remove_network(len(self._editor.networks) - 1)
        self._edit = self._edit.apply(self._editor.networks[self._index])
        self._editor.network_changed(self._index)


class NetworkListCommand(QUndoCommand):
    """Insert or remove a whole network (delete network, paste network)."""

    def __init__(self, editor: LadderEditor, index: int, network: LadderNetwork | None,
                 text: str) -> None:
        super().__init__(text)
        self._editor = editor
        self._index = index
        self._network = network  # None: remove the network at index

    def redo(self) -> None:
        """Insert (or remove) the network."""
        if self._network is not None:
            self._editor.insert_network(self._index, self._network)
        else:
            self._network_removed = self._editor.remove_network(self._index)

    def undo(self) -> None:
        """Remove (or put back) the network."""
        if self._network is not None:
            self._editor.remove_network(self._index)
        else:
            self._editor.insert_network(self._index, self._network_removed)
