"""Delta DVP floating point as native code where it is exact (core/plc/functions/
delta_float.py): the contacts FLD= ... FOR>= (and their .STK rows), DECMP, DEZCP, FLT/DFLT,
INT/DINT and DEMOV with their pulse forms. A float operand is the single in a device pair
made a double (`fpext`: exact) or a constant's double (exact: 32-bit), compared as Python
compares them (ordered tests, `une` for <>: a NaN is unequal to all); FLT's integer is exact
as a double and rounded once to a single (`fptrunc`, as Python's pack: below 2^31, never
clamped); INT/DINT test the range on the double first; DEMOV works on the bits: an infinity
becomes the largest single with its sign, a NaN is quieted (bit 22 on) with its payload
kept, as Python's unpack and pack do (IEEE 754's conversions); DEADD ... DEDIV (of two
NaNs the first's: `_arithmetic`); DESQR (`llvm.sqrt`: correctly rounded,
as C's sqrt); DRAD/DDEG (one product by CPython's constant). The other functions: delta_libm.py."""

from __future__ import annotations

import math
import struct
from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.instructions import Combine
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, delta_float, load_all
from ladderworks.core.plc.functions.delta_float import LARGEST, SMALLEST, bits_of
from ladderworks.core.plc.functions.dvp_data import M1020, M1021, M1022, M1067, M1068
from ladderworks.core.plc.native import words, words32
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.contacts import _cells, _join
from ladderworks.core.plc.native.delta_logic import checked, rows, writer
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import Prepare, _bit, _place, _Refused, _results, _row

Body = Callable[[FunctionText], None]
def _double(number: float) -> str:
    """An LLVM double literal of exactly `number` (a float literal too when it is a single)."""
    return "0x" + struct.pack(">d", number).hex().upper()


_PREDICATES = {"eq": "oeq", "gt": "ogt", "lt": "olt", "ne": "une", "le": "ole", "ge": "oge"}
_I32 = (-(1 << 31), (1 << 31) - 1)
_LARGEST, _SMALLEST = _double(LARGEST), _double(SMALLEST)
_NEGATIVE_LARGEST, _NEGATIVE_SMALLEST = _double(-LARGEST), _double(-SMALLEST)


def _raw(operand: object) -> Callable[[FunctionText], str]:
    """The i32 bits of a float operand's device pair (`value32`)."""
    read = words32._source(operand)
    return lambda f: f.value(f"trunc i64 {read(f)} to i32")


def _float(operand: object) -> Callable[[FunctionText], str]:
    """`read_float` as a double: a constant's value, or the pair's single made a double."""
    if isinstance(operand, bool) or not isinstance(operand, int | Address):
        raise _Refused
    if isinstance(operand, int):
        if not _I32[0] <= operand <= _I32[1]:
            raise _Refused
        literal = _double(float(operand))
        return lambda f: literal
    raw = _raw(operand)
    return lambda f: f.value(
        f"fpext float {f.value(f'bitcast i32 {raw(f)} to float')} to double")


def _compare(params: Sequence[object]) -> Body:
    s1, s2, output = params
    first, second, bits = _float(s1), _float(s2), _results(output)

    def body(f: FunctionText) -> None:
        a, b = first(f), second(f)
        above = f.value(f"fcmp ogt double {a}, {b}")
        equal = f.value(f"fcmp oeq double {a}, {b}")
        other = f.value(f"xor i1 {f.value(f'or i1 {above}, {equal}')}, true")
        for place, value in zip(bits, (above, equal, other), strict=True):
            _bit(f, place, value)

    return body


def _zone(params: Sequence[object]) -> Body:
    low, high, source, output = params
    lo, hi, read, bits = _float(low), _float(high), _float(source), _results(output)

    def body(f: FunctionText) -> None:
        lower, upper, s = lo(f), hi(f), read(f)
        below = f.value(f"fcmp olt double {s}, {lower}")
        above = f.value(f"and i1 {f.value(f'xor i1 {below}, true')}, "
                        f"{f.value(f'fcmp ogt double {s}, {upper}')}")
        inside = f.value(f"xor i1 {f.value(f'or i1 {below}, {above}')}, true")
        for place, value in zip(bits, (below, inside, above), strict=True):
            _bit(f, place, value)

    return body


def _to_float(wide: bool) -> Prepare:
    """FLT / DFLT S D: the integer as the nearest single into the pair D."""
    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read = (words32._source if wide else words._source)(source)
        store = writer(output, True)

        def body(f: FunctionText) -> None:
            single = f.value(f"fptrunc double {f.value(f'sitofp i64 {read(f)} to double')} "
                             f"to float")
            store(f, f.value(f"sext i32 {f.value(f'bitcast float {single} to i32')} to i64"))

        return body

    return prepare


def _integer(bits: int) -> Prepare:
    """INT / DINT S D: the float toward zero; a NaN, an infinity or a value outside the
    16 (32) bits: the error, D kept; M1020 when 0. The range is tested on the double
    (trunc(x) >= -2^(b-1) is x > -2^(b-1) - 1, trunc(x) < 2^(b-1) is x < 2^(b-1): exact), so
    `fptosi` only sees values it converts exactly."""
    low, high = _double(-(2.0 ** (bits - 1)) - 1), _double(2.0 ** (bits - 1))

    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = _float(source), writer(output, bits == 32)
        _place(M1020, 1)

        def body(f: FunctionText) -> None:
            number = read(f)
            inside = f.value(f"and i1 {f.value(f'fcmp ogt double {number}, {low}')}, "
                             f"{f.value(f'fcmp olt double {number}, {high}')}")

            def run() -> None:
                whole = f.value(f"fptosi double {number} to i64")
                _bit(f, M1020, f.value(f"icmp eq i64 {whole}, 0"))
                store(f, whole)

            checked(f, f.value(f"xor i1 {inside}, true"), run)

        return body

    return prepare


def _rounded(f: FunctionText, exact: str, store: Callable[[FunctionText, str], None]) -> None:
    """`_result` of a double that is no NaN: rounded to a single (past the largest: the
    largest, with its sign), M1020 zero, M1021 below the smallest normal, M1022 clamped."""
    over = f.value(f"or i1 {f.value(f'fcmp ogt double {exact}, {_LARGEST}')}, "
                   f"{f.value(f'fcmp olt double {exact}, {_NEGATIVE_LARGEST}')}")
    negative = f.value(f"fcmp olt double {exact}, 0.0")
    largest = f.value(f"select i1 {negative}, float {_NEGATIVE_LARGEST}, float {_LARGEST}")
    single = f.value(f"select i1 {over}, float {largest}, "
                     f"float {f.value(f'fptrunc double {exact} to float')}")
    stored = f.value(f"fpext float {single} to double")
    _bit(f, M1020, f.value(f"fcmp oeq double {stored}, 0.0"))
    tiny = f.value(f"and i1 {f.value(f'fcmp ogt double {stored}, 0.0')}, "
                   f"{f.value(f'fcmp olt double {stored}, {_SMALLEST}')}")
    above = f.value(f"fcmp ogt double {stored}, {_NEGATIVE_SMALLEST}")
    tiny_below = f.value(f"and i1 {f.value(f'fcmp olt double {stored}, 0.0')}, {above}")
    _bit(f, M1021, f.value(f"or i1 {tiny}, {tiny_below}"))
    _bit(f, M1022, over)
    store(f, f.value(f"sext i32 {f.value(f'bitcast float {single} to i32')} to i64"))


def _root(params: Sequence[object]) -> Body:
    """DESQR S D: the correctly rounded root (`llvm.sqrt`, as C's sqrt); below 0 (-0 is
    not) or a NaN: the error, D kept."""
    source, output = params
    read, store = _float(source), writer(output, True)
    for flag in (M1020, M1021, M1022, M1067, M1068):
        _place(flag, 1)

    def body(f: FunctionText) -> None:
        number = read(f)
        bad = f.value(f"fcmp ult double {number}, 0.0")  # below 0, or a NaN
        checked(f, bad, lambda: _rounded(
            f, f.value(f"call double @llvm.sqrt.f64(double {number})"), store))

    return body


def _scaled(factor: float) -> Prepare:
    """DRAD / DDEG S D: S times pi/180 (180/pi), the constants CPython's math.radians and
    math.degrees multiply by; a NaN: the error, D kept."""
    literal = _double(factor)

    def prepare(params: Sequence[object]) -> Body:
        source, output = params
        read, store = _float(source), writer(output, True)
        for flag in (M1020, M1021, M1022, M1067, M1068):
            _place(flag, 1)

        def body(f: FunctionText) -> None:
            exact = f.value(f"fmul double {read(f)}, {literal}")
            checked(f, f.value(f"fcmp uno double {exact}, 0.0"),
                    lambda: _rounded(f, exact, store))

        return body

    return prepare


def _arithmetic(operator: str) -> Prepare:
    """DEADD ... DEDIV: one NaN operand: its quieted NaN, which the hardware passes on in
    either operand order; two NaNs: the first (`select`: as `_arithmetic` chooses, the operand
    order of the compiled instruction not mattering); so the double result is Python's; rounded
    to a single (past the largest: the largest, with its sign) with M1020-M1022 as
    `_arithmetic` sets them; a division by 0: the error."""
    dividing = operator == "fdiv"

    def prepare(params: Sequence[object]) -> Body:
        s1, s2, output = params
        first, second, store = _float(s1), _float(s2), writer(output, True)
        for flag in (M1020, M1021, M1022, M1067, M1068):
            _place(flag, 1)

        def body(f: FunctionText) -> None:
            a, b = first(f), second(f)

            def run() -> None:
                both = f.value(f"and i1 {f.value(f'fcmp uno double {a}, 0.0')}, "
                               f"{f.value(f'fcmp uno double {b}, 0.0')}")
                exact = f.value(f"{operator} double {a}, {b}")
                _rounded(f, f.value(f"select i1 {both}, double {a}, double {exact}"), store)

            if dividing:
                checked(f, f.value(f"fcmp oeq double {b}, 0.0"), run)
            else:
                run()

        return body

    return prepare


def _move(params: Sequence[object]) -> Body:
    """DEMOV S D: the single's bits (an infinity: the largest single; a NaN quieted)."""
    source, output = params
    store = writer(output, True)
    if isinstance(source, int) and not isinstance(source, bool):
        if not _I32[0] <= source <= _I32[1]:
            raise _Refused
        bits = bits_of(float(source))
        constant = str(bits - (1 << 32) if bits >> 31 else bits)
        return lambda f: store(f, constant)
    raw = _raw(source)

    def body(f: FunctionText) -> None:
        value = raw(f)
        magnitude = f.value(f"and i32 {value}, 2147483647")
        infinite = f.value(f"icmp eq i32 {magnitude}, 2139095040")
        nan = f.value(f"icmp ugt i32 {magnitude}, 2139095040")
        largest = f.value(f"or i32 {f.value(f'and i32 {value}, -2147483648')}, 2139095039")
        quiet = f.value(f"or i32 {value}, 4194304")
        kept = f.value(f"select i1 {nan}, i32 {quiet}, i32 {value}")
        bits = f.value(f"select i1 {infinite}, i32 {largest}, i32 {kept}")
        store(f, f.value(f"sext i32 {bits} to i64"))

    return body


def _contact(combine: object, predicate: str) -> Emitter:
    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(params) != 2 or (combine is not Combine.READ and not inputs):
            return None
        try:
            first, second = _float(params[0]), _float(params[1])
        except (_Refused, ValueError, TypeError, KeyError):
            return None
        contact = f.value(f"fcmp {predicate} double {first(f)}, {second(f)}")
        return _join(f, combine, contact, inputs)

    return emit


def _contacts() -> dict[FunctionImpl, Emitter]:
    """FLD= ... FOR>= (their .STK rows too), each from its implementation's closure."""
    load_all()
    found: dict[FunctionImpl, Emitter] = {}
    for impl in set(REGISTRY.values()):
        if getattr(impl, "__module__", "") != delta_float.__name__:
            continue
        cells = _cells(impl)
        test = getattr(cells.get("test"), "__name__", "")
        if "combine" in cells and test in _PREDICATES:
            found[impl] = _contact(cells["combine"], _PREDICATES[test])
    return found


PREPARE: dict[str, Prepare] = {"fcompare": _compare, "fzone": _zone, "float": _to_float(False),
                               "float32": _to_float(True), "fmove": _move,
                               "integer": _integer(16), "integer32": _integer(32),
                               "fadd": _arithmetic("fadd"), "fsubtract": _arithmetic("fsub"),
                               "fmultiply": _arithmetic("fmul"), "fdivide": _arithmetic("fdiv"),
                               "sqrt": _root, "radians": _scaled(math.pi / 180.0),
                               "degrees": _scaled(180.0 / math.pi)}
EMITTERS: dict[FunctionImpl, Emitter] = {
    **{impl: _row(p) for impl, p in rows(PREPARE, False).items()}, **_contacts()}
PULSES = rows(PREPARE, True)
