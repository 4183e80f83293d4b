"""Delta DVP's blocks of words and bits as native code (core/plc/functions/delta_blocks.py,
delta_words.py, delta_math.py's MEAN): ZRST, BMOV, FMOV/DFMOV, XCH/DXCH, SFTR/SFTL,
WSFR/WSFL, DECO, ENCO, ALT, SUM/DSUM and MEAN/DMEAN, with their pulse forms. Their devices are
found when the IR is made (the Python functions' own lists: `word_after`, `bit_range`), so a
count must be a constant (K n) and the block at most `MOST` words (ZRST: 8 x `MOST` bits):
otherwise, and where a 32-bit output would run past its area, the op calls back. What the
Python code finds wrong when it runs (a count out of range, devices past the last of their
letter) is the operation error, emitted as such."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.functions.delta_blocks import _words, bit_range, device_at
from ladderworks.core.plc.functions.delta_words import _places
from ladderworks.core.plc.functions.delta_words32 import width32
from ladderworks.core.plc.functions.dvp_data import M1020
from ladderworks.core.plc.native.builtins import Emitter, _load, _store
from ladderworks.core.plc.native.delta_logic import error, reader, rows, writer
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import Prepare, _bit, _place, _Refused, _row, _write

Body = Callable[[FunctionText], None]
MOST = 512  # devices in a block at most (each is a load or store of its own)


def _constant(operand: object, low: int = -(1 << 31), high: int = (1 << 31) - 1) -> int:
    """A count operand that is a constant (K n); else refused."""
    if isinstance(operand, bool) or not isinstance(operand, int) or not low <= operand <= high:
        raise _Refused
    return operand


def _failed(f: FunctionText) -> None:
    error(f)


def _bit_masks(places: Sequence[Address]) -> dict[Address, int]:
    """The bits of `places` by byte (each checked now: before any IR is emitted)."""
    masks: dict[Address, int] = {}
    for place in places:
        if place.bit is None:
            raise _Refused
        byte = Address(_place(place, 1).area, place.byte)
        masks[byte] = masks.get(byte, 0) | 1 << place.bit
    return masks


def _clear_bits(f: FunctionText, masks: dict[Address, int]) -> None:
    """`set_bit(place, False)` for each place (`_bit_masks`), one `and` a byte."""
    for address, mask in masks.items():
        _store(f, address, 1, f.value(f"and i8 {_load(f, address, 1)}, {~mask & 0xFF}"))


def _zone_reset(params: Sequence[object]) -> Body:
    """ZRST D1 D2: bits off, or words 0 (a T/C contact off too); different letters: error."""
    first, last = params
    if not isinstance(first, Address) or not isinstance(last, Address):
        raise _Refused
    one, two = device_at(first), device_at(last)
    if one is None or two is None or one[0].letter != two[0].letter \
            or (first.bit is None and last.bit is not None):
        return _failed
    count = max(two[1] - one[1], 0) + 1
    if count > (8 * MOST if first.bit is not None else MOST):  # bits: one `and` a byte
        raise _Refused
    if first.bit is not None:
        bits = _bit_masks(bit_range(first, count) or ())
        return lambda f: _clear_bits(f, bits)
    stores: list[tuple[Address, int]] = []
    contacts: list[Address] = []
    for place in _words(first, count):
        found = device_at(place)
        if found is None:
            continue
        device, number = found
        stores.append((_place(place, device.width(number)), device.width(number)))
        if device.bits is not None:
            contacts.append(device.bit_address(number))
    if any(width not in (1, 2, 4, 8) for _place_at, width in stores):
        raise _Refused
    masks = _bit_masks(contacts)

    def body(f: FunctionText) -> None:
        for place, width in stores:
            _store(f, place, width, "0")
        _clear_bits(f, masks)

    return body


def _block_move(params: Sequence[object]) -> Body:
    """BMOV S D n: n words copied as through a buffer."""
    source, output, count = params
    n = _constant(count)
    if not isinstance(source, Address) or n <= 0:
        return lambda f: None
    if n > MOST or not isinstance(output, Address):
        raise _Refused
    sources = [_place(place, 2) for place in _words(source, n)]
    targets = [_place(place, 2) for place in _words(output, len(sources))]

    def body(f: FunctionText) -> None:
        data = [_load(f, place, 2) for place in sources]
        for place, word in zip(targets, data, strict=False):
            _store(f, place, 2, word)

    return body


def _fill(wide: bool) -> Prepare:
    """FMOV S D n: S into n words; DFMOV: into n pairs (each past its area: refused)."""
    def prepare(params: Sequence[object]) -> Body:
        source, output, count = params
        n = _constant(count)
        if n > MOST or not isinstance(output, Address):
            raise _Refused
        read = reader(source, wide)
        stores = [writer(place, wide) for place in _words(output, n, 2 if wide else 1)]

        def body(f: FunctionText) -> None:
            number = read(f)
            for store in stores:
                store(f, number)

        return body

    return prepare


def _exchange(params: Sequence[object]) -> Body:
    one, two = (_place(place, 2) for place in params)

    def body(f: FunctionText) -> None:
        a, b = _load(f, one, 2), _load(f, two, 2)
        _store(f, one, 2, b)
        _store(f, two, 2, a)

    return body


def _exchange32(params: Sequence[object]) -> Body:
    one, two = params
    read_one, read_two = reader(one, True), reader(two, True)
    write_one, write_two = writer(one, True), writer(two, True)

    def body(f: FunctionText) -> None:
        a, b = read_one(f), read_two(f)
        write_one(f, b)
        write_two(f, a)

    return body


def _bit_shift(right: bool) -> Prepare:
    """SFTR / SFTL S D n1 n2: the n1 bits from D moved by n2, the freed ones from S."""
    def prepare(params: Sequence[object]) -> Body:
        source, output, bits, shift = params
        n1, n2 = _constant(bits), _constant(shift)
        if not 0 < n2 <= n1:
            return _failed
        if n1 > MOST or not isinstance(output, Address) or not isinstance(source, Address):
            raise _Refused
        targets, sources = bit_range(output, n1), bit_range(source, n2)
        if targets is None or sources is None:
            return _failed
        for place in (*targets, *sources):
            _place(place, 1)

        def body(f: FunctionText) -> None:
            old = [f.bit(p.area, p.byte, p.bit or 0, False) for p in targets]
            new = [f.bit(p.area, p.byte, p.bit or 0, False) for p in sources]
            shifted = old[n2:] + new if right else new + old[:n1 - n2]
            for place, on in zip(targets, shifted, strict=True):
                _bit(f, place, f.truth(on))

        return body

    return prepare


def _word_shift(right: bool) -> Prepare:
    """WSFR / WSFL S D n1 n2: the n1 words from D moved by n2, the freed ones from S."""
    def prepare(params: Sequence[object]) -> Body:
        source, output, words, shift = params
        n1, n2 = _constant(words), _constant(shift)
        if not 0 < n2 <= n1:
            return _failed
        if n1 > MOST or not isinstance(output, Address):
            raise _Refused
        found = _places(output, n1)
        if found is None:
            return _failed
        targets = [_place(place, 2) for place in found]
        sources: list[Address] = []
        if isinstance(source, Address):
            found = _places(source, n2)
            if found is None:
                return _failed
            sources = [_place(place, 2) for place in found]
        else:
            _constant(source)

        def body(f: FunctionText) -> None:
            old = [_load(f, place, 2) for place in targets]
            if isinstance(source, Address):
                new = [_load(f, place, 2) for place in sources]
            else:
                new = [f.value(f"trunc i64 {source} to i16")] * n2
            moved = old[n2:] + new if right else new + old[:n1 - n2]
            for place, word in zip(targets, moved, strict=True):
                _store(f, place, 2, word)

        return body

    return prepare


def _decode(params: Sequence[object]) -> Body:
    """DECO S D n: the low n bits of S pick the one bit of 2^n (of word D) turned on."""
    source, output, bits = params
    n = _constant(bits)
    if not isinstance(output, Address):
        raise _Refused
    word = output.bit is None
    if not 1 <= n <= (4 if word else 8):
        return _failed
    read = reader(source, False)
    if word:
        place = _place(output, 2)
        return lambda f: _write(f, place, f.value(
            f"shl i64 1, {f.value(f'and i64 {read(f)}, {(1 << n) - 1}')}"), 2)
    places = bit_range(output, 1 << n)
    if places is None:
        return _failed
    for place in places:
        _place(place, 1)

    def body(f: FunctionText) -> None:
        which = f.value(f"and i64 {read(f)}, {(1 << n) - 1}")
        for k, place in enumerate(places):
            _bit(f, place, f.value(f"icmp eq i64 {which}, {k}"))

    return body


def _encode(params: Sequence[object]) -> Body:
    """ENCO S D n: the number of the highest bit on of S's 2^n; none on: the error."""
    source, output, bits = params
    n = _constant(bits)
    if not isinstance(source, Address):
        raise _Refused
    word = source.bit is None
    if not 1 <= n <= (4 if word else 8):
        return _failed
    target = _place(output, 2)
    places = None if word else bit_range(source, 1 << n)
    if not word and places is None:
        return _failed
    if word:
        _place(source, 2)
    else:
        for place in places or ():
            _place(place, 1)

    def body(f: FunctionText) -> None:
        if word:
            raw = _load(f, source, 2)
            states = [f.value(f"trunc i16 {f.value(f'lshr i16 {raw}, {k}')} to i1")
                      for k in range(1 << n)]
        else:
            states = [f.truth(f.bit(p.area, p.byte, p.bit or 0, False)) for p in places or ()]
        found, highest = "false", "0"
        for k, on in enumerate(states):
            found = f.value(f"or i1 {found}, {on}")
            highest = f.value(f"select i1 {on}, i64 {k}, i64 {highest}")
        none = f.value(f"xor i1 {found}, true")
        wrong, good, after = f.label(), f.label(), f.label()
        f.add(f"br i1 {none}, label %{wrong}, label %{good}")
        f.start(wrong)
        error(f)
        f.add(f"br label %{after}")
        f.start(good)
        _write(f, target, highest, 2)
        f.join(after)

    return body


def _alternate(params: Sequence[object]) -> Body:
    (output,) = params
    place = _place(output, 1)
    if place.bit is None:
        raise _Refused
    return lambda f: _bit(f, place, f.value(
        f"xor i1 {f.truth(f.bit(place.area, place.byte, place.bit or 0, False))}, true"))


def _ones(f: FunctionText, value: str) -> str:
    """The bits on in the i64 `value` (no more than 32 bits of it on)."""
    def op(text: str) -> str:
        return f.value(text)

    halves = op(f"and i64 {op(f'lshr i64 {value}, 1')}, {0x5555555555555555}")
    x = op(f"sub i64 {value}, {halves}")
    quarters = op(f"and i64 {op(f'lshr i64 {x}, 2')}, {0x3333333333333333}")
    x = op(f"add i64 {op(f'and i64 {x}, {0x3333333333333333}')}, {quarters}")
    nibbles = op(f"add i64 {x}, {op(f'lshr i64 {x}, 4')}")
    x = op(f"and i64 {nibbles}, {0x0F0F0F0F0F0F0F0F}")
    return op(f"lshr i64 {op(f'mul i64 {x}, {0x0101010101010101}')}, 56")


def _sum(wide: bool) -> Prepare:
    """SUM S D: the bits on in S (16; DSUM 32) into D (its own width: DSUM); M1020 when 0."""
    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read = reader(source, wide)
        if not isinstance(output, Address):
            raise _Refused
        width = width32(output) if wide else 2
        place = _place(output, width)
        _place(M1020, 1)
        mask = 0xFFFF_FFFF if wide else 0xFFFF

        def body(f: FunctionText) -> None:
            count = _ones(f, f.value(f"and i64 {read(f)}, {mask}"))
            _write(f, place, count, width)
            _bit(f, M1020, f.value(f"icmp eq i64 {count}, 0"))

        return body

    return prepare


def _mean(wide: bool) -> Prepare:
    """MEAN S D n: the mean of n words (pairs) from S toward zero (those that exist)."""
    def prepare(params: Sequence[object]) -> Body:
        source, output, count = params
        n = _constant(count)
        if not 1 <= n <= 64:
            return _failed
        store = writer(output, wide)
        if not isinstance(source, Address):
            number = str(_constant(source))
            return lambda f: store(f, number)
        found = [place for place in _words(source, n, 2 if wide else 1)]
        if not found:
            return lambda f: None
        reads = [reader(place, wide) for place in found]

        def body(f: FunctionText) -> None:
            total = "0"
            for read in reads:
                total = f.value(f"add i64 {total}, {read(f)}")
            store(f, f.value(f"sdiv i64 {total}, {len(reads)}"))

        return body

    return prepare


PREPARE: dict[str, Prepare] = {
    "zone-reset": _zone_reset, "block-move": _block_move, "fill": _fill(False),
    "fill32": _fill(True), "exchange": _exchange, "exchange32": _exchange32,
    "shift-right": _bit_shift(True), "shift-left": _bit_shift(False),
    "word-right": _word_shift(True), "word-left": _word_shift(False),
    "decode": _decode, "encode": _encode, "alternate": _alternate,
    "sum": _sum(False), "sum32": _sum(True), "mean": _mean(False), "mean32": _mean(True),
}
EMITTERS: dict[FunctionImpl, Emitter] = {impl: _row(p) for impl, p in rows(PREPARE, False).items()}
PULSES = rows(PREPARE, True)
