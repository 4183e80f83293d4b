"""S7-1200's CONVERT as native code (core/plc/functions/s7_math.py, `convert`): from an
integer type to any (wrapped, W1 = it fits; to Real/LReal one rounding, as Python's `float`
then `struct.pack`) and from Real to any: not finite → nothing written, W1 = 0; to an integer
`round` (half to even: |x| < 2**52 rounded by adding and taking away 2**52, larger ones are
whole), its low bytes written (a Real of 2**63 or more is a multiple of 2**40: 0); to Real
the bits (a signalling NaN made quiet, as s7_values.MOVE); to LReal the Real widened (the
same instruction as C's float → double in Python's struct). A constant is converted now, by
Python. From LReal: s7_real.py (its emitter delegates the rest here)."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.s7_values import (
    VT,
    Emitter,
    big_endian,
    double,
    fits_type,
    float_bits,
    load,
    read_int,
    readable,
    set_bit,
    signed,
    value_type,
    writable,
    write_float_bits,
    write_int,
)
from ladderworks.core.plc.native.state_block import Block

_TWO52, _TWO63 = double(2.0 ** 52), double(2.0 ** 63)


def from_integer(f: FunctionText, value: str, target: VT, out: object) -> str:
    """Write i64 `value` converted to `target`; W1 (i1)."""
    if target in typed.FLOATS:
        kind = "double" if target is VT.LREAL else "float"
        number = f.value(f"sitofp i64 {value} to {kind}")
        bits = "i64" if target is VT.LREAL else "i32"
        write_float_bits(f, out, target, f.value(f"bitcast {kind} {number} to {bits}"))
        return "true"
    write_int(f, out, target, value)
    return fits_type(f, value, target)


def constant(f: FunctionText, value: float, target: VT, out: object) -> str:
    """A Real constant converted now (Python's own steps); W1 (i1)."""
    if target in typed.FLOATS:
        raw = typed.lreal_bits(value) if target is VT.LREAL else \
            typed.real_bits(value) & 0xFFFFFFFF
        write_float_bits(f, out, target, str(signed(raw, typed.WIDTH[target])))
        return "true" if typed.fits(value, target) else "false"
    if value != value or value in (float("inf"), float("-inf")):
        return "false"
    whole = round(value)
    if isinstance(out, Address) and out.bit is not None:
        set_bit(f, out, "true" if whole else "false")
    elif isinstance(out, Address):
        write_int(f, out, target, str(typed.wrap(whole, target)))
    return "true" if typed.fits(whole, target) else "false"


def _from_real(f: FunctionText, source: Address, target: VT, out: object) -> str:
    """Convert the Real at `source` (a byte address) to `target`; W1 (i1)."""
    raw = load(f, source, 4)
    finite = f.value(f"icmp ne i32 {f.value(f'and i32 {raw}, 2139095040')}, 2139095040")
    wide = f.value(f"fpext float {f.value(f'bitcast i32 {raw} to float')} to double")
    if target is VT.REAL:
        write_float_bits(f, out, target, float_bits(f, source, target))
        return finite
    if target is VT.LREAL:
        write_float_bits(f, out, target, f.value(f"bitcast double {wide} to i64"))
        return finite
    start = f.block
    write, done = f.label(), f.label()
    f.add(f"br i1 {finite}, label %{write}, label %{done}")
    f.start(write)
    negative = f.value(f"fcmp olt double {wide}, 0.0")
    size = f.value(f"select i1 {negative}, double {f.value(f'fneg double {wide}')}, "
                   f"double {wide}")
    shifted = f.value(f"fsub double {f.value(f'fadd double {size}, {_TWO52}')}, {_TWO52}")
    whole = f.value(f"select i1 {f.value(f'fcmp oge double {size}, {_TWO52}')}, double {size},"
                    f" double {shifted}")
    rounded = f.value(f"select i1 {negative}, double {f.value(f'fneg double {whole}')}, "
                      f"double {whole}")
    if isinstance(out, Address) and out.bit is not None:
        set_bit(f, out, f.value(f"fcmp une double {rounded}, 0.0"))
    elif isinstance(out, Address):
        small = f.value(f"fcmp olt double {whole}, {_TWO63}")
        integer = f.value(f"fptosi double {rounded} to i64")
        write_int(f, out, target, f.value(f"select i1 {small}, i64 {integer}, i64 0"))
    low, high = typed.limits(target)
    fits = f.value(f"and i1 {f.value(f'fcmp oge double {rounded}, {double(low)}')}, "
                   f"{f.value(f'fcmp ole double {rounded}, {double(high)}')}")
    converted = f.block
    f.add(f"br label %{done}")
    f.start(done)
    return f.value(f"phi i1 [false, %{start}], [{fits}, %{converted}]")


def convert(b: Block, impl: FunctionImpl, params: Sequence[object],
            inputs: list[str]) -> str | None:
    """CONVERT: OUT (type `to`) := IN (type `type`) while EN."""
    if len(params) != 4:
        return None
    source, target = value_type(params[0]), value_type(params[1])
    operand, out = params[2], params[3]
    if source is None or target is None or source is VT.LREAL or not big_endian(b) or \
            not readable(operand, source) or not writable(out, target):
        return None
    f = b.f
    start = f.block
    _, after = f.branch(inputs[0])
    if source is not VT.REAL or (isinstance(operand, Address) and operand.bit is not None):
        ok = from_integer(f, read_int(f, operand, source), target, out)  # a bit: 0 or 1
    elif isinstance(operand, Address):
        ok = _from_real(f, operand, target, out)
    else:
        assert isinstance(operand, int)
        ok = constant(f, typed.bits_real(operand), target, out)
    ran = f.block
    f.join(after)
    w1 = f.value(f"phi i1 [false, %{start}], [{ok}, %{ran}]")
    return f.value(f"zext i1 {w1} to i8")


load_all()
STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {REGISTRY["S7.CONVERT"]: ("s7", convert)}
"""S7's CONVERT: implementation -> (kind, emitter)."""
