"""Delta DVP's device monitor tables (WPLSoft's device monitor): which rows use a timer or a
counter, where their presets are, and the timer bases (seed 001 for the DVP-14SS)."""

from __future__ import annotations

from ladderworks.core.address import Area
from ladderworks.core.dialects.delta import CR, M1028, MODULE_REGISTERS
from ladderworks.core.dialects.device_tables import Areas, DeviceTables, ModuleUse, Use

FAST_FIRST, FAST_LAST = 64, 126  # 10 ms while M1028 is on
MS_TIMER = 127  # 1 ms


def timer_base_ms(number: int, fast: bool) -> int:
    """Timer `number`'s base in ms: 100; 10 for T64-T126 while M1028 is on (`fast`); T127 1."""
    if number == MS_TIMER:
        return 1
    return 10 if fast and FAST_FIRST <= number <= FAST_LAST else 100


def base_now(number: int, areas: Areas) -> int:
    """Timer `number`'s base in ms with M1028 as the memory holds it now."""
    relays = areas[Area.R]
    return timer_base_ms(number, bool(relays[M1028.byte] >> (M1028.bit or 0) & 1))


TABLES = DeviceTables(
    timers={"DVP.TMR": Use(0, 1)},
    counters={"DVP.CNT": Use(0, 1), "DVP.DCNT": Use(0, 1, up_down=True)},
    timer_base=base_now, registers=("D", "CR"), constant="K{0}",
    switched_bases={n: ("M1028", 10) for n in range(FAST_FIRST, FAST_LAST + 1)},
    # FROM/TO m1 m2 D n: module m1's CR#m2 .. (n words; the D forms n pairs), listed as CR
    modules={**{f"DVP.{name}": ModuleUse(0, 1, 3) for name in ("FROM", "FROMP", "TO", "TOP")},
             **{f"DVP.{name}": ModuleUse(0, 1, 3, 2)
                for name in ("DFROM", "DFROMP", "DTO", "DTOP")}},
    module_letter=CR.letter, module_size=MODULE_REGISTERS)
