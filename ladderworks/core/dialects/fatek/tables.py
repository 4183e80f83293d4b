"""Fatek FBs's device monitor tables (WinProladder's): which rows use a timer or a counter,
where their presets are, the timer bases by number (seed 001:392-416), registers R and D."""

from __future__ import annotations

from ladderworks.core.dialects.device_tables import Areas, DeviceTables, Use
from ladderworks.core.dialects.fatek.devices import timer_base_ms


def base_now(number: int, _areas: Areas) -> int:
    """Timer `number`'s base in ms: 10 (T0-T49), 100 (T50-T199), 1000 (T200-T255)."""
    return timer_base_ms(number)


TABLES = DeviceTables(
    timers={"FBS.TMR": Use(0, 1)},
    counters={"FBS.CTR": Use(0, 1), "FBS.UDCTR": Use(0, 1, up_down=True)},
    timer_base=base_now, registers=("R", "D"))
