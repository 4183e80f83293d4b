"""S7-1200's typed values as native code (core/plc/typed.py): big-endian loads and stores
(llvm.bswap), and the stateless rows on them: the comparisons, IN_RANGE/OUT_RANGE, OK/NOT_OK,
MOVE, ADD/SUB/MUL/DIV, INC/DEC (core/plc/functions/s7_compare.py, s7_math.py; CONVERT in
s7_convert.py).

Integers are worked in i64 (ADD/SUB/MUL in i128: UDInt × UDInt needs 64 bits unsigned), so
every result is Python's exactly before it is wrapped to its type. Real and LReal: the
comparisons and IN_RANGE (in double: a Real widened is exact), OK/NOT_OK (on the bits), MOVE
(the bits; a Real read and written again by Python's struct is a signalling NaN made quiet,
done here on the bits); arithmetic on them calls back. A row runs natively only in a program
whose memory is big-endian (the S7 dialect), with its type known and its data inside memory.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.native.builtins import _fits, _load, _store, _when
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import Block

VT = typed.ValueType
_I32 = (-(1 << 31), (1 << 31) - 1)
Emitter = Callable[[Block, FunctionImpl, Sequence[object], list[str]], str | None]


def big_endian(b: Block) -> bool:
    """True when the program's memory holds values big-endian (S7)."""
    found = dialects.get(b.dialect)
    return found is not None and found.byteorder == "big"


def value_type(number: object, floats: bool = True) -> VT | None:
    """The ValueType a row's `type` parameter names (None: Python would fail, or a float
    where `floats` is False)."""
    if not isinstance(number, int) or isinstance(number, bool) or \
            number not in {t.value for t in VT}:
        return None
    vtype = VT(number)
    return None if vtype in typed.FLOATS and not floats else vtype


def readable(operand: object, vtype: VT) -> bool:
    """A typed operand the native code reads as Python does: a 32-bit constant, a bit, or
    the type's bytes inside their area."""
    if isinstance(operand, Address):
        return _fits(operand, 1 if operand.bit is not None else typed.WIDTH[vtype])
    return isinstance(operand, int) and not isinstance(operand, bool) and \
        _I32[0] <= operand <= _I32[1]


def writable(target: object, vtype: VT) -> bool:
    """A target `typed.write` writes inside memory, or none (not an address: nothing)."""
    return not isinstance(target, Address) or readable(target, vtype)


def load(f: FunctionText, address: Address, width: int) -> str:
    """The `width`-byte value at `address` (big-endian) as i{8·width}."""
    raw = _load(f, address, width)
    if width == 1:
        return raw
    return f.value(f"call i{8 * width} @llvm.bswap.i{8 * width}(i{8 * width} {raw})")


def store(f: FunctionText, address: Address, width: int, value: str) -> None:
    """Store i{8·width} `value` big-endian."""
    if width > 1:
        value = f.value(f"call i{8 * width} @llvm.bswap.i{8 * width}(i{8 * width} {value})")
    _store(f, address, width, value)


def bit(f: FunctionText, address: Address) -> str:
    """A memory bit as i8 0/1."""
    assert address.bit is not None
    return f.bit(address.area, address.byte, address.bit, False)


def set_bit(f: FunctionText, address: Address, on: str) -> None:
    """`Memory.set_bit` of an i1."""
    assert address.bit is not None
    ptr = f.byte_ptr(address.area, address.byte)
    old = f.value(f"load i8, ptr {ptr}")
    cleared = f.value(f"and i8 {old}, {~(1 << address.bit) & 0xFF}")
    wide = f.value(f"zext i1 {on} to i8")
    moved = f.value(f"shl i8 {wide}, {address.bit}") if address.bit else wide
    f.add(f"store i8 {f.value(f'or i8 {cleared}, {moved}')}, ptr {ptr}")


def read_int(f: FunctionText, operand: object, vtype: VT) -> str:
    """`typed.read` of an integer type as i64."""
    if isinstance(operand, Address):
        if operand.bit is not None:
            return f.value(f"zext i8 {bit(f, operand)} to i64")
        width = typed.WIDTH[vtype]
        extend = "sext" if vtype in typed.SIGNED else "zext"
        return f.value(f"{extend} i{8 * width} {load(f, operand, width)} to i64")
    assert isinstance(operand, int)
    return str(operand)


def write_int(f: FunctionText, target: object, vtype: VT, value: str, kind: str = "i64") -> None:
    """`typed.write` of an integer (`kind` wide) into an integer type."""
    if not isinstance(target, Address):
        return
    if target.bit is not None:
        set_bit(f, target, f.value(f"icmp ne {kind} {value}, 0"))
        return
    width = typed.WIDTH[vtype]
    store(f, target, width, f.value(f"trunc {kind} {value} to i{8 * width}"))


def double(value: float) -> str:
    """An IR double constant (its bits: exact, NaN and infinities included)."""
    return f"0x{struct.unpack('>Q', struct.pack('>d', value))[0]:016X}"


def read_float(f: FunctionText, operand: object, vtype: VT) -> str:
    """`typed.read` of Real or LReal as a double (a Real widened: exact)."""
    if isinstance(operand, Address):
        if operand.bit is not None:
            return f.value(f"uitofp i8 {bit(f, operand)} to double")
        if vtype is VT.LREAL:
            return f.value(f"bitcast i64 {load(f, operand, 8)} to double")
        single = f.value(f"bitcast i32 {load(f, operand, 4)} to float")
        return f.value(f"fpext float {single} to double")
    assert isinstance(operand, int)
    return double(typed.bits_real(operand))


def _tested(kind_int: str, kind_float: str) -> Emitter:
    """S7.EQ … S7.LE: IN AND (IN1 test IN2)."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        vtype = value_type(params[0])
        if vtype is None or len(params) != 3 or not big_endian(b) or \
                not all(readable(p, vtype) for p in params[1:]):
            return None
        f = b.f
        if vtype in typed.FLOATS:
            first, second = (read_float(f, p, vtype) for p in params[1:])
            test = f.value(f"fcmp {kind_float} double {first}, {second}")
        else:
            first, second = (read_int(f, p, vtype) for p in params[1:])
            test = f.value(f"icmp {kind_int} i64 {first}, {second}")
        return f.value(f"and i8 {inputs[0]}, {f.value(f'zext i1 {test} to i8')}")

    return emit


def _range(outside: bool) -> Emitter:
    """IN_RANGE / OUT_RANGE: IN AND (MIN ≤ VAL ≤ MAX), or IN AND NOT that."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        vtype = value_type(params[0])
        if vtype is None or len(params) != 4 or not big_endian(b) or \
                not all(readable(p, vtype) for p in params[1:]):
            return None
        f = b.f
        if vtype in typed.FLOATS:
            low, value, high = (read_float(f, p, vtype) for p in params[1:])
            inside = f.value(f"and i1 {f.value(f'fcmp ole double {low}, {value}')}, "
                             f"{f.value(f'fcmp ole double {value}, {high}')}")
        else:
            low, value, high = (read_int(f, p, vtype) for p in params[1:])
            inside = f.value(f"and i1 {f.value(f'icmp sle i64 {low}, {value}')}, "
                             f"{f.value(f'icmp sle i64 {value}, {high}')}")
        if outside:
            inside = f.value(f"xor i1 {inside}, true")
        return f.value(f"and i8 {inputs[0]}, {f.value(f'zext i1 {inside} to i8')}")

    return emit


def _valid(invalid: bool) -> Emitter:
    """OK / NOT_OK: IN AND the Real is (not) finite and normal (or zero), on its bits."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if len(params) != 1 or not readable(params[0], VT.REAL) or not big_endian(b):
            return None
        operand, f = params[0], b.f
        if not isinstance(operand, Address) or operand.bit is not None:  # known now
            value = typed.bits_real(operand) if isinstance(operand, int) else 0.0
            return inputs[0] if typed.valid_real(value) != invalid else "0"
        raw = load(f, operand, 4)
        exponent = f.value(f"and i32 {raw}, 2139095040")  # 0x7F800000
        finite = f.value(f"icmp ne i32 {exponent}, 2139095040")
        zero_exponent = f.value(f"icmp eq i32 {exponent}, 0")
        fraction = f.value(f"and i32 {raw}, 8388607")
        denormal = f.value(f"and i1 {zero_exponent}, {f.value(f'icmp ne i32 {fraction}, 0')}")
        valid = f.value(f"and i1 {finite}, {f.value(f'xor i1 {denormal}, true')}")
        if invalid:
            valid = f.value(f"xor i1 {valid}, true")
        return f.value(f"and i8 {inputs[0]}, {f.value(f'zext i1 {valid} to i8')}")

    return emit


def float_bits(f: FunctionText, operand: object, vtype: VT) -> str:
    """The bits `typed.write` stores for a Real/LReal `typed.read` gave (i32 or i64): a
    Real's signalling NaN comes back quiet (C's float → double → float in struct)."""
    if vtype is VT.LREAL:
        if isinstance(operand, Address) and operand.bit is None:
            return load(f, operand, 8)
        if isinstance(operand, Address):
            return f.value(f"select i1 {f.truth(bit(f, operand))}, i64 4607182418800017408, "
                           f"i64 0")  # 1.0
        assert isinstance(operand, int)
        return str(signed(typed.lreal_bits(typed.bits_real(operand)), 8))
    if isinstance(operand, Address) and operand.bit is None:
        raw = load(f, operand, 4)
        exponent = f.value(f"and i32 {raw}, 2139095040")
        fraction = f.value(f"and i32 {raw}, 8388607")
        nan = f.value(f"and i1 {f.value(f'icmp eq i32 {exponent}, 2139095040')}, "
                      f"{f.value(f'icmp ne i32 {fraction}, 0')}")
        return f.value(f"select i1 {nan}, i32 {f.value(f'or i32 {raw}, 4194304')}, i32 {raw}")
    if isinstance(operand, Address):
        return f.value(f"select i1 {f.truth(bit(f, operand))}, i32 1065353216, i32 0")
    assert isinstance(operand, int)
    return str(signed(typed.real_bits(typed.bits_real(operand)) & 0xFFFFFFFF, 4))


def signed(raw: int, width: int) -> int:
    half = 1 << (8 * width - 1)
    return raw - (half << 1) if raw >= half else raw


def write_float_bits(f: FunctionText, target: object, vtype: VT, raw: str) -> None:
    """`typed.write` of a Real/LReal given its bits."""
    if not isinstance(target, Address):
        return
    kind = "i64" if vtype is VT.LREAL else "i32"
    if target.bit is not None:  # bool(value): anything but ±0.0
        magnitude = f.value(f"and {kind} {raw}, {(1 << (64 if kind == 'i64' else 32) - 1) - 1}")
        set_bit(f, target, f.value(f"icmp ne {kind} {magnitude}, 0"))
        return
    store(f, target, typed.WIDTH[vtype], raw)


def _move(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """MOVE: OUT1 := IN while EN (W1 = EN)."""
    vtype = value_type(params[0])
    if vtype is None or len(params) != 3 or not big_endian(b) or \
            not readable(params[1], vtype) or not writable(params[2], vtype):
        return None
    f, source, target = b.f, params[1], params[2]

    def body() -> None:
        if vtype in typed.FLOATS:
            write_float_bits(f, target, vtype, float_bits(f, source, vtype))
        else:
            write_int(f, target, vtype, read_int(f, source, vtype))

    _when(f, inputs[0], body)
    return inputs[0]


def fits_type(f: FunctionText, value: str, vtype: VT, kind: str = "i64") -> str:
    """`typed.fits` of an integer (i1)."""
    low, high = typed.limits(vtype)
    return f.value(f"and i1 {f.value(f'icmp sge {kind} {value}, {low}')}, "
                   f"{f.value(f'icmp sle {kind} {value}, {high}')}")


_OPS = {"S7.ADD": "add", "S7.SUB": "sub", "S7.MUL": "mul"}


def _arithmetic(name: str) -> Emitter:
    """ADD/SUB/MUL/DIV of integers: the wrapped result written, W1 = it fits (DIV by 0:
    nothing written, W1 = 0)."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        vtype = value_type(params[0], floats=False)
        if vtype is None or len(params) != 4 or not big_endian(b) or \
                not all(readable(p, vtype) for p in params[1:3]) or \
                not writable(params[3], vtype):
            return None
        f, target = b.f, params[3]
        start = f.block
        _, after = f.branch(inputs[0])
        a, c = read_int(f, params[1], vtype), read_int(f, params[2], vtype)
        if name == "S7.DIV":
            zero = f.value(f"icmp eq i64 {c}, 0")
            divide, done = f.label(), f.label()
            check = f.block
            f.add(f"br i1 {zero}, label %{done}, label %{divide}")
            f.start(divide)
            result = f.value(f"sdiv i64 {a}, {c}")
            write_int(f, target, vtype, result)
            ok = fits_type(f, result, vtype)
            divided = f.block
            f.add(f"br label %{done}")
            f.start(done)
            ok = f.value(f"phi i1 [false, %{check}], [{ok}, %{divided}]")
        else:
            wide = [f.value(f"sext i64 {v} to i128") for v in (a, c)]
            result = f.value(f"{_OPS[name]} i128 {wide[0]}, {wide[1]}")
            write_int(f, target, vtype, result, "i128")
            ok = fits_type(f, result, vtype, "i128")
        ran = f.block
        f.join(after)
        w1 = f.value(f"phi i1 [false, %{start}], [{ok}, %{ran}]")
        return f.value(f"zext i1 {w1} to i8")

    return emit


def _step(delta: int) -> Emitter:
    """INC / DEC: IN/OUT := IN/OUT ± 1 (wrapped), W1 = it fits."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        vtype = value_type(params[0], floats=False)
        if vtype is None or len(params) != 2 or not big_endian(b) or \
                not isinstance(params[1], Address) or not readable(params[1], vtype):
            return None
        f, target = b.f, params[1]
        start = f.block
        _, after = f.branch(inputs[0])
        result = f.value(f"add i64 {read_int(f, target, vtype)}, {delta}")
        write_int(f, target, vtype, result)
        ok = fits_type(f, result, vtype)
        ran = f.block
        f.join(after)
        w1 = f.value(f"phi i1 [false, %{start}], [{ok}, %{ran}]")
        return f.value(f"zext i1 {w1} to i8")

    return emit


load_all()
_TESTS = {"S7.EQ": ("eq", "oeq"), "S7.NE": ("ne", "une"), "S7.GT": ("sgt", "ogt"),
          "S7.LT": ("slt", "olt"), "S7.GE": ("sge", "oge"), "S7.LE": ("sle", "ole")}
STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {
    **{REGISTRY[name]: ("s7", _tested(*tests)) for name, tests in _TESTS.items()},
    REGISTRY["S7.IN_RANGE"]: ("s7", _range(False)),
    REGISTRY["S7.OUT_RANGE"]: ("s7", _range(True)),
    REGISTRY["S7.OK"]: ("s7", _valid(False)),
    REGISTRY["S7.NOT_OK"]: ("s7", _valid(True)),
    REGISTRY["S7.MOVE"]: ("s7", _move),
    **{REGISTRY[name]: ("s7", _arithmetic(name)) for name in ("S7.ADD", "S7.SUB", "S7.MUL",
                                                              "S7.DIV")},
    REGISTRY["S7.INC"]: ("s7", _step(1)),
    REGISTRY["S7.DEC"]: ("s7", _step(-1)),
}
"""S7's stateless rows (their state block stays unused): implementation -> (kind, emitter)."""
