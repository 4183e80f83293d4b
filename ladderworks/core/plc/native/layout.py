"""The native scan's state words (one i32 array beside memory) and its result codes."""

from __future__ import annotations

from dataclasses import dataclass

ABORT = 0  # 0 = running; JUMP_MAIN or FAILED while the scan unwinds
JUMP_LABEL = 1  # JMPC: the label to go on at in the level's main program
LOOP_UNIT = 2  # the endless-loop stop: the unit and the chunk jumped to
LOOP_CHUNK = 3
CARRIED = 4  # 9 words: the stack values a giant network's next chunk goes on with
NOW = 14  # i64: the scan's time (ctx.now_ms)
SCAN_MS = 16  # i64: the time since the last scan (ctx.scan_ms)
WAKE = 18  # i64: the earliest wake a timer said in this scan (ctx.wake_ms)
DIRTY = 20  # the entries of the changed list: state blocks (k >= 0), edge memories (-1 - k)
FIRST_FREE = 22

JUMP_MAIN = 1  # ABORT: a JMPC is leaving the subprograms
FAILED = 2  # ABORT: a call-back raised (the exception is re-raised) or the loop guard stopped
LOOPED = 3  # ABORT: the loop guard


@dataclass(frozen=True, slots=True)
class Layout:
    """Where each unit's jump id (SK) and each COM gate (CM) and DIFU/DIFD memory live."""

    units: int
    commons: int
    edges: int
    stateful: int = 0  # sites whose state lives in a block of state words (stateful.py)

    @property
    def jump_base(self) -> int:
        return FIRST_FREE

    @property
    def common_base(self) -> int:
        return FIRST_FREE + self.units

    @property
    def edge_base(self) -> int:
        return FIRST_FREE + self.units + self.commons

    @property
    def block_base(self) -> int:
        return self.edge_base + self.edges

    @property
    def marks(self) -> int:
        """The changed marks (1 while in the changed list): block k's at `marks + k`, edge
        memory n's at `marks - 1 - n` (the list's entry added to it). Outside the state
        words, so that the words before them are the program's state alone."""
        return self.block_base + 8 * self.stateful + self.edges

    @property
    def dirty(self) -> int:
        """The list of changed blocks and edge memories (one spare: the list is written one
        past its end)."""
        return self.marks + self.stateful

    @property
    def words(self) -> int:
        return self.dirty + self.stateful + self.edges + 1
