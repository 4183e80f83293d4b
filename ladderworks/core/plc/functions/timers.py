"""Timers: TMR (preset in the T table), TMRB (preset in the program), TMRC (preset at an
address) and TMRBF (off-delay, preset in the program).

Time is the engine's virtual clock, counted only while the timer executes: each scan in which a
call site runs adds that scan's `ctx.scan_ms` once (the scan that starts the timer adds 0). A
timer that is not executed (skipped by JMP, in a subprogram that is not called) is frozen: it
neither runs nor resets. On-delay timers: W1 = 1 from the first execution at which the elapsed
time reaches the effective preset; ACT = 0 resets the timer (W1 = 0 at once).

The T table depends on the program's dialect (`ctx.dialect`): a "seed" program keeps 4 bytes of
preset in ms per timer at T[4(n-1)]; a "fanuc" program keeps 2 bytes of preset in ticks of the
timer's precision at T[2(n-1)] and the precision code at T9000+2(n-1).
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.functions import (
    NEVER,
    FunctionContext,
    executed_once_this_scan,
    fits,
    function,
)
from ladderworks.core.plc.memory import Memory

TIMER_BYTES = 4  # seed: bytes of preset (ms, binary) per timer in the T area
FANUC_TIMER_BYTES = 2  # fanuc: bytes of preset (ticks) per timer
FANUC_PRECISION_BASE = 9000  # fanuc: T9000 + 2(n-1) holds timer n's precision code
FANUC_MAX_TICKS = 32767
SLOW_TIMERS = 8  # timers 1..8 count in 48 ms ticks
SLOW_TICK_MS = 48
FAST_TICK_MS = 8  # timers 9.., and TMRB/TMRBF
# TMR precision codes of a FANUC program (0: the default tick of the timer number)
TMR_PRECISION_MS = {1: 1, 2: 10, 3: 100, 4: 1000, 5: 60_000}
TMRC_UNIT_MS = {0: 1, 1: 8}  # seed TMRC accuracy: 0 = 1 ms, 1 = 8 ms (seed manual)
# FANUC 30i TMRC accuracy: 0 = 8 ms, 1 = 48 ms, 2 = 1 s, 3 = 10 s, 4 = 1 min, 5-7 = 1/10/100 ms
FANUC_TMRC_UNIT_MS = {0: 8, 1: 48, 2: 1000, 3: 10_000, 4: 60_000, 5: 1, 6: 10, 7: 100}


def timer_preset_address(number: int, dialect: str = "seed") -> Address:
    """Where timer `number`'s preset lives: T[4(n-1)] (seed) or T[2(n-1)] (fanuc)."""
    size = FANUC_TIMER_BYTES if dialect == "fanuc" else TIMER_BYTES
    return Address(Area.T, (number - 1) * size)


def timer_precision_address(number: int) -> Address:
    """Where a FANUC program keeps timer `number`'s precision code: T9000 + 2(n-1)."""
    return Address(Area.T, FANUC_PRECISION_BASE + (number - 1) * FANUC_TIMER_BYTES)


def _read(memory: Memory, address: Address, width: int) -> int:
    """Unsigned data at `address`, 0 when it lies past the end of the area."""
    return memory.read(address, width) if fits(memory, address, width) else 0


def read_timer_preset(memory: Memory, number: int) -> int:
    """Timer `number`'s preset in ms as stored in a seed program's T table."""
    return _read(memory, timer_preset_address(number), TIMER_BYTES)


def write_timer_preset(memory: Memory, number: int, ms: int) -> None:
    """Set timer `number`'s preset in ms in a seed program's T table."""
    memory.write(timer_preset_address(number), ms, TIMER_BYTES)


def timer_tick(number: int) -> int:
    """The default tick of TMR `number` in ms: 48 for timers 1..8, 8 from timer 9 on."""
    return SLOW_TICK_MS if number <= SLOW_TIMERS else FAST_TICK_MS


def fanuc_tick(memory: Memory, number: int) -> int:
    """The tick of TMR `number` in a FANUC program, from its precision code (unknown -> 0)."""
    code = _read(memory, timer_precision_address(number), 1)
    return TMR_PRECISION_MS.get(code, timer_tick(number))


def fanuc_preset_ms(memory: Memory, number: int) -> int:
    """Timer `number`'s preset in ms in a FANUC program: ticks (at most 32767) x tick."""
    ticks = min(_read(memory, timer_preset_address(number, "fanuc"), FANUC_TIMER_BYTES),
                FANUC_MAX_TICKS)
    return ticks * fanuc_tick(memory, number)


def effective_preset(preset_ms: int, tick_ms: int) -> int:
    """The preset rounded down to the tick (a preset below one tick acts at once)."""
    return max(preset_ms, 0) // tick_ms * tick_ms


def reached(ctx: FunctionContext, state: dict, elapsed: int, preset_ms: int) -> bool:
    """True once `elapsed` reaches `preset_ms`; until then the timer wakes the scan in which
    it would (time that passes without a scan cannot be skipped past it)."""
    if elapsed >= preset_ms:
        ctx.wake(state)
        return True
    ctx.wake(state, ctx.now_ms + preset_ms - elapsed)
    return False


def elapsed_ms(ctx: FunctionContext, state: dict, running: bool) -> int | None:
    """ms the timer has run, counted only in scans that execute it; None (and reset) when it
    does not run."""
    if not running:
        state["elapsed"] = None
        return None
    counting = executed_once_this_scan(ctx, state)
    elapsed = state.get("elapsed")
    if elapsed is None:
        elapsed = 0
    elif counting:
        elapsed += ctx.scan_ms
    state["elapsed"] = elapsed
    return elapsed


@function("TMR")
def tmr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer with the preset of timer n read from the T table each scan."""
    (number,) = params
    elapsed = elapsed_ms(ctx, state, inputs[-1])
    if elapsed is None:
        return False
    if ctx.dialect == "fanuc":
        return reached(ctx, state, elapsed, fanuc_preset_ms(ctx.memory, number))
    return reached(ctx, state, elapsed,
                   effective_preset(read_timer_preset(ctx.memory, number), timer_tick(number)))


@function("TMRB")
def tmrb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer with a fixed preset (ms) in the program; 8 ms tick."""
    _number, preset = params
    elapsed = elapsed_ms(ctx, state, inputs[-1])
    if elapsed is None:
        return False
    return reached(ctx, state, elapsed, effective_preset(preset, FAST_TICK_MS))


@function("TMRBF")
def tmrbf(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Off-delay timer: W1 = 1 while ACT = 1 and for the preset (ms, 8 ms tick) after ACT
    drops; ACT back to 1 clears the timer. W1 = 0 at power-on."""
    _number, preset = params
    if inputs[-1]:
        state["on"] = True
        elapsed_ms(ctx, state, False)
        return True
    if not state.get("on"):
        return False
    elapsed = elapsed_ms(ctx, state, True)
    assert elapsed is not None
    if reached(ctx, state, elapsed, effective_preset(preset, FAST_TICK_MS)):
        state["on"] = False
        elapsed_ms(ctx, state, False)
    return bool(state["on"])


@function("TMRC")
def tmrc(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay timer: preset (2 B binary, in accuracy units) at an address; the 4-byte register
    holds the elapsed time in accuracy units, held at the preset once reached."""
    accuracy, preset_at, register = params
    units_ms = FANUC_TMRC_UNIT_MS if ctx.dialect == "fanuc" else TMRC_UNIT_MS
    unit = units_ms.get(accuracy, units_ms[0])
    elapsed = elapsed_ms(ctx, state, inputs[-1])
    if elapsed is None:
        ctx.memory.write(register, 0, 4)
        return False
    preset = ctx.memory.read(preset_at, 2)
    units = min(elapsed // unit, preset)
    # the register changes at the next unit, until the preset
    ctx.wake(state, ctx.now_ms + unit - elapsed % unit if units < preset else NEVER)
    ctx.memory.write(register, units, 4)
    return units >= preset
