"""Delta DVP counters: CNT (16-bit, C0-C199), DCNT (32-bit up/down, C200-C255), and RST of a
timer, counter or data register.

High-speed counters C235-C255 (DCNT's input enables them) count the off->on changes of their X
inputs seen by the scan (dvp_high_speed: one input, up/down inputs, A/B phases, reset and start
inputs); the preset is 32-bit (a D pair).

CNT Cn SV: +1 at each off->on of its input (a held input counts once) while value < SV; the
contact is on while value >= SV (seed 001:474-529). DCNT Cn SV: +1 (M1200+n-200 off) or -1
(on) at each off->on, wrapping at the 32-bit limits; contact on while value >= SV. RST: value
0 and contact off (a D register: 0). The edge memory of the input is 0 at power-on.
docs/dialects.md.
"""

from __future__ import annotations

from ladderworks.core.dialects.delta import DEVICES, M1200, WIDE_COUNTERS, C
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.delta_words32 import value32
from ladderworks.core.plc.functions.dvp_data import bit_after, rising, value, wrap
from ladderworks.core.plc.functions.dvp_high_speed import TABLE, step


def _number(address: object) -> int:
    number = C.word_number(address)  # type: ignore[arg-type]
    assert number is not None
    return number


@function("DVP.CNT")
def cnt(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """CNT Cn SV; passes its input on."""
    act = bool(inputs[-1])
    counter, preset = params
    memory = ctx.memory
    target = value(memory, preset)
    current = memory.read(counter, 2, signed=True)
    if rising(state, act) and current < target:
        current += 1
        memory.write(counter, current, 2)
    memory.set_bit(C.bit_address(_number(counter)), current >= target)
    return act


@function("DVP.DCNT")
def dcnt(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """DCNT Cn SV (C200-C255); passes its input on."""
    act = bool(inputs[-1])
    counter, preset = params
    memory = ctx.memory
    number = _number(counter)
    current = memory.read(counter, 4, signed=True)
    if number in TABLE:  # counts its X inputs while the input is on
        current = step(memory, state, number, act, current)
        memory.write(counter, current, 4)
    elif rising(state, act):
        down = memory.bit(bit_after(M1200, number - WIDE_COUNTERS))
        current = wrap(current + (-1 if down else 1), 4)
        memory.write(counter, current, 4)
    memory.set_bit(C.bit_address(number), current >= value32(memory, preset))
    return act


@function("DVP.RST.WORD")
def rst(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """RST Tn / Cn / Dn while the input is on; passes its input on."""
    act = bool(inputs[-1])
    if act:
        (device,) = params
        memory = ctx.memory
        memory.write(device, 0, DEVICES.width_at(device))
        found = DEVICES.device_of(device)
        if found is not None and found[0].bits is not None:
            memory.set_bit(found[0].bit_address(found[1]), False)
    return act
