"""Delta DVP TMR: a 16-bit on-delay timer, its value and contact in the T device.

Input on: the value counts up in the timer's base (T0-T63 and T128-T255 100 ms; T64-T126
100 ms, or 10 ms while M1028 is on; T127 1 ms: seed 001 for the DVP-14SS) and stops at the
set value; the contact is on while value >= set value. Input off: value 0, contact off. Time is
the engine's virtual clock, counted only while the TMR executes (each scan it runs adds that
scan's time once; the scan that starts it adds 0): a timer skipped by CJ, or in a subroutine
not called, holds its value and goes on later (seed 003). docs/dialects.md.
"""

from __future__ import annotations

from functools import cache

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import M1028, T
from ladderworks.core.dialects.delta.tables import timer_base_ms
from ladderworks.core.plc.functions import FunctionContext, executed_once_this_scan, function
from ladderworks.core.plc.functions.dvp_data import value
from ladderworks.core.plc.memory import Memory

MAX_VALUE = 32767


def base_ms(memory: Memory, number: int) -> int:
    """Timer `number`'s base in ms (M1028 read now; the rule is core/dialects/delta/tables)."""
    return timer_base_ms(number, bool(memory.bit(M1028)))


@cache
def timer_number(address: Address) -> int:
    """The number of the timer whose value is at `address`."""
    number = T.word_number(address)
    assert number is not None
    return number


@function("DVP.TMR")
def tmr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """TMR Tn SV: see the module's docstring; passes its input on."""
    act = bool(inputs[-1])
    timer, preset = params
    memory = ctx.memory
    number = timer_number(timer)
    contact = T.bit_address(number)
    if not act:
        memory.write(timer, 0, 2)
        memory.set_bit(contact, False)
        state["running"] = False
        state["ms"] = 0
        return act
    if executed_once_this_scan(ctx, state):
        elapsed = state.get("ms", 0) + (ctx.scan_ms if state.get("running") else 0)
        state["running"] = True
        target = value(memory, preset)
        current = memory.read(timer, 2, signed=True)
        base = base_ms(memory, number)
        if current < target:
            ticks, state["ms"] = divmod(elapsed, base)
            ctx.wake(state, ctx.now_ms + base - state["ms"])  # the next tick
            current = min(current + ticks, target, MAX_VALUE)
            memory.write(timer, current, 2)
        else:  # stopped at the set value: no time counts on (docs/dialects.md)
            state["ms"] = 0
            ctx.wake(state)
        memory.set_bit(contact, current >= target)
    return act
