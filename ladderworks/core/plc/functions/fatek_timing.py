"""Fatek FBs timers, counters, their RST, TU/TD edge contacts (docs/dialects.md, Fatek).

Timer Tn (001:392-432): EN = 1 counts in the number's base (0.01 s, 0.1 s, 1 s); the present
value CV (read from memory each scan, so a value set from the PLC tables counts on) runs on to
32767 and stays; CV >= PV closes Tn and TUP (FO0); EN = 0 clears CV, Tn and
TUP. Counter Cn (001:572-612): CLR = 1 clears CV, Cn and CUP (FO0) and stops counting; else each
CK 0 -> 1 adds 1; CUP and Cn while CV >= PV; CV stops at 32767 (2147483647 for C200-C255).
Up/down counter FUN 7 (001:652-694): U/D = 1 up, 0 down; FO0 only while CV = PV; wraps.
"""

from __future__ import annotations

from functools import cache

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.devices import (
    Device,
    bit_address,
    counter_is_32bit,
    counter_is_retentive,
    timer_base_ms,
    word_address,
    word_device_at,
)
from ladderworks.core.plc.functions import NEVER, FunctionContext, executed_once_this_scan, function
from ladderworks.core.plc.memory import Memory

MAX16 = 32767


def operand_value(memory: Memory, value: object, width: int = 2) -> int:
    """A VALUE parameter: a constant, or the signed value at a register address."""
    if isinstance(value, Address):
        return memory.read(value, width, signed=True)
    assert isinstance(value, int)
    return value


def write_outputs(memory: Memory, fo: object, *bits: bool) -> None:
    """Store a box's FO0, FO1 … in its output byte."""
    if isinstance(fo, Address):
        value = 0
        for n, bit in enumerate(bits):
            if bit:
                value |= 1 << n
        memory.areas[fo.area][fo.byte] = value


def _set(memory: Memory, device: Device, value: bool) -> None:
    memory.set_bit(bit_address(device), value)


@cache
def places(kind: str, number: int) -> tuple[Device, Address, int, Address]:
    """The device, its value's address and width, its contact: found once per device (not
    kept in the call site's state, which holds only what the native code keeps too)."""
    device = Device(kind, number)
    return (device, *word_address(device), bit_address(device))


@function("FBS.TMR")
def fatek_timer(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    """Timer Tn with PV a constant or a register (001:449-461)."""
    number, preset, fo = params
    _device, cv_at, _width, contact = places("T", number)
    memory = ctx.memory
    if not inputs[0]:
        state["ms"] = None
        memory.write(cv_at, 0, 2)
        memory.set_bit(contact, False)
        write_outputs(memory, fo, False)
        return False
    counting = executed_once_this_scan(ctx, state)
    rest = state.get("ms")
    base = timer_base_ms(number)
    if rest is None:  # the scan that starts it: CV 0
        rest, value = 0, 0
    else:  # CV as the memory holds it (the PLC tables may have changed it) + the counts
        ticks, rest = divmod(rest + (ctx.scan_ms if counting else 0), base)
        value = min(memory.read(cv_at, 2, signed=True) + ticks, MAX16)
    if value >= MAX16:  # at its most no time counts on
        rest = 0
    state["ms"] = rest
    # the present value changes at the next tick, until its most
    ctx.wake(state, ctx.now_ms + base - rest if value < MAX16 else NEVER)
    memory.write(cv_at, value, 2)
    up = value >= operand_value(memory, preset)
    memory.set_bit(contact, up)
    write_outputs(memory, fo, up)
    return up


def _counter_start(memory: Memory, state: dict, device: Device, cv_at: Address,
                   width: int) -> None:
    """A non-retentive counter starts from 0 when the program is loaded (001:576-588)."""
    if "loaded" not in state:
        state["loaded"] = True
        if not counter_is_retentive(device.number):
            memory.write(cv_at, 0, width)


def _count_input(ctx: FunctionContext, state: dict, number: int, ck: bool, clr: bool,
                 fo: object) -> tuple[Device, Address, int, bool] | None:
    """What the counters share: their places, the value at the load, CK's rising edge; None
    when CLR cleared the value, the contact and FO0."""
    device, cv_at, width, _contact = places("C", number)
    memory = ctx.memory
    _counter_start(memory, state, device, cv_at, width)
    rising = bool(ck) and not state.get("ck", False)
    state["ck"] = bool(ck)
    if clr:
        memory.write(cv_at, 0, width)
        _set(memory, device, False)
        write_outputs(memory, fo, False)
        return None
    return device, cv_at, width, rising


@function("FBS.CTR")
def fatek_counter(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                  params: tuple) -> bool:
    """Up counter Cn: inputs CK (top) and CLR."""
    number, preset, fo = params
    ck, clr = inputs
    counted = _count_input(ctx, state, number, ck, clr, fo)
    if counted is None:
        return False
    device, cv_at, width, rising = counted
    memory = ctx.memory
    value = memory.read(cv_at, width, signed=True)
    top = 2**31 - 1 if counter_is_32bit(number) else MAX16
    if rising and value < top:
        value += 1
        memory.write(cv_at, value, width)
    up = value >= operand_value(memory, preset, width)
    _set(memory, device, up)
    write_outputs(memory, fo, up)
    return up


@function("FBS.UDCTR")
def fatek_up_down_counter(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                          params: tuple) -> bool:
    """FUN 7 UDCTR: inputs CK, U/D, CLR; FO0 only while CV = PV; the value wraps. CV is a
    counter (`CV: C0`: its contact follows FO0) or a register (`CV: R 0`, as the FBs manual
    §5.1 writes it: 16 bits)."""
    cv_at, preset, fo = params
    ck, up_down, clr = inputs
    device = word_device_at(cv_at)
    if device is not None and device.kind == "C":
        counted = _count_input(ctx, state, device.number, ck, clr, fo)
        if counted is None:
            return False
        _device, cv_at, width, rising = counted
    else:
        device, width = None, 2
        rising = bool(ck) and not state.get("ck", False)
        state["ck"] = bool(ck)
        if clr:
            ctx.memory.write(cv_at, 0, width)
            write_outputs(ctx.memory, fo, False)
            return False
    memory = ctx.memory
    value = memory.read(cv_at, width, signed=True)
    if rising:
        memory.write(cv_at, value + (1 if up_down else -1), width)  # two's complement wrap
        value = memory.read(cv_at, width, signed=True)
    equal = value == operand_value(memory, preset, width)
    if device is not None:
        _set(memory, device, equal)
    write_outputs(memory, fo, equal)
    return equal


@function("FBS.RST")
def fatek_reset(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    """RST of a timer or counter: EN = 1 clears its present value and its contact."""
    kind, number = params
    if inputs[0]:
        device = Device("T" if kind == 0 else "C", number)
        cv_at, width = word_address(device)
        ctx.memory.write(cv_at, 0, width)
        _set(ctx.memory, device, False)
    return bool(inputs[0])


def edge(ctx: FunctionContext, state: dict, device: Address, rising: bool) -> bool:
    """The device changed (0 -> 1 or 1 -> 0) since this contact last ran (0 at the load)."""
    now = bool(ctx.memory.bit(device))
    before = state.get("before", False)
    state["before"] = now
    return (now and not before) if rising else (before and not now)


@function("FBS.TU")
def fatek_rising_contact(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                         params: tuple) -> bool:
    """TU contact: on for one scan after its device turns on (002:80), in series with IN."""
    return edge(ctx, state, params[0], True) and bool(inputs[0])


@function("FBS.TD")
def fatek_falling_contact(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                          params: tuple) -> bool:
    """TD contact: on for one scan after its device turns off (002:80), in series with IN."""
    return edge(ctx, state, params[0], False) and bool(inputs[0])
