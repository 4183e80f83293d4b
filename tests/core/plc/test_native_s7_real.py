"""S7 ADD/SUB/MUL/DIV of Real/LReal and CONVERT from LReal as native code equal their Python
implementations bit for bit (native/s7_real.py): small programs run on a Python engine and a
native one with operand bytes drawn by hypothesis (Real and LReal edges weighted in: ±0,
denormals, the largest Real and half an ulp past it, ±infinity, NaNs with payloads, signalling
and quiet, the halves of round's ties) and, each in each operand place, every edge word; after
every scan all memory and W1 are equal and nothing calls back (test_native_s7.py's helpers)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.plc import typed
from tests.core.plc.test_native_functions import DATA, _run
from tests.core.plc.test_native_s7 import (
    INTEGERS,
    WORDS,
    Program,
    _inputs,
    _signed32,
    _typed_boxes,
    disk_cache_in_tmp,  # noqa: F401 (the fixture)
)
from tests.hypothesis_profiles import examples

VT = typed.ValueType
FLOATS = (VT.REAL, VT.LREAL)
ARITHMETIC = ("S7.ADD", "S7.SUB", "S7.MUL", "S7.DIV")
# LReal bits: ±0, denormals, the smallest normal, the largest, ±infinity, NaNs (signalling,
# quiet, payloads, signs), the largest Real and half an ulp past it, round's ties and 2**52,
# 2**63 and past it (the low bytes of a whole number), Int/DInt limits ± ½
DOUBLES = (0x0000000000000000, 0x8000000000000000, 0x0000000000000001, 0x800FFFFFFFFFFFFF,
           0x0010000000000000, 0x7FEFFFFFFFFFFFFF, 0xFFEFFFFFFFFFFFFF, 0x7FF0000000000000,
           0xFFF0000000000000, 0x7FF0000000000001, 0xFFF4000000000123, 0x7FF8000000000000,
           0xFFF8000000000000, 0x7FFFFFFFFFFFFFFF, 0x7FF80000DEADBEEF, 0x47EFFFFFE0000000,
           0x47EFFFFFF0000000, 0xC7EFFFFFEFFFFFFF, 0x3690000000000000, 0x36A0000000000000,
           0x3FE0000000000000, 0x3FF8000000000000, 0x4004000000000000, 0xC004000000000000,
           0x432FFFFFFFFFFFFF, 0x4330000000000000, 0x4330000000000001, 0x43E0000000000000,
           0x43E0000000000001, 0xC3F0000000000123, 0x44F0000000012345, 0x40DFFFE000000000,
           0xC0E0000800000000, 0x41DFFFFFFFE00000, 0xC1E0000000100000, 0x41EFFFFFFFF00000)
_double = st.one_of(st.sampled_from(DOUBLES), st.integers(0, (1 << 64) - 1),
                    st.tuples(st.sampled_from(WORDS), st.sampled_from(WORDS)).map(
                        lambda w: w[0] << 32 | w[1])).map(lambda d: d.to_bytes(8, "big"))
_data = st.lists(_double, min_size=DATA // 8, max_size=DATA // 8).map(b"".join)
SCANS = st.lists(st.tuples(_data, st.integers(0, 255), st.integers(0, 255)),
                 min_size=1, max_size=5)

_CONSTANTS = (0x7F7FFFFF, 0x7F800000, 0x7FC00001, 0x7F800001, 0xFF800000, 0x80000000,
              0x00000001, 0x3F800000)
ROWS = {
    "arithmetic": lambda: _typed_boxes(ARITHMETIC, (
        ("D0", "D8", "D32"), ("D16", "D16", "D44"), ("D8", "D0", "D56.3"),
        ("D0", _signed32(0x7F7FFFFF), "D68"), (_signed32(0xFF800001), "D8", "D80"),
        ("D0.5", "D16", "D92"), (_signed32(0x7F7FFFFF), _signed32(0x7F7FFFFF), "D104"),
        (0, 0, "D116.1"), (_signed32(0x7FC00001), 1065353216, "D128")), FLOATS),
    "constants": lambda: _constant_boxes(),
    "CONVERT": lambda: _converts(),
}


def _constant_boxes() -> BinaryProgram:
    """Both operands constants (Python's result at compile time), each pair once."""
    program, k = Program(), 0
    for name in ARITHMETIC:
        for vtype in FLOATS:
            for a in _CONSTANTS:
                for b in _CONSTANTS[::3]:
                    program.box(name, int(vtype), _signed32(a), _signed32(b),
                                f"D{200 + 8 * k}", inputs=(_inputs(k % 16),))
                    k += 1
    return program.binary()


def _converts() -> BinaryProgram:
    """LReal to every type from D0/D8/D16, a bit, a constant; to bits of targets too."""
    program, k = Program(), 0
    for target in (*INTEGERS, *FLOATS):
        for operand in ("D0", "D8", "D16", "D4.6", _signed32(0x7F7FFFFF), -1):
            program.box("S7.CONVERT", int(VT.LREAL), int(target), operand, f"D{32 + 8 * k}",
                        inputs=(_inputs(k % 16),))
            k += 1
        program.box("S7.CONVERT", int(VT.LREAL), int(target), "D8", f"D{32 + 8 * k}.5",
                    inputs=(_inputs(k % 16),))
        k += 1
    return program.binary()


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(ROWS))
@settings(max_examples=examples(25), deadline=None)
@given(scans=SCANS)
def test_an_s7_float_row_runs_natively_as_in_python(row: str, monitored: bool,
                                                     scans: list) -> None:
    _run(ROWS[row](), monitored, scans, counters=False)


@pytest.mark.parametrize("row", ["arithmetic", "CONVERT"])
def test_every_edge_double_of_an_s7_float_row_runs_natively_as_in_python(row: str) -> None:
    """Each of DOUBLES (and each pair of WORDS halves) in each operand place, rotated."""
    values = [d.to_bytes(8, "big") for d in DOUBLES] + \
        [(WORDS[k] << 32 | WORDS[-1 - k]).to_bytes(8, "big") for k in range(len(WORDS))]
    scans = [(b"".join(values[(k + n * 7) % len(values)] for n in range(3)), x, x)
             for x in (255, 0) for k in range(len(values))]
    _run(ROWS[row](), False, scans, counters=False)
