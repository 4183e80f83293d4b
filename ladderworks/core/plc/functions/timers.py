"""Timers: TMR (preset in the T table), TMRB (preset in the program), TMRC (preset at an address).

All three are on-delay timers measured on the engine's virtual clock: the time runs from the
first scan that sees ACT = 1; W1 = 1 from the first scan at which the elapsed time reaches the
effective preset; ACT = 0 resets the timer (W1 = 0 at once).
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.memory import Memory

TIMER_BYTES = 4  # bytes of preset (ms, binary) per timer in the T area
SLOW_TIMERS = 8  # timers 1..8 count in 48 ms ticks
SLOW_TICK_MS = 48
FAST_TICK_MS = 8  # timers 9..100, and TMRB
TMRC_UNIT_MS = {0: 1, 1: 8}  # TMRC accuracy: 0 = 1 ms, 1 = 8 ms (seed manual)


def timer_preset_address(number: int) -> Address:
    """Where timer `number`'s preset (4 bytes of ms) lives: T[(number - 1) * 4]."""
    return Address(Area.T, (number - 1) * TIMER_BYTES)


def read_timer_preset(memory: Memory, number: int) -> int:
    """Timer `number`'s preset in ms as stored in the T table."""
    return memory.read(timer_preset_address(number), TIMER_BYTES)


def write_timer_preset(memory: Memory, number: int, ms: int) -> None:
    """Set timer `number`'s preset in ms in the T table."""
    memory.write(timer_preset_address(number), ms, TIMER_BYTES)


def timer_tick(number: int) -> int:
    """The tick of TMR `number` in ms: 48 for timers 1..8, 8 for 9..100."""
    return SLOW_TICK_MS if number <= SLOW_TIMERS else FAST_TICK_MS


def effective_preset(preset_ms: int, tick_ms: int) -> int:
    """The preset rounded down to the tick (a preset below one tick acts at once)."""
    return max(preset_ms, 0) // tick_ms * tick_ms


def _elapsed(ctx: FunctionContext, state: dict, act: bool) -> int | None:
    """Elapsed ms since ACT went on, or None when ACT is off (the timer is reset)."""
    if not act:
        state["start"] = None
        return None
    start = state.get("start")
    if start is None:
        start = state["start"] = ctx.now_ms
    return ctx.now_ms - start


@function("TMR")
def tmr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer with the preset of timer n read from the T table each scan."""
    (number,) = params
    elapsed = _elapsed(ctx, state, inputs[-1])
    if elapsed is None:
        return False
    preset = effective_preset(read_timer_preset(ctx.memory, number), timer_tick(number))
    return elapsed >= preset


@function("TMRB")
def tmrb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer with a fixed preset (ms) in the program; 8 ms tick."""
    _number, preset = params
    elapsed = _elapsed(ctx, state, inputs[-1])
    if elapsed is None:
        return False
    return elapsed >= effective_preset(preset, FAST_TICK_MS)


@function("TMRC")
def tmrc(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer: preset (2 B binary, in accuracy units) at an address; the 4-byte register
    holds the elapsed time in accuracy units, held at the preset once reached."""
    accuracy, preset_at, register = params
    unit = TMRC_UNIT_MS.get(accuracy, 1)
    elapsed = _elapsed(ctx, state, inputs[-1])
    if elapsed is None:
        ctx.memory.write(register, 0, 4)
        return False
    preset = ctx.memory.read(preset_at, 2)
    units = min(elapsed // unit, preset)
    ctx.memory.write(register, units, 4)
    return units >= preset
