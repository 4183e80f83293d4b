"""Delta DVP word shifts and FIFO registers: WSFR, WSFL, SFWR, SFRD and their pulse forms.

WSFR/WSFL S D n1 n2: the n1 words from D move by n2 toward D (R) / away from it (L); the n2
words from S fill the freed end. SFWR S D n: D is the count of words written; below n - 1 it
goes up by one and S is written to D + count; at n - 1 nothing is written and M1022 (carry)
goes on. SFRD S D n: S is the count; above 0, S + 1 goes to D, S + 2 .. S + n - 1 move down one
word and the count goes down by one (M1020 when it reaches 0); at 0 nothing is read and M1020
is on. docs/dialects.md.
"""

from __future__ import annotations

from itertools import pairwise

from ladderworks.core.address import Address
from ladderworks.core.plc.functions.delta_blocks import word_after
from ladderworks.core.plc.functions.delta_words32 import operation_error, register
from ladderworks.core.plc.functions.dvp_data import M1020, M1022, value
from ladderworks.core.plc.memory import Memory


def _places(first: Address, count: int) -> list[Address] | None:
    places = []
    for k in range(count):
        place = word_after(first, k)
        if place is None:  # past the last device of its letter
            return None
        places.append(place)
    return places


def _shift(memory: Memory, params: tuple, right: bool) -> None:
    source, output, words, shift = params
    n1, n2 = value(memory, words), value(memory, shift)
    targets = _places(output, n1) if 0 < n2 <= n1 else None
    if targets is None:
        operation_error(memory)
        return
    old = [memory.read(place, 2) for place in targets]
    if isinstance(source, int):
        new = [source] * n2
    else:
        sources = _places(source, n2)
        if sources is None:
            operation_error(memory)
            return
        new = [memory.read(place, 2) for place in sources]
    moved = old[n2:] + new if right else new + old[:n1 - n2]
    for place, word in zip(targets, moved, strict=True):
        memory.write(place, word, 2)


def _word_right(memory: Memory, params: tuple) -> None:
    _shift(memory, params, True)


def _word_left(memory: Memory, params: tuple) -> None:
    _shift(memory, params, False)


def _fifo_write(memory: Memory, params: tuple) -> None:
    source, output, count = params
    n = value(memory, count)
    written = value(memory, output)
    if written >= n - 1:
        memory.set_bit(M1022, True)
        return
    place = word_after(output, written + 1)
    if place is None:
        operation_error(memory)
        return
    memory.write(place, value(memory, source), 2)
    memory.write(output, written + 1, 2)
    memory.set_bit(M1022, written + 1 >= n - 1)


def _fifo_read(memory: Memory, params: tuple) -> None:
    source, output, count = params
    n = value(memory, count)
    held = value(memory, source)
    if held <= 0:
        memory.set_bit(M1020, True)
        return
    places = _places(source, n)
    if places is None:
        operation_error(memory)
        return
    memory.write(output, memory.read(places[1], 2), 2)
    for lower, upper in pairwise(places[1:]):
        memory.write(lower, memory.read(upper, 2), 2)
    memory.write(source, held - 1, 2)
    memory.set_bit(M1020, held - 1 == 0)


register(__name__, {"word-right": _word_right, "word-left": _word_left,
                    "fifo-write": _fifo_write, "fifo-read": _fifo_read})
