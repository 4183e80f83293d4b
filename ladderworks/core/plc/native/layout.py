"""The native scan's state words (one i32 array beside memory) and its result codes."""

from __future__ import annotations

from dataclasses import dataclass

ABORT = 0  # 0 = running; JUMP_MAIN or FAILED while the scan unwinds
JUMP_LABEL = 1  # JMPC: the label to go on at in the level's main program
LOOP_UNIT = 2  # the endless-loop stop: the unit and the chunk jumped to
LOOP_CHUNK = 3
CARRIED = 4  # 9 words: the stack values a giant network's next chunk goes on with
FIRST_FREE = CARRIED + 9

JUMP_MAIN = 1  # ABORT: a JMPC is leaving the subprograms
FAILED = 2  # ABORT: a call-back raised (the exception is re-raised) or the loop guard stopped
LOOPED = 3  # ABORT: the loop guard


@dataclass(frozen=True, slots=True)
class Layout:
    """Where each unit's jump id (SK) and each COM gate (CM) and DIFU/DIFD memory live."""

    units: int
    commons: int
    edges: int

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
    def words(self) -> int:
        return self.edge_base + self.edges
