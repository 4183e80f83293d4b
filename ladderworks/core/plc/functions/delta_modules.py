"""Delta DVP special modules and pulse output: FROM/DFROM, TO/DTO (and FROMP ...), PLSY/DPLSY.

FROM m1 m2 D n: n words from special module m1's control registers CR#m2.. into D..; TO m1
m2 S n: S.. (a constant: the same value n times) into CR#m2... The CRs live in the PLC's
memory (device CR100*m1+m2, area G: docs/dialects.md), so the PLC tables show and write them
as the module would; a CR past #99 is an operation error (the words before it are moved).
DFROM/DTO: n pairs. PLSY S1 S2 D (D Y0 or Y1): while its input is on, pulses at S1 Hz are
counted on the virtual clock until S2 are out (S2 = 0: no end), the count in D1030/D1031 (Y0)
or D1032/D1033 (Y1), the output on while pulses go out; at the end M1029 (Y0) / M1030 (Y1)
goes on. Input off: the output off, the count kept; on again: a new run from 0. No pulse
train is drawn (the scan is far slower than the pulses). docs/dialects.md.
"""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import CR, DEVICES, MODULE_REGISTERS, Y, relay
from ladderworks.core.dialects.delta.rows_extra import ACTIONS, FAMILIES
from ladderworks.core.plc.functions import FunctionContext, executed_once_this_scan, function
from ladderworks.core.plc.functions.delta_blocks import word_after
from ladderworks.core.plc.functions.delta_words32 import (
    operation_error,
    register,
    store32,
    value32,
)
from ladderworks.core.plc.functions.dvp_data import Impl, rising, value
from ladderworks.core.plc.memory import Memory

M1029, M1030 = relay(1029), relay(1030)  # Y0 / Y1 pulses all out
COUNTS = {Y.bit_address(0): (DEVICES.word("D1030")[0], M1029),
          Y.bit_address(1): (DEVICES.word("D1032")[0], M1030)}


def register_of(module: int, number: int) -> Address | None:
    """Where CR#`number` of special module `module` lives, or None (no place for it)."""
    if not 0 <= number < MODULE_REGISTERS or not 0 <= module <= 7:
        return None
    return CR.word_address(module * MODULE_REGISTERS + number)


def _transfer(memory: Memory, params: tuple, wide: bool, reading: bool) -> None:
    module, first, data, count = params
    m1, m2, n = value(memory, module), value(memory, first), value(memory, count)
    step = 2 if wide else 1
    for k in range(max(n, 0)):
        place = register_of(m1, m2 + k * step)
        if place is None or (wide and register_of(m1, m2 + k * step + 1) is None):
            operation_error(memory)
            return
        device = word_after(data, k * step) if isinstance(data, Address) else None
        if reading:
            if device is None:
                return
            if wide:
                store32(memory, device, memory.read(place, 4, signed=True))
            else:
                memory.write(device, memory.read(place, 2), 2)
        elif wide:
            memory.write(place, value32(memory, device if device is not None else data), 4)
        else:
            memory.write(place, value(memory, device if device is not None else data), 2)


def _from(memory: Memory, params: tuple) -> None:
    _transfer(memory, params, False, True)


def _from32(memory: Memory, params: tuple) -> None:
    _transfer(memory, params, True, True)


def _to(memory: Memory, params: tuple) -> None:
    _transfer(memory, params, False, False)


def _to32(memory: Memory, params: tuple) -> None:
    _transfer(memory, params, True, False)


register(__name__, {"from": _from, "from32": _from32, "to": _to, "to32": _to32})


def _pulses(wide: bool) -> Impl:
    read = value32 if wide else value

    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        """PLSY S1 S2 D: see the module's docstring; passes its input on."""
        act = bool(inputs[-1])
        frequency, total, output = params
        memory = ctx.memory
        place = COUNTS.get(output)
        if place is None:
            if act:
                operation_error(memory)
            return act
        count_at, done = place
        start = rising(state, act)
        if not act:
            memory.set_bit(output, False)
            state["ms"] = 0
            ctx.wake(state)
            return act
        if start:
            state["ms"] = 0
            state["at"] = ctx.now_ms
            memory.set_bit(done, False)
            store32(memory, count_at, 0)
        elif executed_once_this_scan(ctx, state):
            state["ms"] = state.get("ms", 0) + ctx.scan_ms
        hz, limit = read(memory, frequency), read(memory, total)
        count = value32(memory, count_at)
        if hz > 0 and (limit <= 0 or count < limit):
            count = max(count, state["ms"] * hz // 1000)
            if 0 < limit <= count:
                count = limit
            store32(memory, count_at, count)
        finished = 0 < limit <= count
        memory.set_bit(done, finished or memory.bit(done))
        memory.set_bit(output, hz > 0 and not finished)
        if hz > 0 and not finished:  # the next pulse counted
            ctx.wake(state, ctx.now_ms + max(-(-(count + 1) * 1000 // hz) - state["ms"], 1))
        else:
            ctx.wake(state)
        return act

    return run


for _name in FAMILIES["delta_modules"]:
    if ACTIONS[_name].startswith("pulses"):
        function(_name)(_pulses(ACTIONS[_name].endswith("32")))
