"""Delta's float functions made native (native/delta_libm.py: DSIN ... DPOW through libm)
equal their Python implementations exactly: one program of every function (and pulse form,
radians and degrees) on a Python and a native engine, the operand singles and inputs set before
every scan, the outputs and flags reset to a pattern; after every scan all memory, the call
sites' states and the power flow are equal and nothing calls back. Every pair of a grid of
special singles (infinities, NaNs with payloads, -0, denormals, the largest, the domain and
overflow edges), then hypothesis-drawn singles and bits."""

from __future__ import annotations

import struct
from itertools import product

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.test_native_delta import (
    _delta,
    _pair,
)
from tests.core.plc.test_native_delta import (
    test_real_delta_programs_run_natively_as_in_python as _real_run,  # not collected here
)
from tests.core.plc.test_native_functions import (
    disk_cache_in_tmp as disk_cache_in_tmp,  # the autouse fixture: the disk cache in tmp
)
from tests.hypothesis_profiles import examples
from tests.real_programs import real_programs_dir

_ONE = ("DSIN", "DCOS", "DTAN", "DASIN", "DACOS", "DATAN", "DSINH", "DCOSH", "DTANH", "DEXP",
        "DLN")
_TWO = ("DLOG", "DPOW")


def _lines() -> list[str]:
    """Every function on D0 (and D2) into D100 ..., with constants too; pulse forms on X1."""
    lines: list[str] = []
    for name in _ONE:
        lines += [f"{name} D0 D{{}}", f"{name} D2 D{{}}", f"{name} K-3 D{{}}",
                  f"{name}P D4 D{{}}"]
    for name in _TWO:
        lines += [f"{name} D0 D2 D{{}}", f"{name} D2 D0 D{{}}", f"{name} D4 D0 D{{}}",
                  f"{name} K10 D0 D{{}}", f"{name} D0 K3 D{{}}", f"{name} K-2 D2 D{{}}",
                  f"{name}P D0 D4 D{{}}", f"{name} D0 D0 D{{}}"]
    return [line.format(100 + 2 * k) for k, line in enumerate(lines)]


LINES = _lines()
OUT = 100 + 2 * len(LINES)  # the bytes from D100 the rows write
# M1018 on X0 (degrees), the plain rows under M1000, the pulse forms under X1
PROGRAM = "LD X0\nOUT M1018\n" + "".join(
    f"LD {'X1' if 'P ' in line else 'M1000'}\n{line}\n" for line in LINES)
_FLAGS = [DEVICES.bit(f"M{n}") for n in (1020, 1021, 1022, 1067, 1068)]
_D = DEVICES.word("D0")[0]

# singles: infinities, NaNs (signalling, quiet, payloads), zeros, denormals, the largest,
# +-1 and their neighbours (asin, log), 10, 2, 0.5, -0.5, -2.5 (pow), exp/sinh overflow edges
# (709.78, 710.5 as doubles: single near them), 88.7 (the single's overflow), huge values
SPECIAL = (0x7F800000, 0xFF800000, 0x7F800001, 0xFFC00123, 0x7FC00000, 0x00000000,
           0x80000000, 0x00000001, 0x807FFFFF, 0x00800000, 0x7F7FFFFF, 0xFF7FFFFF,
           0x3F800000, 0xBF800000, 0x3F800001, 0x3F7FFFFF, 0xBF800001, 0x41200000,
           0x40000000, 0x3F000000, 0xBF000000, 0xC0200000, 0x44317000, 0x4431E000,
           0x44318000, 0x42B17218, 0x42B20000, 0xC4317000, 0x4B000001, 0xCB000001,
           0x43340000, 0x42B40000, 0xC2B40000, 0x5F000000, 0x40490FDB)
_single = st.one_of(st.sampled_from(SPECIAL), st.integers(0, 0xFFFF_FFFF),
                    st.floats(width=32).map(lambda x: int.from_bytes(struct.pack("<f", x),
                                                                     "little")))
_scans = st.lists(st.tuples(_single, _single, _single, st.integers(0, 3)),
                  min_size=1, max_size=12)


def _scan(engines: tuple[ScanEngine, ScanEngine], singles: tuple[int, int, int],
          inputs: int, step: int) -> None:
    python, native = engines
    for engine in engines:
        memory = engine.memory
        for k, bits in enumerate(singles):
            memory.write(DEVICES.word(f"D{2 * k}")[0], bits, 4)
        out = DEVICES.word("D100")[0]
        memory.areas[Area.D][out.byte:out.byte + 2 * (OUT - 100)] = bytes(
            (step + k) % 256 for k in range(2 * (OUT - 100)))
        for flag in _FLAGS:
            memory.set_bit(flag, False)
        memory.areas[Area.X][0] = inputs
        engine.scan()
    assert native.memory.areas == python.memory.areas, (step, [hex(s) for s in singles])
    assert native.call_states() == python.call_states(), step
    if python.monitored:
        assert native.power_flow == python.power_flow, step


def test_every_pair_of_special_singles_runs_natively_as_in_python() -> None:
    """Every (D0, D2) of SPECIAL (D4 the next), radians and degrees, fast."""
    engines = _pair(_delta(PROGRAM), False, 10)
    for step, (a, b) in enumerate(product(SPECIAL, SPECIAL)):
        _scan(engines, (a, b, SPECIAL[(step + 1) % len(SPECIAL)]), step % 4, step)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@settings(max_examples=examples(60), deadline=None)
@given(scans=_scans)
def test_delta_float_functions_run_natively_as_in_python(monitored: bool, scans: list
                                                         ) -> None:
    engines = _pair(_delta(PROGRAM), monitored, 10)
    for step, (a, b, c, inputs) in enumerate(scans):
        _scan(engines, (a, b, c), inputs, step)


def test_the_float_functions_are_native() -> None:
    """No row of the program calls back (as `_pair` asserts), and the errors are seen: DLN
    of 0 is the operation error, D kept."""
    python, native = _pair(_delta("LD M1000\nDLN D0 D2\n"), False, 10)
    for engine in (python, native):
        engine.memory.write(DEVICES.word("D2")[0], 7, 4)
        engine.scan()
        assert engine.memory.bit(DEVICES.bit("M1067")) == 1
        assert engine.memory.read(DEVICES.word("D2")[0], 4) == 7


# DSCLP (native/delta_scale32.py): S, the table T (4 pairs) and constants; a table from C200
# (C200 ... C206), one past D's end (the error); S and the table's values drawn, the limits often
SCALE = ("LD M1000\nDSCLP D0 D2 D20\nDSCLP K-7 D2 D22\nDSCLP D10 C200 D24\nDSCLP C207 D2 C210\n"
         "DSCLP D0 D9996 D26\nLD X1\nDSCLPP D0 D2 D28\nDSCLPP D10 D12 D30\n")
_EDGE32 = (-(1 << 31), (1 << 31) - 1, 0, 1, -1, 1000, -1000, (1 << 31) - 2, -(1 << 31) + 1)
_int32 = st.one_of(st.sampled_from(_EDGE32), st.integers(-(1 << 31), (1 << 31) - 1))


def _scale_scan(engines: tuple[ScanEngine, ScanEngine], values: list[int], inputs: int,
                equal: bool, step: int) -> None:
    python, native = engines
    for engine in engines:
        memory = engine.memory
        for k, number in enumerate(values[:9]):
            memory.write(DEVICES.word(f"D{2 * k}")[0], number, 4)
        if equal:  # T = T+2: the error
            memory.write(DEVICES.word("D14")[0], values[6], 4)
            memory.write(DEVICES.word("D4")[0], values[1], 4)
        for k, number in enumerate(values[9:]):
            memory.write(DEVICES.word(f"C20{k}")[0], number, 4)
        for flag in _FLAGS:
            memory.set_bit(flag, False)
        memory.areas[Area.X][0] = inputs
        engine.scan()
    assert native.memory.areas == python.memory.areas, (step, values)
    assert native.call_states() == python.call_states(), step
    if python.monitored:
        assert native.power_flow == python.power_flow, step


def test_dsclp_at_the_limits_runs_natively_as_in_python() -> None:
    """S, T, T+2, T+4, T+6 each -2^31, -1, 0 or 2^31-1 (products past 2^63)."""
    engines = _pair(_delta(SCALE), False, 10)
    limits = (-(1 << 31), -1, 0, (1 << 31) - 1)
    for step, (s, t, b, h, lo) in enumerate(product(limits, repeat=5)):
        values = [s, t, b, h, lo, t, b, h, lo, s, b, t, lo, h, 0, 0, 0, 0]
        _scale_scan(engines, values, step % 4, False, step)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@settings(max_examples=examples(100), deadline=None)
@given(scans=st.lists(st.tuples(st.lists(_int32, min_size=18, max_size=18),
                                st.integers(0, 3), st.booleans()), min_size=1, max_size=8))
def test_dsclp_runs_natively_as_in_python(monitored: bool, scans: list) -> None:
    engines = _pair(_delta(SCALE), monitored, 10)
    for step, (values, inputs, equal) in enumerate(scans):
        _scale_scan(engines, values, inputs, equal, step)


# DEADD ... DEDIV of two different pairs (delta_float.py): two NaNs give the first's NaN
ARITHMETIC = "".join(f"LD M1000\n{name} D0 D2 D{20 + 8 * k}\n{name} D2 D0 D{22 + 8 * k}\n"
                     f"{name} D4 D0 D{24 + 8 * k}\nLD X1\n{name}P D0 D4 D{26 + 8 * k}\n"
                     for k, name in enumerate(("DEADD", "DESUB", "DEMUL", "DEDIV")))
_nan = st.one_of(st.integers(0x7F800001, 0x7FFFFFFF), st.integers(0xFF800001, 0xFFFFFFFF))


def _arithmetic_scan(engines: tuple[ScanEngine, ScanEngine], singles: tuple[int, ...],
                     inputs: int, step: int) -> None:
    python, native = engines
    for engine in engines:
        memory = engine.memory
        for k, bits in enumerate(singles):
            memory.write(DEVICES.word(f"D{2 * k}")[0], bits, 4)
        for flag in _FLAGS:
            memory.set_bit(flag, False)
        memory.areas[Area.X][0] = inputs
        engine.scan()
    assert native.memory.areas == python.memory.areas, (step, [hex(s) for s in singles])
    assert native.call_states() == python.call_states(), step


def test_two_pairs_of_special_singles_add_natively_as_in_python() -> None:
    """Every (D0, D2) of SPECIAL, each row run many times (CPython's own add and multiply
    keep the other NaN before their bytecode is specialized, the first after)."""
    engines = _pair(_delta(ARITHMETIC), False, 10)
    for step, (a, b) in enumerate(product(SPECIAL, SPECIAL)):
        _arithmetic_scan(engines, (a, b, SPECIAL[(step + 3) % len(SPECIAL)]), step % 4, step)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@settings(max_examples=examples(60), deadline=None)
@given(scans=st.lists(st.tuples(st.one_of(_nan, _single), st.one_of(_nan, _single),
                                st.one_of(_nan, _single), st.integers(0, 3)),
                      min_size=1, max_size=8))
def test_two_pairs_add_natively_as_in_python(monitored: bool, scans: list) -> None:
    engines = _pair(_delta(ARITHMETIC), monitored, 10)
    for step, (a, b, c, inputs) in enumerate(scans):
        _arithmetic_scan(engines, (a, b, c), inputs, step)


def test_two_nans_give_the_first_nan_every_time() -> None:
    """Python's DEADD of two NaNs is the same before and after CPython specializes `a + b`
    (its eighth run): the first operand's NaN, quieted."""
    python = ScanEngine(_delta("LD M1000\nDEADD D0 D2 D4\nDEMUL D2 D0 D6\n"))
    for _ in range(20):
        python.memory.write(DEVICES.word("D0")[0], 0x7F800123, 4)
        python.memory.write(DEVICES.word("D2")[0], 0xFFC00456, 4)
        python.scan()
        assert python.memory.read(DEVICES.word("D4")[0], 4) == 0x7FC00123
        assert python.memory.read(DEVICES.word("D6")[0], 4) == 0xFFC00456


@pytest.mark.parametrize("name", ["NIRMALKUMAR_compliment", "NIRMALKUMAR_float"])
def test_real_float_programs_run_natively_without_calling_back(name: str) -> None:
    """The WPLSoft projects (read from ../shared) whose DEXP, DLN, DSIN, DASIN, DLOG and
    DEADD of two pairs called back: none does now, and they run as in Python (200 scans
    fast and monitored, then skipping: test_native_delta.py's test)."""
    path = real_programs_dir() / "delta" / f"{name}.dvp"
    compiled = compile_program(parse_file(path).program)
    assert compiled.binary is not None
    _pair(decode(compiled.binary), False, 10)  # asserts that nothing calls back
    _real_run(name)


# PLSY/DPLSY (native/delta_pulses.py): frequencies and counts from the data (drawn each scan)
# and constants, on Y0/Y1 (two sites on one output), an output of neither (the error), a
# subroutine's PLSY run twice a scan (counted once); D1030-D1033 now and then written
PULSES = ("LD X0\nPLSY D0 D1 Y0\nLD X1\nDPLSY D2 D4 Y1\nLD X2\nPLSY K1000 K50 Y0\n"
          "LD X3\nPLSY K10 K0 Y1\nLD X4\nPLSY D6 K7 Y2\nLD X5\nDPLSY K200000 D8 Y1\n"
          "LD X6\nCALL P1\nLD X6\nCALL P1\nLD X7\nPLSY D10 K3 Y0\nFEND\n"
          "P1\nLD X10\nDPLSY K200000 K2147483647 Y0\nSRET\n")
_HERTZ = st.sampled_from((0, 1, 3, 7, 1000, 65535, 0xFFFF_FFFF, 0x7FFF_FFFF, 0x8000_0000))
_pulse_scans = st.lists(st.tuples(st.lists(_HERTZ, min_size=6, max_size=6),
                                  st.integers(0, 0x7FF), st.booleans(),
                                  st.integers(0, 0xFFFF_FFFF)), min_size=1, max_size=30)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@settings(max_examples=examples(60), deadline=None)
@given(scans=_pulse_scans, period=st.sampled_from((1, 8, 30, 130, 5000)))
def test_plsy_runs_natively_as_in_python(monitored: bool, scans: list, period: int) -> None:
    python, native = _pair(_delta(PULSES), monitored, period)
    for values, inputs, written, count in scans:
        for engine in (python, native):
            memory = engine.memory
            for k, number in enumerate(values):
                memory.write(DEVICES.word(f"D{2 * k}")[0], number, 4)
            if written:
                memory.write(DEVICES.word("D1030")[0], count, 4)
                memory.write(DEVICES.word("D1032")[0], count ^ 0x8000_0000, 4)
            memory.areas[Area.X][0], memory.areas[Area.X][1] = inputs & 0xFF, inputs >> 8
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        assert native._ctx.wake_ms == python._ctx.wake_ms
        if monitored:
            assert native.power_flow == python.power_flow


def test_a_plsy_is_skipped_natively_as_python_runs_it() -> None:
    """The native skipper moves PLSY's "ms" and "at" on (time values) as every scan would."""
    binary = _delta("LD X0\nPLSY K3 K40 Y0\nLD X1\nDPLSY K1 K0 Y1\n")
    python, native = _pair(binary, False, 8, every_scan=False)
    for low, ms in ((1, 500), (3, 20000), (0, 300), (2, 4000), (3, 60000)):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = low
            engine.step(ms)
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
    assert native.skipped > 0
