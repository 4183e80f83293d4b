"""Ring counters: CTR (preset and value in the C area), CTRC (preset and register at addresses)
and CTRB (preset in the program, value at C5000 + 2(n-1)).

Control inputs CN0, UPDOWN, RST, ACT. A count happens on the rising edge of ACT (a scan with
ACT = 1 after a scan with ACT = 0). CN0 = 0 counts from 0, CN0 = 1 from 1 (the minimum).
Up (UPDOWN = 0): minimum .. preset, W1 = 1 at the preset, the next count wraps to the minimum.
Down (UPDOWN = 1): preset .. minimum, W1 = 1 at the minimum, the next count wraps to the preset.
RST = 1: W1 = 0 and the value goes to its start (up: minimum, down: preset); no counting.
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.functions import FunctionContext, fits, function
from ladderworks.core.plc.memory import Memory

COUNTER_BYTES = 4  # per counter in the C area: 2-byte preset, then 2-byte current value
MAX_PRESET = 32767
CTRB_BASE = 5000  # CTRB n keeps its current value at C5000 + 2(n-1), 2 bytes binary


def counter_preset_address(number: int) -> Address:
    """Where counter `number`'s preset lives: C[(number - 1) * 4], 2 bytes binary."""
    return Address(Area.C, (number - 1) * COUNTER_BYTES)


def counter_value_address(number: int) -> Address:
    """Where counter `number`'s current value lives: C[(number - 1) * 4 + 2], 2 bytes binary."""
    return Address(Area.C, (number - 1) * COUNTER_BYTES + 2)


def ctrb_value_address(number: int) -> Address:
    """Where CTRB `number`'s current value lives: C[5000 + (number - 1) * 2], 2 bytes."""
    return Address(Area.C, CTRB_BASE + (number - 1) * 2)


def write_counter_preset(memory: Memory, number: int, preset: int) -> None:
    """Set counter `number`'s preset in the C area."""
    memory.write(counter_preset_address(number), preset, 2)


def ring_count(state: dict, inputs: tuple[bool, ...], preset: int, value: int) -> tuple[int, bool]:
    """The counter's new value and W1 after one scan (shared by CTR and CTRC)."""
    cn0, down, rst, act = inputs
    low = 1 if cn0 else 0
    preset = max(preset, low)
    rising = act and not state.get("act", False)
    state["act"] = bool(act)
    if rst:
        return (preset if down else low), False
    if rising:
        if down:
            value = preset if value <= low else value - 1
        else:
            value = low if value >= preset else value + 1
    return value, (value <= low if down else value >= preset)


@function("CTR")
def ctr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Ring counter `n` (1..20); preset and value in the C area."""
    (number,) = params
    preset = ctx.memory.read(counter_preset_address(number), 2)
    where = counter_value_address(number)
    value, w1 = ring_count(state, inputs, preset, ctx.memory.read(where, 2))
    ctx.memory.write(where, value, 2)
    return w1


@function("CTRC")
def ctrc(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Ring counter with its preset (2 B, 0..32767) at an address; the register's first two
    bytes hold the current value, the other two are left alone."""
    preset_at, register = params
    preset = min(ctx.memory.read(preset_at, 2), MAX_PRESET)
    value, w1 = ring_count(state, inputs, preset, ctx.memory.read(register, 2))
    ctx.memory.write(register, value, 2)
    return w1


@function("CTRB")
def ctrb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Ring counter `n` with its preset fixed in the program; the current value at
    C5000 + 2(n-1) (kept in the call site while that address is past the C area)."""
    number, preset = params
    where = ctrb_value_address(number)
    stored = fits(ctx.memory, where, 2)
    current = ctx.memory.read(where, 2) if stored else state.get("value", 0)
    value, w1 = ring_count(state, inputs, min(preset, MAX_PRESET), current)
    if stored:
        ctx.memory.write(where, value, 2)
    state["value"] = value
    return w1
