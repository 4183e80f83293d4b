"""Delta DVP's float functions as native code (core/plc/functions/delta_float.py): DSIN ...
DTAN, DASIN ... DATAN, DSINH ... DTANH, DEXP, DLN, DLOG, DPOW and their pulse forms. Each
calls the libm function CPython's math module calls (`declare double @sin(double)` resolves in
the JIT to the process's libm; `nobuiltin` keeps LLVM from folding or replacing the call) and
reproduces the module's checks: `math_1` (a NaN from a non-NaN argument: ValueError; an
infinity from a finite one: ValueError or OverflowError; a finite result with errno set never
raises with glibc: it sets EDOM only with a NaN and ERANGE above 1.5 only with an infinity),
`m_log` (log of 0, of a negative or of -inf: ValueError; of a NaN or +inf: itself) and
`math.pow`'s own special cases for an infinite or NaN operand (with finite operands: an error
when libm's result is not finite). Every error is the row's operation error (D kept), as is a
NaN result (`_result`); else the result is rounded as `_result` rounds it. The exactness
rests on glibc's libm being the one CPython calls: elsewhere the rows call back."""

from __future__ import annotations

import math
import platform
from collections.abc import Callable, Sequence

from ladderworks.core.plc.functions import FunctionImpl
from ladderworks.core.plc.functions.delta_float import M1018
from ladderworks.core.plc.functions.dvp_data import M1020, M1021, M1022, M1067, M1068
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.delta_float import _double, _float, _rounded
from ladderworks.core.plc.native.delta_logic import checked, rows, writer
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import Prepare, _place, _Refused, _row

Body = Callable[[FunctionText], None]
Value = Callable[[FunctionText], str]
_GLIBC = platform.libc_ver()[0] == "glibc"
_INFINITY, _NEGATIVE_ZERO = _double(math.inf), _double(-0.0)
_TO_RADIANS, _TO_DEGREES = _double(math.pi / 180.0), _double(180.0 / math.pi)


def _call(f: FunctionText, name: str, *arguments: str) -> str:
    """libm's `name` of doubles, never replaced by LLVM (`nobuiltin`)."""
    listed = ", ".join(f"double {a}" for a in arguments)
    return f.value(f"call double @{name}({listed}) nobuiltin")


def _finite(f: FunctionText, value: str) -> str:
    """An i1: `value` is neither an infinity nor a NaN."""
    return f.value(f"fcmp olt double {f.value(f'call double @llvm.fabs.f64(double {value})')}, "
                   f"{_INFINITY}")


def _infinite(f: FunctionText, value: str) -> str:
    return f.value(f"fcmp oeq double {f.value(f'call double @llvm.fabs.f64(double {value})')}, "
                   f"{_INFINITY}")


def _nan(f: FunctionText, value: str) -> str:
    return f.value(f"fcmp uno double {value}, 0.0")


def _or(f: FunctionText, *values: str) -> str:
    result = values[0]
    for value in values[1:]:
        result = f.value(f"or i1 {result}, {value}")
    return result


def _and(f: FunctionText, *values: str) -> str:
    result = values[0]
    for value in values[1:]:
        result = f.value(f"and i1 {result}, {value}")
    return result


def _select(f: FunctionText, condition: str, yes: str, no: str) -> str:
    return f.value(f"select i1 {condition}, double {yes}, double {no}")


def _prepared(compute: Callable[[FunctionText, list[str]], tuple[str, str]], count: int,
              angles: bool = False) -> Prepare:
    """A row of `count` float operands and a pair D: `compute` gives (error i1, double result);
    on the error (or a NaN result: `_result`) the operation error, D kept; else rounded."""
    def prepare(params: Sequence[object]) -> Body:
        if not _GLIBC or len(params) != count + 1:
            raise _Refused
        reads: list[Value] = [_float(p) for p in params[:count]]
        store = writer(params[count], True)
        for flag in (M1020, M1021, M1022, M1067, M1068, *((M1018,) if angles else ())):
            _place(flag, 1)

        def body(f: FunctionText) -> None:
            bad, exact = compute(f, [read(f) for read in reads])
            checked(f, _or(f, bad, _nan(f, exact)), lambda: _rounded(f, exact, store))

        return body

    return prepare


def _degrees_on(f: FunctionText) -> str:
    assert M1018.bit is not None
    return f.value(f"icmp ne i8 {f.bit(M1018.area, M1018.byte, M1018.bit, False)}, 0")


def _math_1(name: str, angle_in: bool = False, angle_out: bool = False) -> Prepare:
    """`_function(math.<name>)`: M1018 on: the argument (result) from (to) degrees as
    math.radians (math.degrees) multiplies; `math_1`'s checks."""
    def compute(f: FunctionText, values: list[str]) -> tuple[str, str]:
        number = values[0]
        degrees = _degrees_on(f) if angle_in or angle_out else ""
        if angle_in:
            number = _select(f, degrees, f.value(f"fmul double {number}, {_TO_RADIANS}"),
                             number)
        result = _call(f, name, number)
        # a NaN result (ValueError from a non-NaN argument) is `_prepared`'s error anyway
        bad = _and(f, _infinite(f, result), _finite(f, number))
        if angle_out:
            result = _select(f, degrees, f.value(f"fmul double {result}, {_TO_DEGREES}"),
                             result)
        return bad, result

    return _prepared(compute, 1, angle_in or angle_out)


def _m_log(f: FunctionText, number: str) -> str:
    """`m_log` of a number that is positive, +inf or a NaN: log(x), or x itself."""
    return _select(f, _finite(f, number), _call(f, "log", number), number)


def _ln(f: FunctionText, values: list[str]) -> tuple[str, str]:
    """math.log(x): x not above 0 (0, a negative, -inf) or a NaN: an error (or a NaN)."""
    number = values[0]
    return f.value(f"fcmp ule double {number}, 0.0"), _m_log(f, number)


def _log(f: FunctionText, values: list[str]) -> tuple[str, str]:
    """`_log`: base <= 0, base 1 or x <= 0: the error; else m_log(x) / m_log(base)."""
    base, number = values
    bad = _or(f, f.value(f"fcmp ole double {base}, 0.0"),
              f.value(f"fcmp oeq double {base}, 1.0"), f.value(f"fcmp ole double {number}, 0.0"))
    return bad, f.value(f"fdiv double {_m_log(f, number)}, {_m_log(f, base)}")


def _power(f: FunctionText, values: list[str]) -> tuple[str, str]:
    """math.pow: finite operands: libm's pow, an error unless finite; else CPython's own
    special cases (whose NaN is `_result`'s error)."""
    x, y = values
    both = _and(f, _finite(f, x), _finite(f, y))
    libm = _call(f, "pow", x, y)
    absolute_x = f.value(f"call double @llvm.fabs.f64(double {x})")
    absolute_y = f.value(f"call double @llvm.fabs.f64(double {y})")
    nan = _double(math.nan)
    # x infinite: y > 0: x (odd y) or |x|; y == 0: 1; y < 0: copysign(0, x) (odd y) or 0
    odd = _and(f, _finite(f, y),
               f.value(f"fcmp oeq double {f.value(f'frem double {absolute_y}, 2.0')}, 1.0"))
    signed_zero = _select(f, f.value(f"fcmp olt double {x}, 0.0"), _NEGATIVE_ZERO, "0.0")
    above = _select(f, odd, x, absolute_x)
    below = _select(f, odd, signed_zero, "0.0")
    infinite_x = _select(f, f.value(f"fcmp ogt double {y}, 0.0"), above,
                         _select(f, f.value(f"fcmp oeq double {y}, 0.0"), "1.0", below))
    # y infinite: |x| == 1: 1; y > 0 and |x| > 1: y; y < 0 and |x| < 1: -y; else 0
    growing = _or(f, _and(f, f.value(f"fcmp ogt double {y}, 0.0"),
                          f.value(f"fcmp ogt double {absolute_x}, 1.0")),
                  _and(f, f.value(f"fcmp olt double {y}, 0.0"),
                       f.value(f"fcmp olt double {absolute_x}, 1.0")))
    infinite_y = _select(f, f.value(f"fcmp oeq double {absolute_x}, 1.0"), "1.0",
                         _select(f, growing, _INFINITY, "0.0"))
    special = _select(
        f, _nan(f, x), _select(f, f.value(f"fcmp oeq double {y}, 0.0"), "1.0", nan),
        _select(f, _nan(f, y), _select(f, f.value(f"fcmp oeq double {x}, 1.0"), "1.0", nan),
                _select(f, _infinite(f, x), infinite_x, infinite_y)))
    bad = f.value(f"and i1 {both}, {f.value(f'xor i1 {_finite(f, libm)}, true')}")
    return bad, _select(f, both, libm, special)


PREPARE: dict[str, Prepare] = {
    **{name: _math_1(name) for name in ("sinh", "cosh", "tanh", "exp")},
    **{name: _math_1(name, angle_in=True) for name in ("sin", "cos", "tan")},
    **{name: _math_1(name, angle_out=True) for name in ("asin", "acos", "atan")},
    "ln": _prepared(_ln, 1), "log": _prepared(_log, 2), "power": _prepared(_power, 2)}
EMITTERS: dict[FunctionImpl, Emitter] = {impl: _row(p) for impl, p in rows(PREPARE, False).items()}
PULSES = rows(PREPARE, True)
