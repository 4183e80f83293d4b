"""S7-1200's Real/LReal ADD/SUB/MUL/DIV and CONVERT from LReal as native code, equal to
core/plc/functions/s7_math.py bit for bit (other types: s7_values, s7_convert).

The operands are taken in double (a Real widened: exact) and the IEEE operation done there, as
Python does; NaNs never come from the hardware: a NaN operand's bits are written with the quiet
bit set (IN1's first), another NaN result is `math.nan`'s bits (selects on the operands' bits,
so neither the FPU's operand order nor LLVM's folding chooses a payload). A Real result is the
double rounded once to float (`fptrunc`: C's cast, as Python's `struct.pack`; past the largest
Real: ±infinity); W1 = the value written is finite. A bit target takes the double ≠ 0.
CONVERT from an LReal at an address: to LReal its bits; to Real as a result above; to an
integer type nothing when not finite, else `round` (half to even: |x| < 2**52 by adding and
taking away 2**52) and its low bytes (≥ 2**63: the significand shifted, from the bits).
"""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.s7_math import float_result
from ladderworks.core.plc.native import s7_convert, s7_values
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.s7_values import (
    VT,
    Emitter,
    big_endian,
    bit,
    double,
    load,
    readable,
    set_bit,
    signed,
    store,
    value_type,
    writable,
    write_int,
)
from ladderworks.core.plc.native.state_block import Block

# per type: the integer kind, the float kind, the exponent mask, the quiet bit, math.nan's bits
_REAL = ("i32", "float", 0x7F800000, 0x400000, typed.real_bits(float("nan")) & 0xFFFFFFFF)
_LREAL = ("i64", "double", 0x7FF0000000000000, 1 << 51, typed.lreal_bits(float("nan")))
_OPS = {"S7.ADD": "fadd", "S7.SUB": "fsub", "S7.MUL": "fmul", "S7.DIV": "fdiv"}
_TWO52, _TWO63 = double(2.0 ** 52), double(2.0 ** 63)


def _kind(vtype: VT) -> tuple[str, str, int, int, int]:
    return _REAL if vtype is VT.REAL else _LREAL


def _const(raw: int, vtype: VT) -> str:
    return str(signed(raw, typed.WIDTH[vtype]))


def operand_bits(f: FunctionText, operand: object, vtype: VT) -> str:
    """The bits (i32/i64) of the Real/LReal `typed.read` gives for an operand."""
    kind = _kind(vtype)[0]
    if isinstance(operand, Address) and operand.bit is None:
        return load(f, operand, typed.WIDTH[vtype])
    to_bits = typed.lreal_bits if vtype is VT.LREAL else typed.real_bits
    if isinstance(operand, Address):
        one = _const(to_bits(1.0) & ((1 << 8 * typed.WIDTH[vtype]) - 1), vtype)
        return f.value(f"select i1 {f.truth(bit(f, operand))}, {kind} {one}, {kind} 0")
    assert isinstance(operand, int)
    raw = to_bits(typed.bits_real(operand)) & ((1 << 8 * typed.WIDTH[vtype]) - 1)
    return _const(raw, vtype)


def is_nan(f: FunctionText, raw: str, vtype: VT) -> str:
    """i1: the bits are a NaN's."""
    kind, _, exponent, _, _ = _kind(vtype)
    size = f.value(f"and {kind} {raw}, {_const(exponent | (exponent - 1), vtype)}")
    return f.value(f"icmp ugt {kind} {size}, {_const(exponent, vtype)}")


def finite(f: FunctionText, raw: str, vtype: VT) -> str:
    """i1: the bits are a finite number's."""
    kind, _, exponent, _, _ = _kind(vtype)
    masked = f.value(f"and {kind} {raw}, {_const(exponent, vtype)}")
    return f.value(f"icmp ne {kind} {masked}, {_const(exponent, vtype)}")


def as_double(f: FunctionText, raw: str, vtype: VT) -> str:
    """The value of Real/LReal bits as a double (a Real widened)."""
    if vtype is VT.LREAL:
        return f.value(f"bitcast i64 {raw} to double")
    return f.value(f"fpext float {f.value(f'bitcast i32 {raw} to float')} to double")


def stored_bits(f: FunctionText, value: str, vtype: VT) -> str:
    """The bits `typed.write` stores for a double that is not a NaN (a Real: one rounding)."""
    if vtype is VT.LREAL:
        return f.value(f"bitcast double {value} to i64")
    return f.value(f"bitcast float {f.value(f'fptrunc double {value} to float')} to i32")


def nan_to_real(f: FunctionText, raw: str) -> str:
    """A double NaN's bits as C's cast to float makes them: sign, quiet, the top 22 bits."""
    sign = f.value(f"trunc i64 {f.value(f'lshr i64 {raw}, 32')} to i32")
    top = f.value(f"trunc i64 {f.value(f'lshr i64 {raw}, 29')} to i32")
    payload = f.value(f"and i32 {top}, 4194303")  # 0x3FFFFF
    high = f.value(f"and i32 {sign}, {_const(0x80000000, VT.REAL)}")
    return f.value(f"or i32 {f.value(f'or i32 {high}, {_const(0x7FC00000, VT.REAL)}')}, "
                   f"{payload}")


def write_result(f: FunctionText, target: object, vtype: VT, raw: str, value: str) -> None:
    """`typed.write` of a result: bits `raw` at a byte address, `value` (double) ≠ 0 to a bit."""
    if not isinstance(target, Address):
        return
    if target.bit is not None:
        set_bit(f, target, f.value(f"fcmp une double {value}, 0.0"))
        return
    store(f, target, typed.WIDTH[vtype], raw)


def _compute(f: FunctionText, name: str, vtype: VT, params: Sequence[object]) -> str:
    """One run of ADD … DIV on Real/LReal: the result written; W1 (i1)."""
    kind, _, _, quiet, nan = _kind(vtype)
    raws = [operand_bits(f, p, vtype) for p in params[1:3]]
    nans = [is_nan(f, raw, vtype) for raw in raws]
    first, second = (as_double(f, raw, vtype) for raw in raws)
    value = f.value(f"{_OPS[name]} double {first}, {second}")
    result = f.value(f"select i1 {f.value(f'fcmp uno double {value}, 0.0')}, {kind} "
                     f"{_const(nan, vtype)}, {kind} {stored_bits(f, value, vtype)}")
    for raw, nan_operand in reversed(list(zip(raws, nans, strict=True))):
        made_quiet = f.value(f"or {kind} {raw}, {_const(quiet, vtype)}")
        result = f.value(f"select i1 {nan_operand}, {kind} {made_quiet}, {kind} {result}")
    write_result(f, params[3], vtype, result, value)
    return finite(f, result, vtype)


def _constants(f: FunctionText, name: str, vtype: VT, params: Sequence[object]) -> str:
    """Both operands constants: Python's result now."""
    a, b = (typed.bits_real(p) for p in params[1:3] if isinstance(p, int))
    value = float_result(name, a, b)
    if vtype is VT.LREAL:
        raw = typed.lreal_bits(value)
    else:
        raw = typed.real_bits(typed.to_real(value)) & 0xFFFFFFFF
    target = params[3]
    if isinstance(target, Address) and target.bit is not None:
        set_bit(f, target, "true" if value else "false")
    elif isinstance(target, Address):
        store(f, target, typed.WIDTH[vtype], _const(raw, vtype))
    return "true" if typed.fits(value, vtype) else "false"


def _arithmetic(name: str, other: Emitter) -> Emitter:
    """ADD/SUB/MUL/DIV: Real/LReal here, other types `other` (s7_values)."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if not params:
            return None
        vtype = value_type(params[0])
        if vtype not in typed.FLOATS:
            return other(b, impl, params, inputs)
        assert vtype is not None
        if len(params) != 4 or not big_endian(b) or \
                not all(readable(p, vtype) for p in params[1:3]) or \
                not writable(params[3], vtype):
            return None
        f = b.f
        start = f.block
        _, after = f.branch(inputs[0])
        if all(isinstance(p, int) for p in params[1:3]):
            ok = _constants(f, name, vtype, params)
        else:
            ok = _compute(f, name, vtype, params)
        ran = f.block
        f.join(after)
        w1 = f.value(f"phi i1 [false, %{start}], [{ok}, %{ran}]")
        return f.value(f"zext i1 {w1} to i8")

    return emit


def _low_bits(f: FunctionText, raw: str, size: str, rounded: str) -> str:
    """i64: the low 64 bits of the whole number `rounded` (|x| = `size`, bits `raw`)."""
    small = f.value(f"fcmp olt double {size}, {_TWO63}")
    integer = f.value(f"fptosi double {rounded} to i64")
    exponent = f.value(f"and i64 {f.value(f'lshr i64 {raw}, 52')}, 2047")
    significand = f.value(f"or i64 {f.value(f'and i64 {raw}, 4503599627370495')}, "
                          f"4503599627370496")  # the 52 fraction bits and the hidden bit
    shift = f.value(f"sub i64 {exponent}, 1075")
    in_range = f.value(f"icmp ult i64 {shift}, 64")
    shifted = f.value(f"shl i64 {significand}, {f.value(f'and i64 {shift}, 63')}")
    magnitude = f.value(f"select i1 {in_range}, i64 {shifted}, i64 0")
    negative = f.value(f"icmp slt i64 {raw}, 0")
    large = f.value(f"select i1 {negative}, i64 {f.value(f'sub i64 0, {magnitude}')}, "
                    f"i64 {magnitude}")
    return f.value(f"select i1 {small}, i64 {integer}, i64 {large}")


def _to_integer(f: FunctionText, raw: str, target: VT, out: object) -> str:
    """Convert the LReal bits `raw` to an integer type; W1 (i1)."""
    start = f.block
    write, done = f.label(), f.label()
    f.add(f"br i1 {finite(f, raw, VT.LREAL)}, label %{write}, label %{done}")
    f.start(write)
    size = as_double(f, f.value(f"and i64 {raw}, 9223372036854775807"), VT.LREAL)
    shifted = f.value(f"fsub double {f.value(f'fadd double {size}, {_TWO52}')}, {_TWO52}")
    whole = f.value(f"select i1 {f.value(f'fcmp oge double {size}, {_TWO52}')}, double {size},"
                    f" double {shifted}")
    negative = f.value(f"icmp slt i64 {raw}, 0")
    rounded = f.value(f"select i1 {negative}, double {f.value(f'fneg double {whole}')}, "
                      f"double {whole}")
    if isinstance(out, Address) and out.bit is not None:
        set_bit(f, out, f.value(f"fcmp une double {rounded}, 0.0"))
    elif isinstance(out, Address):
        write_int(f, out, target, _low_bits(f, raw, whole, rounded))
    low, high = typed.limits(target)
    fits = f.value(f"and i1 {f.value(f'fcmp oge double {rounded}, {double(low)}')}, "
                   f"{f.value(f'fcmp ole double {rounded}, {double(high)}')}")
    converted = f.block
    f.add(f"br label %{done}")
    f.start(done)
    return f.value(f"phi i1 [false, %{start}], [{fits}, %{converted}]")


def _from_lreal(f: FunctionText, source: Address, target: VT, out: object) -> str:
    """Convert the LReal at `source` (a byte address) to `target`; W1 (i1)."""
    raw = load(f, source, 8)
    if target is VT.LREAL:
        write_result(f, out, target, raw, as_double(f, raw, VT.LREAL))
        return finite(f, raw, VT.LREAL)
    if target is VT.REAL:
        value = as_double(f, raw, VT.LREAL)
        bits = f.value(f"select i1 {is_nan(f, raw, VT.LREAL)}, i32 {nan_to_real(f, raw)}, "
                       f"i32 {stored_bits(f, value, VT.REAL)}")
        write_result(f, out, target, bits, value)
        return finite(f, bits, VT.REAL)
    return _to_integer(f, raw, target, out)


def convert(b: Block, impl: FunctionImpl, params: Sequence[object],
            inputs: list[str]) -> str | None:
    """CONVERT from an LReal here, from any other type s7_convert's."""
    source = value_type(params[0]) if len(params) == 4 else None
    target = value_type(params[1]) if len(params) == 4 else None
    operand, out = (params[2], params[3]) if len(params) == 4 else (None, None)
    if source is not VT.LREAL:
        return s7_convert.convert(b, impl, params, inputs)
    if target is None or not big_endian(b) or not readable(operand, source) or \
            not writable(out, target):
        return None
    f = b.f
    start = f.block
    _, after = f.branch(inputs[0])
    if isinstance(operand, Address) and operand.bit is not None:  # 0 or 1, as an integer
        ok = s7_convert.from_integer(f, s7_values.read_int(f, operand, source), target, out)
    elif isinstance(operand, Address):
        ok = _from_lreal(f, operand, target, out)
    else:
        assert isinstance(operand, int)
        ok = s7_convert.constant(f, typed.bits_real(operand), target, out)
    ran = f.block
    f.join(after)
    w1 = f.value(f"phi i1 [false, %{start}], [{ok}, %{ran}]")
    return f.value(f"zext i1 {w1} to i8")


load_all()
STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {
    **{REGISTRY[name]: ("s7", _arithmetic(name, s7_values.STATEFUL[REGISTRY[name]][1]))
       for name in _OPS},
    REGISTRY["S7.CONVERT"]: ("s7", convert),
}
"""S7's arithmetic and CONVERT (floats here, the rest delegated): implementation ->
(kind, emitter)."""
