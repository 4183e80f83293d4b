"""Siemens S7-1200 (TIA Portal): SIMATIC SD blocks and PLC tag tables on the one engine.

graph.py is the form both readers (SD here, SimaticML XML) build; lowering.py makes the
engine's networks; rows.py the instruction table's rows; devices.py the address map.
docs/dialects.md, "S7-1200".
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.base import Dialect
from ladderworks.core.dialects.s7.devices import DEVICES
from ladderworks.core.dialects.s7.rows import FAMILIES, NAME, ROWS
from ladderworks.core.dialects.s7.sniff import score

# The system and clock memory bytes as LadderWorks enables them (TIA's defaults %MB1, %MB0):
# %M1.0 FirstScan, %M1.1 DiagStatusUpdate (0), %M1.2 AlwaysTRUE, %M1.3 AlwaysFALSE;
# %M0.0 10 Hz … %M0.7 0.5 Hz (S7-1200 system manual V4.2, "System and clock memory").
SYSTEM_BYTE, CLOCK_BYTE = 1, 0
CLOCK_PERIODS = (100, 200, 400, 500, 800, 1000, 1600, 2000)  # %M0.0 … %M0.7, ms


def relays(areas: dict[Area, bytearray], now_ms: int, first: bool) -> None:
    """The system memory byte %MB1 and the clock memory byte %MB0, before each scan."""
    memory = areas[Area.R]
    memory[SYSTEM_BYTE] = (memory[SYSTEM_BYTE] & 0xF0) | (1 if first else 0) | 0x04
    clock = 0
    for bit, period in enumerate(CLOCK_PERIODS):
        if now_ms % period < period // 2:
            clock |= 1 << bit
    memory[CLOCK_BYTE] = clock


DIALECT = Dialect(
    name=NAME, title="Siemens S7-1200", title_tr="Siemens S7-1200", code=4, devices=DEVICES,
    rows=ROWS, sniff=score, reader="ladderworks.core.dialects.s7.opening:read",
    printer="ladderworks.core.dialects.s7.printer:network_lines", relays=relays,
    clocks=tuple((Address(Area.R, CLOCK_BYTE, bit), period, period // 2)
                 for bit, period in enumerate(CLOCK_PERIODS)),
    period_ms=10, extensions=(".s7dcl",), families=FAMILIES, byteorder="big",
    untyped_format="hex",
    namer="ladderworks.core.dialects.s7.printer:mnemonic_of",
    spelling="ladderworks.core.dialects.s7.printer:spelling",
    opener="ladderworks.core.dialects.s7.opening:open_path", refuse_changes="s7-save-changed",
    writer="ladderworks.core.dialects.s7.saving:write_changed",
    changed="ladderworks.core.dialects.s7.saving:changed_since_read",
    save_companions="ladderworks.core.dialects.s7.res_save:companions")
