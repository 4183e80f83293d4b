"""Delta's whole instruction table: instructions.py's rows with rows_extra.py's, the modules
that run them and the mnemonics read but not simulated (imported after both, so neither
imports the other back)."""

from __future__ import annotations

from ladderworks.core.dialects.delta import rows_extra
from ladderworks.core.dialects.delta.instructions import (
    DATA_NAMES,
    LISTED_NOT_SIMULATED,
    ROWS_LIST,
    SPELLINGS,
)
from ladderworks.core.instructions import Combine, InstructionSpec, Kind

ROWS: tuple[InstructionSpec, ...] = tuple(ROWS_LIST)

# The functions each module of plc/functions implements for Delta (plc/families.py reads it).
FAMILIES: dict[str, tuple[str, ...]] = {
    "dvp_contacts": tuple(row.name for row in ROWS  # (FLD= ...: delta_float's, by ACTIONS)
                          if row.combine is not Combine.NONE and row.kind is Kind.FUNCTION
                          and row.name not in rows_extra.ACTIONS),
    "dvp_timers": ("DVP.TMR",),
    "dvp_counters": ("DVP.CNT", "DVP.DCNT", "DVP.RST.WORD"),
    "dvp_data": (*(f"DVP.{name}{pulse}" for name in DATA_NAMES for pulse in ("", "P")),
                 "DVP.PLS", "DVP.PLF"),
}
FAMILIES.update(rows_extra.FAMILIES)
# the manual's list as first written, with the rest of it; less those the reader now reads
NOT_SIMULATED: frozenset[str] = (LISTED_NOT_SIMULATED
                                 | rows_extra.MORE_NOT_SIMULATED) - SPELLINGS.keys()
