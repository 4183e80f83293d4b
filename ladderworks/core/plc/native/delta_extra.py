"""Delta DVP's remaining small rows as native code: NOP/WDT, the shown-only rows (a box
passes its input on, an LD/AND contact never conducts: compiler/implementations.py), a step's
SET/OUT Sn, BOUT/DBOUT, CJP/CALLP's edge (its input kept as "prev" in a state block), SCAL,
SCLP (16-bit), SQR/DSQR (an exact integer square root, digit by digit), SMOV, FROM/TO,
SFWR/SFRD (SFWR's place found at run time) and NEXT (its runs left in a state block), with
their pulse forms, made as delta_logic.py makes its rows."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from itertools import pairwise

from ladderworks.core.address import Address
from ladderworks.core.compiler import implementations
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.dialects.delta.rows_extra import ACTIONS
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.delta_blocks import device_at, word_after
from ladderworks.core.plc.functions.delta_modules import register_of
from ladderworks.core.plc.functions.delta_words import _places
from ladderworks.core.plc.functions.dvp_data import M1020, M1022, M1067, M1068, width_of
from ladderworks.core.plc.native import words
from ladderworks.core.plc.native.builtins import Emitter, _load, _store
from ladderworks.core.plc.native.delta_logic import (
    checked,
    error,
    outside,
    reader,
    rows,
    writer,
)
from ladderworks.core.plc.native.delta_timers import StatefulEmitter, _rising
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import CHANGED, ELAPSED, HAS_LEFT, MORE, Block
from ladderworks.core.plc.native.words import Prepare, _bit, _place, _Refused, _row, _write

Body = Callable[[FunctionText], None]
_REFUSED = (_Refused, ValueError, TypeError, KeyError)
_MOST = 512  # SFRD's words at most


def _passes(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """NOP, WDT, a shown-only box: W1 = the input (none: off)."""
    return inputs[-1] if inputs else "0"


def _never(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """A shown-only LD/AND contact (or a box with a W1 of its own): never on."""
    return "0"


def _step(params: Sequence[object]) -> Body:
    """SET / OUT Sm in a step: Sm on, the step's own S off (when not the same)."""
    step, source = params
    on = _place(step, 1)
    off = None if step == source else _place(source, 1)

    def body(f: FunctionText) -> None:
        _bit(f, on, "true")
        if off is not None:
            _bit(f, off, "false")

    return body


def _constant(operand: object) -> int:
    if isinstance(operand, bool) or not isinstance(operand, int):
        raise _Refused
    return operand


def _scale(params: Sequence[object]) -> Body:
    """SCAL S1 S2 S3 D: S1 x S2 / 1000 (toward zero) + S3; outside 16 bits: the error."""
    source, slope, offset, output = params
    first, second, third = reader(source, False), reader(slope, False), reader(offset, False)
    store = writer(output, False)

    def body(f: FunctionText) -> None:
        product = f.value(f"mul i64 {first(f)}, {second(f)}")
        exact = f.value(f"add i64 {f.value(f'sdiv i64 {product}, 1000')}, {third(f)}")
        checked(f, outside(f, exact, -32768, 32767), lambda: store(f, exact))

    return body


def _scale_table(params: Sequence[object]) -> Body:
    """SCLP S T D (16-bit): (S - T+1) x (T+2 - T+3) / (T - T+1) + T+3 toward zero; T = T+1
    or a result outside 16 bits: the error. A 32-bit word read (the product could pass 64
    bits) calls back."""
    source, table, output = params
    places = [word_after(table, k) for k in range(4)]
    if any(place is None for place in places):
        return error
    for place in (source, *places):
        if not isinstance(place, int) and width_of(place) != 2:
            raise _Refused
    read = reader(source, False)
    top, bottom, high, low = (reader(place, False) for place in places)
    store = writer(output, False)

    def body(f: FunctionText) -> None:
        t, b, h, lo = top(f), bottom(f), high(f), low(f)
        span = f.value(f"sub i64 {t}, {b}")
        zero = f.value(f"icmp eq i64 {span}, 0")

        def run() -> None:
            safe = f.value(f"select i1 {zero}, i64 1, i64 {span}")
            product = f.value(f"mul i64 {f.value(f'sub i64 {read(f)}, {b}')}, "
                              f"{f.value(f'sub i64 {h}, {lo}')}")
            exact = f.value(f"add i64 {f.value(f'sdiv i64 {product}, {safe}')}, {lo}")
            checked(f, outside(f, exact, -32768, 32767), lambda: store(f, exact))

        checked(f, zero, run)

    return body


def _isqrt(f: FunctionText, number: str) -> str:
    """The integer square root of `number` (i64, 0 <= number < 2^62), digit by digit."""
    rest, root = number, "0"
    for shift in range(60, -1, -2):
        bit = 1 << shift
        trial = f.value(f"add i64 {root}, {bit}")
        fits = f.value(f"icmp sge i64 {rest}, {trial}")
        rest = f.value(f"select i1 {fits}, i64 {f.value(f'sub i64 {rest}, {trial}')}, "
                       f"i64 {rest}")
        halved = f.value(f"lshr i64 {root}, 1")
        root = f.value(f"select i1 {fits}, i64 {f.value(f'add i64 {halved}, {bit}')}, "
                       f"i64 {halved}")
    return root


def _root(wide: bool) -> Prepare:
    """SQR / DSQR S D: isqrt(S); S < 0: the error; M1020 when the root is 0."""
    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = reader(source, wide), writer(output, wide)
        _place(M1020, 1)

        def body(f: FunctionText) -> None:
            number = read(f)

            def run() -> None:
                root = _isqrt(f, number)
                store(f, root)
                _bit(f, M1020, f.value(f"icmp eq i64 {root}, 0"))

            checked(f, f.value(f"icmp slt i64 {number}, 0"), run)

        return body

    return prepare


def _digits(f: FunctionText, number: str) -> list[str]:
    """The 4 decimal digits of 0 <= number <= 9999, lowest first."""
    found, rest = [], number
    for _ in range(4):
        found.append(f.value(f"urem i64 {rest}, 10"))
        rest = f.value(f"udiv i64 {rest}, 10")
    return found


def _digit_move(params: Sequence[object]) -> Body:
    """SMOV S m1 m2 D n: the m2 digits of S from digit m1 down into D from digit n down."""
    source, first, digits, output, to = params
    m1, m2, n = _constant(first), _constant(digits), _constant(to)
    read, current = reader(source, False), reader(output, False)
    place = _place(output, 2)
    if not (1 <= m2 <= m1 <= 4 and m2 <= n <= 4):
        return error

    def body(f: FunctionText) -> None:
        moved, kept = read(f), current(f)
        bad = f.value(f"or i1 {outside(f, moved, 0, 9999)}, {outside(f, kept, 0, 9999)}")

        def run() -> None:
            taken, result = _digits(f, moved), _digits(f, kept)
            for k in range(m2):
                result[n - 1 - k] = taken[m1 - 1 - k]
            number = "0"
            for k, digit in enumerate(result):
                number = f.value(f"add i64 {number}, {f.value(f'mul i64 {digit}, {10 ** k}')}")
            _write(f, place, number, 2)

        checked(f, bad, run)

    return body


def _register(place: Address, width: int) -> Callable[[FunctionText], str]:
    """A CR read as `delta_modules` reads it: 2 bytes unsigned, 4 signed."""
    kind = "sext" if width == 4 else "zext"
    return lambda f: f.value(f"{kind} i{8 * width} {_load(f, place, width)} to i64")


def _to_register(place: Address, width: int) -> Callable[[FunctionText, str], None]:
    return lambda f, value: _write(f, place, value, width)


def _transfer(wide: bool, reading: bool) -> Prepare:
    """FROM / TO m1 m2 D n (constants): n words (DFROM/DTO: pairs) between module m1's CRs
    and D.., as `delta_modules._transfer` finds them (a CR past #99: the error after the
    words before it; FROM stops at the last D; TO reads S itself past its last)."""
    def prepare(params: Sequence[object]) -> Body:
        module, first, data, count = params
        m1, m2, n = _constant(module), _constant(first), _constant(count)
        step, width, failed = (2, 4, False) if wide else (1, 2, False)
        moves: list[tuple[Callable[[FunctionText], str], Callable[[FunctionText, str], None]]] = []
        if n > 512:
            raise _Refused
        for k in range(max(n, 0)):
            place = register_of(m1, m2 + k * step)
            if place is None or (wide and register_of(m1, m2 + k * step + 1) is None):
                failed = True
                break
            device = word_after(data, k * step) if isinstance(data, Address) else None
            register = _place(place, width)
            if reading:
                if device is None:
                    break
                moves.append((_register(register, width), writer(device, wide)))
            else:
                source = device if device is not None else data
                moves.append((reader(source, wide), _to_register(register, width)))

        def body(f: FunctionText) -> None:
            for read, write in moves:
                write(f, read(f))
            if failed:
                error(f)

        return body

    return prepare


def _bit_out(wide: bool) -> Emitter:
    """BOUT / DBOUT D n: bit n of D follows the input (n out of range: the error)."""
    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(params) != 2 or not inputs:
            return None
        output, which = params
        try:
            read, store = reader(output, wide), writer(output, wide)
            count = reader(which, False)
        except _REFUSED:
            return None
        n = count(f)
        on = f.truth(inputs[-1])

        def run() -> None:
            mask = f.value(f"shl i64 1, {n}")
            word = read(f)
            set_ = f.value(f"or i64 {word}, {mask}")
            cleared = f.value(f"and i64 {word}, {f.value(f'xor i64 {mask}, -1')}")
            store(f, f.value(f"select i1 {on}, i64 {set_}, i64 {cleared}"))

        checked(f, outside(f, n, 0, 31 if wide else 15), run)
        return inputs[-1]

    return emit


def _edge(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """CJP / CALLP's edge: on in the execution its input went on."""
    if not inputs:
        return None
    return b.f.value(f"zext i1 {_rising(b, b.f.truth(inputs[-1]))} to i8")


def _loop_next(b: Block, impl: FunctionImpl, params: Sequence[object],
               inputs: list[str]) -> str | None:
    """NEXT of FOR n: the runs left ("left"; none left: n read again) less one; W1 while
    another run is due."""
    if len(params) != 1:
        return None
    try:
        count = words._source(params[0])
    except _REFUSED:
        return None
    f = b.f
    flags = b.flags()
    more = b.more(flags)
    has_left = f.value(f"icmp ne i32 {f.value(f'and i32 {more}, {HAS_LEFT}')}, 0")
    left = f.value(f"select i1 {has_left}, i64 {b.load64(ELAPSED)}, i64 0")
    again = f.value(f"select i1 {f.value(f'icmp sle i64 {left}, 0')}, i64 {count(f)}, "
                    f"i64 {left}")
    now = f.value(f"sub i64 {again}, 1")
    due = f.value(f"icmp sgt i64 {now}, 0")
    kept = f.value(f"select i1 {due}, i64 {now}, i64 0")
    b.store64(ELAPSED, kept)
    moved = f.value(f"select i1 {f.value(f'icmp ne i64 {kept}, {left}')}, i32 {CHANGED}, "
                    f"i32 0")
    changed = b.set_more(more, f.value(f"or i32 {more}, {HAS_LEFT}"))
    b.set_flags(flags, f.value(f"or i32 {f.value(f'or i32 {flags}, {MORE}')}, "
                               f"{f.value(f'or i32 {changed}, {moved}')}"))
    return f.value(f"zext i1 {due} to i8")


def _runs(letter: str) -> tuple[tuple[int, int, Address, int], ...]:
    """Where `word_after` finds the words of device letter `letter`: each range of its
    numbers (first, last, the first's address, the stride), as DeviceMap.word places them."""
    return tuple((device.first, device.last, device.word_address(device.first), device.stride)
                 for device in DEVICES.by_letter.get(letter, ()) if device.words is not None)


def _fifo_write(params: Sequence[object]) -> Body:
    """SFWR S D n: below n - 1 words written (the count in D), S into D + count + 1 (a place
    found at run time among `_runs`; none: the error) and the count up; M1022 when full."""
    source, output, count = params
    n = _constant(count)
    read, written_of = reader(source, False), reader(output, False)
    place = _place(output, 2)
    found = device_at(place)
    if found is None:
        raise _Refused
    device, number = found
    if width_of(place) != 2:  # a 32-bit count: places beyond any table
        raise _Refused
    runs = _runs(device.letter)
    for first, last, at, stride in runs:
        _place(at, stride * (last - first) + 2)
    _place(M1022, 1), _place(M1067, 1), _place(M1068, 1)

    def body(f: FunctionText) -> None:
        written = written_of(f)
        full, room, after = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.value(f'icmp sge i64 {written}, {n - 1}')}, label %{full}, "
              f"label %{room}")
        f.start(full)
        _bit(f, M1022, "true")
        f.add(f"br label %{after}")
        f.start(room)
        step = f.value(f"add i64 {written}, 1")
        k = f.value(f"add i64 {step}, {number}")
        target, inside = "null", "false"
        for first, last, at, stride in reversed(runs):  # the first range wins, as in split
            here = f.value(f"and i1 {f.value(f'icmp sge i64 {k}, {first}')}, "
                           f"{f.value(f'icmp sle i64 {k}, {last}')}")
            offset = f.value(f"add i64 {f.value(f'mul i64 {k}, {stride}')}, "
                             f"{at.byte - stride * first}")
            pointer = f.value(f"getelementptr i8, ptr {f.byte_ptr(at.area, 0)}, i64 {offset}")
            target = f.value(f"select i1 {here}, ptr {pointer}, ptr {target}")
            inside = f.value(f"or i1 {inside}, {here}")

        def write() -> None:
            f.add(f"store i16 {f.value(f'trunc i64 {read(f)} to i16')}, ptr {target}, "
                  f"align 1")
            _write(f, place, step, 2)
            _bit(f, M1022, f.value(f"icmp sge i64 {step}, {n - 1}"))

        checked(f, f.value(f"xor i1 {inside}, true"), write)
        f.join(after)

    return body


def _fifo_read(params: Sequence[object]) -> Body:
    """SFRD S D n: above 0 held (the count in S), S + 1 into D, S + 2 .. S + n - 1 down one
    word and the count down (M1020 when 0); at 0 or below only M1020."""
    source, output, count = params
    n = _constant(count)
    if not 2 <= n <= _MOST:
        raise _Refused
    held_of, target = reader(source, False), _place(output, 2)
    counter = _place(source, 2)
    found = _places(counter, n)
    places = None if found is None else [_place(place, 2) for place in found]
    _place(M1020, 1), _place(M1067, 1), _place(M1068, 1)

    def body(f: FunctionText) -> None:
        held = held_of(f)
        empty, some, after = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.value(f'icmp sle i64 {held}, 0')}, label %{empty}, label %{some}")
        f.start(empty)
        _bit(f, M1020, "true")
        f.add(f"br label %{after}")
        f.start(some)
        if places is None:
            error(f)
        else:
            _store(f, target, 2, _load(f, places[1], 2))
            for lower, upper in pairwise(places[1:]):
                _store(f, lower, 2, _load(f, upper, 2))
            left = f.value(f"sub i64 {held}, 1")
            _write(f, counter, left, 2)
            _bit(f, M1020, f.value(f"icmp eq i64 {left}, 0"))
        f.join(after)

    return body


PREPARE: dict[str, Prepare] = {
    "step-set": _step, "step-out": _step, "scale": _scale, "scale-table": _scale_table,
    "root": _root(False), "root32": _root(True), "digit-move": _digit_move,
    "from": _transfer(False, True), "from32": _transfer(True, True),
    "to": _transfer(False, False), "to32": _transfer(True, False),
    "fifo-write": _fifo_write, "fifo-read": _fifo_read}


def _own() -> tuple[dict[FunctionImpl, Emitter],
                    dict[FunctionImpl, tuple[str, StatefulEmitter]]]:
    """The rows taken by their action: NOP/WDT, BOUT/DBOUT, CJP/CALLP."""
    load_all()
    emitters: dict[FunctionImpl, Emitter] = {}
    edges: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {}
    for name, action in ACTIONS.items():
        impl = REGISTRY.get(name)
        if impl is None:
            continue
        if action == "nothing":
            emitters[impl] = _passes
        elif action in ("bit-out", "bit-out32"):
            emitters[impl] = _bit_out(action.endswith("32"))
        elif action == "edge":
            edges[impl] = ("dvp edge", _edge)
        elif action == "loop-next":
            edges[impl] = ("dvp next", _loop_next)
    return emitters, edges


_EMITTERS, _EDGES = _own()
EMITTERS: dict[FunctionImpl, Emitter] = {
    **{impl: _row(p) for impl, p in rows(PREPARE, False).items()}, **_EMITTERS,
    implementations.passes_input: _passes, implementations.never_conducts: _never}
PULSES = rows(PREPARE, True)
STATEFUL = _EDGES
