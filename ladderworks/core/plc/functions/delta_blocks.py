"""Delta DVP blocks of words and bits: ZRST, NOP, BMOV, FMOV/DFMOV, XCH/DXCH, SFTR, SFTL,
DECO, ENCO, ALT, SUM/DSUM, each with its pulse form (ZRSTP ...).

ZRST D1 D2 resets D1..D2 (bits Y/M/S off; T/C values 0 and their contacts off; D 0); D1 >
D2: only D1 [chosen]. BMOV S D n copies n words as a block (overlapping: as if through a
buffer); FMOV S D n writes S into n words (DFMOV: n pairs). SFTR/SFTL S D n1 n2 shift the n1
bits from D by n2 places (right: toward D; left: away from it) and fill the freed n2 bits
from S..S+n2-1. DECO S D n: the low n bits of S pick one of 2^n bits from D (a word D: bit of
the word, the others 0; n <= 4) to turn on, the others off. ENCO S D n: the number of the
highest bit on among S's 2^n bits (a word S: its low 2^n bits) into D; none on: operation
error, D kept. ALT D flips bit D at each execution (ALTP at each rising edge). SUM S D: the
number of bits on in S into D, M1020 when none. NOP (and WDT) do nothing and pass their input
on. In a step ladder's step, SET Sm / OUT Sm moves on: Sm on and the step's own S off.
docs/dialects.md.
"""

from __future__ import annotations

from functools import cache, lru_cache

from ladderworks.core.address import Address, AddressError
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.dialects.delta.rows_extra import ACTIONS, FAMILIES
from ladderworks.core.dialects.devices import Device
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.delta_words32 import (
    operation_error,
    register,
    store32,
    value32,
    width32,
)
from ladderworks.core.plc.functions.dvp_data import M1020, rising, value
from ladderworks.core.plc.memory import Memory


@lru_cache(maxsize=1 << 16)  # (operands and counts come from the program's values)
def word_after(address: Address, count: int) -> Address | None:
    """The word device `count` places after word device `address` (D4999 + 1 is D5000), or
    None when there is none."""
    found = device_at(address)
    if found is None:
        return None
    device, number = found
    try:
        return DEVICES.word(device.spell(number + count))[0]
    except AddressError:  # past the last device of its letter
        return None


@lru_cache(maxsize=1 << 12)
def bit_range(address: Address, count: int) -> tuple[Address, ...] | None:
    """The `count` bit devices from bit device `address` (M10, M11 ...; X7, X10 ...), or None
    when they run past the last of its letter."""
    found = DEVICES.device_of(address)
    if found is None or count < 0 or found[1] + count - 1 > found[0].last:
        return None
    device, number = found
    return tuple(device.bit_address(number + k) for k in range(count))


@cache
def device_at(address: Address) -> tuple[Device, int] | None:
    """The device and number at `address` (DeviceMap.device_of, kept: the map never changes)."""
    return DEVICES.device_of(address)


@lru_cache(maxsize=1 << 12)
def _words(address: Address, count: int, step: int = 1) -> tuple[Address, ...]:
    """`count` word devices from `address` (every `step`-th), as far as they exist."""
    places = []
    for k in range(count):
        place = word_after(address, k * step)
        if place is None:
            break
        places.append(place)
    return tuple(places)


def _reset_word(memory: Memory, address: Address) -> None:
    found = device_at(address)
    if found is None:
        return
    device, number = found
    memory.write(address, 0, device.width(number))
    if device.bits is not None:  # T, C: the contact too
        memory.set_bit(device.bit_address(number), False)


def _zone_reset(memory: Memory, params: tuple) -> None:
    first, last = params
    if first.bit is not None:
        one, two = device_at(first), device_at(last)
        if one is None or two is None or one[0].letter != two[0].letter:
            operation_error(memory)
            return
        for place in bit_range(first, max(two[1] - one[1], 0) + 1) or ():
            memory.set_bit(place, False)
        return
    one, two = device_at(first), device_at(last)
    if one is None or two is None or one[0].letter != two[0].letter or last.bit is not None:
        operation_error(memory)
        return
    for place in _words(first, max(two[1] - one[1], 0) + 1):
        _reset_word(memory, place)


def _block_move(memory: Memory, params: tuple) -> None:
    source, output, count = params
    n = value(memory, count)
    if not isinstance(source, Address) or n <= 0:
        return
    data = [memory.read(place, 2) for place in _words(source, n)]
    for place, word in zip(_words(output, len(data)), data, strict=False):
        memory.write(place, word, 2)


def _fill(memory: Memory, params: tuple) -> None:
    source, output, count = params
    number = value(memory, source)
    for place in _words(output, value(memory, count)):
        memory.write(place, number, 2)


def _fill32(memory: Memory, params: tuple) -> None:
    source, output, count = params
    number = value32(memory, source)
    for place in _words(output, value(memory, count), 2):
        store32(memory, place, number)


def _exchange(memory: Memory, params: tuple) -> None:
    one, two = params
    a, b = memory.read(one, 2), memory.read(two, 2)
    memory.write(one, b, 2)
    memory.write(two, a, 2)


def _exchange32(memory: Memory, params: tuple) -> None:
    one, two = params
    a, b = value32(memory, one), value32(memory, two)
    store32(memory, one, b)
    store32(memory, two, a)


def _shift(memory: Memory, params: tuple, right: bool) -> None:
    source, output, bits, shift = params
    n1, n2 = value(memory, bits), value(memory, shift)
    if not 0 < n2 <= n1:
        operation_error(memory)
        return
    targets, sources = bit_range(output, n1), bit_range(source, n2)
    if targets is None or sources is None:
        operation_error(memory)
        return
    old = [memory.bit(place) for place in targets]
    new = [memory.bit(place) for place in sources]
    shifted = old[n2:] + new if right else new + old[:n1 - n2]
    for place, on in zip(targets, shifted, strict=True):
        memory.set_bit(place, on)


def _shift_right(memory: Memory, params: tuple) -> None:
    _shift(memory, params, True)


def _shift_left(memory: Memory, params: tuple) -> None:
    _shift(memory, params, False)


def _decode(memory: Memory, params: tuple) -> None:
    source, output, bits = params
    n = value(memory, bits)
    word = output.bit is None
    if not 1 <= n <= (4 if word else 8):
        operation_error(memory)
        return
    which = value(memory, source) & ((1 << n) - 1)
    if word:
        memory.write(output, 1 << which, 2)
        return
    places = bit_range(output, 1 << n)
    if places is None:
        operation_error(memory)
        return
    for k, place in enumerate(places):
        memory.set_bit(place, k == which)


def _encode(memory: Memory, params: tuple) -> None:
    source, output, bits = params
    n = value(memory, bits)
    word = source.bit is None
    if not 1 <= n <= (4 if word else 8):
        operation_error(memory)
        return
    if word:
        states = [memory.read(source, 2) >> k & 1 for k in range(1 << n)]
    else:
        places = bit_range(source, 1 << n)
        if places is None:
            operation_error(memory)
            return
        states = [memory.bit(place) for place in places]
    on = [k for k, state in enumerate(states) if state]
    if not on:
        operation_error(memory)
        return
    memory.write(output, on[-1], 2)


def _alternate(memory: Memory, params: tuple) -> None:
    (output,) = params
    memory.set_bit(output, not memory.bit(output))


def _sum(memory: Memory, params: tuple) -> None:
    source, output = params
    count = (value(memory, source) & 0xFFFF).bit_count()
    memory.write(output, count, 2)
    memory.set_bit(M1020, count == 0)


def _sum32(memory: Memory, params: tuple) -> None:
    source, output = params
    count = (value32(memory, source) & 0xFFFF_FFFF).bit_count()
    memory.write(output, count, width32(output))
    memory.set_bit(M1020, count == 0)


def _move_step(memory: Memory, params: tuple) -> None:
    step, source = params
    memory.set_bit(step, True)
    if step != source:
        memory.set_bit(source, False)


register(__name__, {
    "zone-reset": _zone_reset, "block-move": _block_move, "fill": _fill, "fill32": _fill32,
    "exchange": _exchange, "exchange32": _exchange32, "shift-right": _shift_right,
    "shift-left": _shift_left, "decode": _decode, "encode": _encode, "alternate": _alternate,
    "sum": _sum, "sum32": _sum32, "step-set": _move_step, "step-out": _move_step})


def _nothing(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """NOP: passes its input on."""
    return bool(inputs[-1]) if inputs else False


def _edge(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """CJP/CALLP's edge: on in the execution its input went on (the CJ/CALL after it reads it)."""
    return rising(state, bool(inputs[-1]))


def _loop_next(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple
               ) -> bool:
    """NEXT of FOR n: on while another run of the loop is due (its count read at the first)."""
    left = state.get("left", 0)
    left = (value(ctx.memory, params[0]) if left <= 0 else left) - 1
    state["left"] = max(left, 0)
    return left > 0


for _name in FAMILIES["delta_blocks"]:
    if ACTIONS[_name] == "nothing":
        function(_name)(_nothing)
    elif ACTIONS[_name] == "loop-next":
        function(_name)(_loop_next)
    elif ACTIONS[_name] == "edge":
        function(_name)(_edge)
