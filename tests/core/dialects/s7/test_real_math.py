"""S7 ADD/SUB/MUL/DIV of Real/LReal and CONVERT from LReal never raise on data: a Real result
too large is ±infinity, NaNs come out the same on every machine, ENO 0 when the result written
is not a finite number (docs/dialects.md, S7-1200, "Real and LReal results")."""

from __future__ import annotations

import math

from ladderworks.core.address import Address, Area
from ladderworks.core.plc import typed
from tests.core.dialects.s7.test_functions import Plc

VT = typed.ValueType
REAL, LREAL, INT, DINT = int(VT.REAL), int(VT.LREAL), int(VT.INT), int(VT.DINT)
A, B, OUT = Address(Area.R, 0), Address(Area.R, 8), Address(Area.R, 16)
MAX = 3.4028234663852886e38  # the largest Real


def _run(name: str, vtype: VT, a: float, b: float) -> tuple[bool, float, int]:
    """ENO, the value written and its bits."""
    plc = Plc()
    memory = plc.ctx.memory
    typed.write(memory, A, vtype, a)
    typed.write(memory, B, vtype, b)
    eno = plc.run(name, (True,), (int(vtype), A, B, OUT))
    width = typed.WIDTH[vtype]
    return eno, typed.read(memory, OUT, vtype), memory.read(OUT, width)


def test_a_real_result_too_large_is_infinity_with_eno_0() -> None:
    assert _run("S7.ADD", VT.REAL, 3e38, 3e38)[:2] == (False, math.inf)
    assert _run("S7.SUB", VT.REAL, -3e38, 3e38)[:2] == (False, -math.inf)
    assert _run("S7.MUL", VT.REAL, 1e20, -1e20)[:2] == (False, -math.inf)
    assert _run("S7.DIV", VT.REAL, 1e30, 1e-30)[:2] == (False, math.inf)


def test_a_real_result_that_rounds_to_the_largest_real_fits() -> None:
    assert _run("S7.ADD", VT.REAL, MAX, 2.0 ** 100) == (True, MAX, 0x7F7FFFFF)
    assert _run("S7.ADD", VT.REAL, MAX, 2.0 ** 103)[:2] == (False, math.inf)  # half an ulp up


def test_an_lreal_result_too_large_is_infinity_with_eno_0() -> None:
    assert _run("S7.MUL", VT.LREAL, 1e308, 10.0)[:2] == (False, math.inf)
    assert _run("S7.ADD", VT.LREAL, 1e308, 1e308)[:2] == (False, math.inf)


def test_invalid_operations_give_pythons_nan_with_eno_0() -> None:
    nan_bits = typed.real_bits(math.nan) & 0xFFFFFFFF
    assert _run("S7.SUB", VT.REAL, math.inf, math.inf)[0::2] == (False, nan_bits)
    assert _run("S7.MUL", VT.REAL, 0.0, -math.inf)[0::2] == (False, nan_bits)
    assert _run("S7.DIV", VT.REAL, 0.0, -0.0)[0::2] == (False, nan_bits)
    assert _run("S7.DIV", VT.LREAL, math.inf, -math.inf)[0::2] == (False, typed.lreal_bits(
        math.nan))


def test_division_by_zero_is_signed_infinity() -> None:
    assert _run("S7.DIV", VT.REAL, 2.0, -0.0)[:2] == (False, -math.inf)
    assert _run("S7.DIV", VT.REAL, -2.0, -0.0)[:2] == (False, math.inf)
    assert _run("S7.DIV", VT.LREAL, -2.0, 0.0)[:2] == (False, -math.inf)


def test_a_nan_operand_gives_the_first_nan_made_quiet() -> None:
    first, second = typed.bits_lreal(0xFFF0000000000001), typed.bits_lreal(0x7FF8000000000002)
    assert _run("S7.ADD", VT.LREAL, first, second)[0::2] == (False, 0xFFF8000000000001)
    assert _run("S7.MUL", VT.LREAL, second, first)[0::2] == (False, 0x7FF8000000000002)
    assert _run("S7.DIV", VT.LREAL, 1.0, first)[0::2] == (False, 0xFFF8000000000001)
    real = typed.bits_real(0x7FC00123)
    assert _run("S7.SUB", VT.REAL, 1.0, real)[0::2] == (False, 0x7FC00123)


def _convert(source: VT, target: VT, value: float) -> tuple[bool, int]:
    plc = Plc()
    memory = plc.ctx.memory
    typed.write(memory, A, source, value)
    memory.write(OUT, 0x5A5A5A5A, 4)
    eno = plc.run("S7.CONVERT", (True,), (int(source), int(target), A, OUT))
    return eno, memory.read(OUT, 4)


def test_convert_lreal_to_real_too_large_is_infinity_with_eno_0() -> None:
    assert _convert(VT.LREAL, VT.REAL, 1e300) == (False, 0x7F800000)
    assert _convert(VT.LREAL, VT.REAL, -1e39) == (False, 0xFF800000)
    assert _convert(VT.LREAL, VT.REAL, 1.5) == (True, 0x3FC00000)
    assert _convert(VT.LREAL, VT.REAL, math.nan) == (False, 0x7FC00000)


def test_convert_lreal_to_an_integer_out_of_range_or_not_a_number() -> None:
    assert _convert(VT.LREAL, VT.DINT, math.nan) == (False, 0x5A5A5A5A)  # nothing written
    assert _convert(VT.LREAL, VT.DINT, -math.inf) == (False, 0x5A5A5A5A)
    assert _convert(VT.LREAL, VT.DINT, 2.0 ** 32 + 5.5) == (False, 6)  # the low bytes
    assert _convert(VT.LREAL, VT.DINT, 1e300)[0] is False
    assert _convert(VT.LREAL, VT.DINT, -2.5) == (True, 0xFFFFFFFE)  # half to even
