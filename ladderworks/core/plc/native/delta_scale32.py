"""Delta DVP's DSCLP (and DSCLPP) as native code (core/plc/functions/delta_math.py's
`_scale_table`, 32-bit): D = (S - T+2) x (T+4 - T+6) / (T - T+2) + T+6 toward zero; T = T+2,
a table past its area or a result outside 32 bits: the operation error, D kept. Each
difference of two 32-bit values is below 2^32 in magnitude, so the product's magnitude is below
2^64: it is computed unsigned in 64 bits and divided by the span's magnitude (`udiv`, as
Python's abs(a) // abs(b)), the sign applied after, as `toward_zero` does."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.functions.delta_blocks import word_after
from ladderworks.core.plc.functions.dvp_data import M1067, M1068
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.delta_logic import checked, error, outside, reader, rows, writer
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import Prepare, _place, _row

Body = Callable[[FunctionText], None]
_FAR = 1 << 33  # a quotient above it is out of 32 bits whatever T+6 is


def _magnitude(f: FunctionText, value: str) -> str:
    """|value| of an i64 (never -2^63 here)."""
    negative = f.value(f"icmp slt i64 {value}, 0")
    return f.value(f"select i1 {negative}, i64 {f.value(f'sub i64 0, {value}')}, i64 {value}")


def _scale_table(params: Sequence[object]) -> Body:
    source, table, output = params
    places = [word_after(table, 2 * k) for k in range(4)]
    if any(place is None for place in places):
        return error
    read = reader(source, True)
    top, bottom, high, low = (reader(place, True) for place in places)
    store = writer(output, True)
    _place(M1067, 1), _place(M1068, 1)

    def body(f: FunctionText) -> None:
        t, b, h, lo = top(f), bottom(f), high(f), low(f)
        span = f.value(f"sub i64 {t}, {b}")

        def run() -> None:
            moved = f.value(f"sub i64 {read(f)}, {b}")
            scale = f.value(f"sub i64 {h}, {lo}")
            product = f.value(f"mul i64 {_magnitude(f, moved)}, {_magnitude(f, scale)}")
            quotient = f.value(f"udiv i64 {product}, {_magnitude(f, span)}")
            signs = (f.value(f"icmp slt i64 {v}, 0") for v in (moved, scale, span))
            negative = f.value(f"xor i1 {f.value(f'xor i1 {next(signs)}, {next(signs)}')}, "
                               f"{next(signs)}")
            far = f.value(f"icmp ugt i64 {quotient}, {_FAR}")
            signed = f.value(f"select i1 {negative}, i64 {f.value(f'sub i64 0, {quotient}')}, "
                             f"i64 {quotient}")
            exact = f.value(f"add i64 {signed}, {lo}")
            bad = f.value(f"or i1 {far}, {outside(f, exact, -(1 << 31), (1 << 31) - 1)}")
            checked(f, bad, lambda: store(f, exact))

        checked(f, f.value(f"icmp eq i64 {span}, 0"), run)

    return body


PREPARE: dict[str, Prepare] = {"scale-table32": _scale_table}
EMITTERS: dict[FunctionImpl, Emitter] = {impl: _row(p) for impl, p in rows(PREPARE, False).items()}
PULSES = rows(PREPARE, True)
