"""Where TMR presets live in the T area, by the program's dialect (seed: ms; fanuc: ticks)."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.address import AREA_SIZES, Address, Area
from ladderworks.core.instructions import Numbered, numbered_row
from ladderworks.core.plc.functions.timers import effective_preset, timer_tick

SEED = "seed"
FANUC = "fanuc"
FANUC_PRECISION_BYTE = 9000  # T9000 + 2(n-1): the precision code of TMR n
# FANUC precision codes: 0 = the timer's default tick (48 ms for 1..8, 8 ms after), then fixed.
PRECISION_MS: dict[int, int] = {1: 1, 2: 10, 3: 100, 4: 1000, 5: 60_000}
MAX_SEED_PRESET_MS = 99_999_999  # the seed manual's range of a timer preset


def dialect_of(program: object) -> str:
    """The dialect of a Program or binary: "fanuc" for LADDER-III programs, else "seed"."""
    return FANUC if getattr(program, "dialect", SEED) == FANUC else SEED


@dataclass(frozen=True, slots=True)
class TimerLayout:
    """The T-area layout of TMR presets: width and unit per dialect, plus FANUC precision codes."""

    dialect: str
    width: int  # bytes per preset
    unit: str  # "ms" (seed) or "ticks" (fanuc)
    count: int  # TMR 1..count have a preset in the T area
    max_preset: int

    @property
    def has_precision(self) -> bool:
        """True when each timer has a precision code (FANUC)."""
        return self.dialect == FANUC

    def preset_address(self, number: int) -> Address:
        """Where TMR `number`'s preset starts."""
        return Address(Area.T, (number - 1) * self.width)

    def precision_address(self, number: int) -> Address | None:
        """Where TMR `number`'s precision code lives (FANUC; None when not in the T area)."""
        byte = FANUC_PRECISION_BYTE + 2 * (number - 1)
        if not self.has_precision or byte + 2 > AREA_SIZES[Area.T]:
            return None
        return Address(Area.T, byte)

    def tick_ms(self, number: int, precision: int = 0) -> int:
        """The timer's tick in ms (seed: 48 ms for TMR 1..8, else 8 ms)."""
        if self.has_precision and precision in PRECISION_MS:
            return PRECISION_MS[precision]
        return timer_tick(number)

    def delay_ms(self, number: int, preset: int, precision: int = 0) -> int:
        """The delay the timer really gives: seed rounds ms down to the tick; fanuc counts ticks."""
        tick = self.tick_ms(number, precision)
        if self.has_precision:
            return max(preset, 0) * tick
        return effective_preset(preset, tick)


def timer_layout(dialect: str) -> TimerLayout:
    """The timer layout of a dialect."""
    size = AREA_SIZES[Area.T]
    timer = numbered_row(Numbered.TIMER).params[0]
    count = timer.highest(dialect)  # seed 1..100, 30i memory-B 1..250
    if dialect == FANUC:
        return TimerLayout(FANUC, 2, "ticks", min(count, size // 2), 32767)
    return TimerLayout(SEED, 4, "ms", min(count, size // 4), MAX_SEED_PRESET_MS)
