"""The ladder document model: the networks the console edits, its undo stack and its mode."""

from __future__ import annotations

from collections.abc import Callable
from enum import StrEnum

from PySide6.QtCore import QObject, Signal
from PySide6.QtGui import QUndoStack

from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Program
from ladderworks.core.instructions import Flow, lookup
from ladderworks.core.ladder import Edit, FunctionBox, LadderDocument, LadderNetwork, Wire, convert
from ladderworks.core.ladder.convert import Kept
from ladderworks.core.symbols import SymbolTable
from ladderworks.gui.editor.progressive import ProgressiveLoader


class Mode(StrEnum):
    """How the program is shown: drawn as ladder, or as instruction-list text."""

    LADDER = "ladder"
    TEXT = "text"


def is_blank(network: LadderNetwork) -> bool:
    """True for a network with nothing drawn and no comment (the drawing area at the end)."""
    return network.is_empty() and not network.comments


def ends_program(network: LadderNetwork) -> bool:
    """True for a network that is the program's END alone (a box of the `PROGRAM_END` row)."""
    boxes = [element for _cell, element in network.elements() if not isinstance(element, Wire)]
    if len(boxes) != 1 or not isinstance(boxes[0], FunctionBox):
        return False
    spec = lookup(boxes[0].name)
    return spec is not None and spec.flow is Flow.PROGRAM_END


class LadderModel(QObject):
    """Owns the networks (always one blank network at the end to draw in, before the END of a
    program that ends with one: END stays last); every change is made here and announced, so
    views only observe. Edits come as undo commands."""

    networks_inserted = Signal(int, int)  # first index, count
    network_removed = Signal(int)
    network_changed = Signal(int)
    networks_changed = Signal(list)  # several networks at once (replace all): index list
    document_reset = Signal()  # a whole new document (open, new, text shown as ladder)
    diagnostics_found = Signal(list)  # Diagnostic list of the last coding (cells to outline)
    modified_changed = Signal(bool)
    mode_changed = Signal(str)  # Mode value

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.undo_stack = QUndoStack(self)
        self.undo_stack.cleanChanged.connect(self._clean_changed)
        self.document = LadderDocument()
        self.symbols: SymbolTable | None = None  # the program's `%@2` symbols
        self.networks: list[LadderNetwork] = [LadderNetwork()]
        self.loader = ProgressiveLoader(self)
        self.loader.laid_out.connect(self._laid_out)
        # each network as laid out with the one it was read as: an unchanged network is
        # saved, checked and compiled as read, not decomposed from its grid again
        self.kept: Kept | None = None
        self._mode = Mode.LADDER

    # -- the mode ------------------------------------------------------------------------

    @property
    def mode(self) -> Mode:
        """Ladder or text."""
        return self._mode

    @property
    def showing_text(self) -> bool:
        """True while the program is shown (and edited) as text."""
        return self._mode is Mode.TEXT

    def set_mode(self, mode: Mode) -> None:
        """Show the program as ladder or as text."""
        if mode is not self._mode:
            self._mode = mode
            self.mode_changed.emit(mode.value)

    # -- whole documents -----------------------------------------------------------------

    def set_program(self, program: Program, kept: Kept | None = None) -> None:
        """Lay a program out as the document (clears undo); a large one's rest in the
        background (`loading`; `finish_loading()` waits). `kept` receives each network as
        laid out with the one it came from (the faithful Save)."""
        document = self.loader.head(program, kept)
        self.set_document(document, keep_pending=True)
        self.kept = kept
        self.loader.start()

    def set_document(self, document: LadderDocument, *, keep_pending: bool = False) -> None:
        """Make `document` the one edited (clears undo)."""
        if not keep_pending:
            self.loader.cancel()
        self.kept = None
        self.undo_stack.clear()
        self.document = document
        self.symbols = document.origin.symbols if document.origin is not None else None
        networks = list(document.networks)
        at = len(networks) - 1 if networks and self.keeps_end(networks[-1]) else len(networks)
        networks.insert(at, LadderNetwork())
        self.networks = networks
        self.document_reset.emit()

    def keeps_end(self, network: LadderNetwork) -> bool:
        """True for a Delta/Fatek program's END network, kept last (issue 38); a PMC program's
        END ends its level 3 and the blank network stays after it, as before."""
        return self.dialect not in ("seed", "fanuc") and ends_program(network)

    def blank_index(self) -> int:
        """The index of the blank network new networks are drawn in: the last, or the one
        before the program's END."""
        last = len(self.networks) - 1
        return last - 1 if last > 0 and self.end_is_last() else last

    def editor_network(self, network: int) -> int:
        """The index here of the program's network `network` (a diagnostic's): the program's
        END after the blank network is one further."""
        blank = self.blank_index()
        return network + 1 if network >= blank and blank < len(self.networks) - 1 else network

    def end_is_last(self) -> bool:
        """True when the last network is the program's END (kept last: drawn before it)."""
        return len(self.networks) > 1 and self.keeps_end(self.networks[-1]) \
            and is_blank(self.networks[-2])

    @property
    def loading(self) -> bool:
        """True while a large program's networks are still being laid out."""
        return self.loader.loading

    def finish_loading(self) -> None:
        """Lay out every network still pending now."""
        self.loader.finish()

    def append_networks(self, networks: list[LadderNetwork]) -> None:
        """Add laid-out networks before the blank network at the end (background loading)."""
        at = self.blank_index()
        self.networks[at:at] = networks
        self.networks_inserted.emit(at, len(networks))
        if networks and self.keeps_end(networks[-1]) and not self.end_is_last():
            self.insert_network(len(self.networks), self.remove_network(at + len(networks) - 1))

    def _laid_out(self, networks: list[LadderNetwork], trailer: list[str] | None) -> None:
        self.append_networks(networks)
        if trailer is not None:  # the last networks of the program
            self.document.trailer = trailer

    def ladder_document(self) -> LadderDocument:
        """The document with the drawn networks (the blank network at the end left out)."""
        self.finish_loading()
        doc = self.document
        nets = list(self.networks)
        if nets and is_blank(nets[self.blank_index()]):
            nets.pop(self.blank_index())
        return LadderDocument(nets, doc.header, doc.trailer, doc.footer, doc.before, doc.after,
                              doc.origin)

    def saved_program(self) -> tuple[Program, list[Diagnostic]]:
        """The program to save: a network that cannot be coded yet is kept as a draft, one
        still as it was read is its instructions as read."""
        program, diagnostics = convert.ladder_to_program(self.ladder_document(), self.kept)
        self.diagnostics_found.emit(diagnostics)
        return program, diagnostics

    def program(self) -> tuple[Program | None, list[Diagnostic]]:
        """The program drawn (None when a network cannot be coded) and the diagnostics."""
        program, diagnostics = self.saved_program()
        return (None if has_errors(diagnostics) else program), diagnostics

    def is_empty(self) -> bool:
        """True when nothing is drawn."""
        self.finish_loading()
        return all(net.is_empty() for net in self.networks)

    @property
    def dialect(self) -> str:
        """The program's dialect (how function parameters are ranged)."""
        return self.document.origin.dialect if self.document.origin is not None else "seed"

    # -- modified state ------------------------------------------------------------------

    def is_modified(self) -> bool:
        """True when the drawing differs from what was last read or saved."""
        return not self.undo_stack.isClean()

    def _clean_changed(self, clean: bool) -> None:
        self.modified_changed.emit(not clean)

    def mark_modified(self) -> None:
        """Make the document count as changed (e.g. after text edits shown as ladder)."""
        self.undo_stack.resetClean()

    def mark_saved(self) -> None:
        """The drawing is what was just saved."""
        self.undo_stack.setClean()

    # -- changes (called by the undo commands) -------------------------------------------

    def prepare(self, index: int, operation: Callable[[LadderNetwork], object]) -> Edit:
        """The edit that makes `operation`'s change to network `index`, worked out on a copy
        (EditRefused: nothing changes); pushing a command with it makes the change."""
        work = self.networks[index].copy()
        operation(work)
        return Edit(work.state())

    def apply(self, index: int, edit: Edit) -> Edit:
        """Apply an edit to network `index`; return its inverse."""
        inverse = edit.apply(self.networks[index])
        self.network_changed.emit(index)
        return inverse

    def apply_many(self, edits: list[tuple[int, Edit]]) -> list[tuple[int, Edit]]:
        """Apply edits to several networks, announced once; return their inverses."""
        inverses = [(index, edit.apply(self.networks[index])) for index, edit in edits]
        self.networks_changed.emit([index for index, _edit in inverses])
        return inverses

    def insert_network(self, index: int, network: LadderNetwork) -> None:
        """Insert a network at `index`."""
        self.networks.insert(index, network)
        self.networks_inserted.emit(index, 1)

    def remove_network(self, index: int) -> LadderNetwork:
        """Remove the network at `index`; returns it."""
        network = self.networks.pop(index)
        self.network_removed.emit(index)
        return network


__all__ = ["LadderModel", "Mode", "ends_program", "is_blank"]
