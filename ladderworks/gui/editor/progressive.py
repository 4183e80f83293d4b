"""Opening a large program: the first networks are laid out at once, the rest in the background
(a few hundred at a time between events), so the ladder is on screen before all is laid out."""

from __future__ import annotations

from PySide6.QtCore import QObject, QTimer, Signal

from ladderworks.core.collector import freeze_alive
from ladderworks.core.il import Network, Program
from ladderworks.core.ladder import LadderDocument, convert

AT_ONCE = 300  # a program with more networks than this lays the rest out in the background
CHUNK = 400  # networks laid out per step in the background


class ProgressiveLoader(QObject):
    """Lays out a program's networks: the head now, the rest step by step, each step's
    networks announced by `laid_out` (the model appends them)."""

    laid_out = Signal(list, object)  # the networks laid out; the trailer with the last, else None

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.pending: list[Network] = []
        self.trailer: list[str] = []
        self.kept: convert.Kept | None = None  # receives each network as first laid out
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self.step)

    @property
    def loading(self) -> bool:
        """True while networks are still to be laid out."""
        return bool(self.pending)

    def head(self, program: Program, kept: convert.Kept | None = None) -> LadderDocument:
        """The document of the first networks (all of a small program); the rest is pending.

        `kept` receives every network as laid out (now and in the background steps), so Save
        writes an unchanged network exactly as it was read."""
        self.cancel()
        self.kept = kept
        if len(program.networks) <= AT_ONCE:
            return convert.program_to_ladder(program, kept)
        first = Program(networks=program.networks[:AT_ONCE], header=program.header,
                        before=program.before, after=program.after, footer=program.footer)
        document = convert.program_to_ladder(first, kept)
        document.origin = program
        self.pending = list(program.networks[AT_ONCE:])
        self.trailer = list(program.trailer)
        return document

    def start(self) -> None:
        """Begin the background steps (after the view shows the head)."""
        if self.pending:
            self._timer.start()

    def cancel(self) -> None:
        """Forget what is pending (another program is shown)."""
        self.pending = []
        self.trailer = []
        self._timer.stop()

    def step(self) -> None:
        """Lay out the next chunk and append it before the model's blank last network."""
        if not self.pending:
            return
        chunk, self.pending = self.pending[:CHUNK], self.pending[CHUNK:]
        last = not self.pending
        part = convert.program_to_ladder(
            Program(networks=chunk, trailer=self.trailer if last else []), self.kept)
        self.laid_out.emit(part.networks, part.trailer if last else None)
        if last:
            self.trailer = []
            freeze_alive()  # a large program laid out: collections no longer walk it
        else:
            self._timer.start()

    def finish(self) -> None:
        """Lay out everything pending now."""
        self._timer.stop()
        while self.pending:
            self.step()
        self._timer.stop()
