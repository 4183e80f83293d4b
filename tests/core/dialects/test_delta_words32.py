"""Delta 32-bit instructions (DMOV ... DZCP, DLD= ... DOR>=) and pulse forms, fast and monitored;
stateful ones also skipping scans equal to every scan."""

from __future__ import annotations

import random

import pytest

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.conftest import delta, engine, get, put
from tests.core.plc.test_skipping import Driver, bytes_of, pair

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


def pair_of(text: str, monitored: bool = False) -> tuple[ScanEngine, ScanEngine]:
    """An every-scan engine and a skipping one of a Delta program."""
    compiled = compile_program(delta(text))
    assert compiled.binary is not None
    return pair(decode(compiled.binary), monitored=monitored)


def same_when_skipping(text: str, scans: int = 1500, monitored: bool = False) -> int:
    """Run a Delta program on an every-scan and a skipping engine with the same random inputs
    (X0-X17, D0-D3 written from outside); memory and states equal after every run. The scans
    the skipping one skipped."""
    engines = pair_of(text, monitored)
    driver = Driver(engines, random.Random(text), bytes_of(Area.X, 2), bytes_of(Area.D, 8), [])
    return driver.run(scans, rate=0.05)


@MODES
def test_dmov_dadd_dsub_keep_32_bits_in_pairs_low_word_first(monitored: bool) -> None:
    plc = engine("LD X0\nDMOV K100000 D0\nDADD D0 K-100001 D2\nDSUB D0 H7FFFFFFF D4\n"
                 "DMOV H12345678 D6\nDMOV C200 D8\nEND\n", monitored=monitored)
    put(plc, "C200", -70000)
    put(plc, "X0", 1)
    plc.scan()
    # 100000 = 1 * 65536 + 34464: D1 = 1, D0 = 34464 (a negative 16-bit value)
    assert (get(plc, "D0:4"), get(plc, "D0"), get(plc, "D1")) == (100000, 34464 - 65536, 1)
    assert get(plc, "D2:4") == -1 and get(plc, "M1020") == 0
    assert get(plc, "D4:4") == 100000 - 2**31 + 1
    assert (get(plc, "D6"), get(plc, "D7")) == (0x5678, 0x1234)  # low word first
    assert get(plc, "D8:4") == -70000


@MODES
def test_dadd_flags_zero_borrow_carry(monitored: bool) -> None:
    plc = engine("LD X0\nDADD D0 D2 D4\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    for a, b, stored, flags in [(5, -5, 0, (1, 0, 0)), (2**31 - 1, 1, -(2**31), (0, 0, 1)),
                                (-(2**31), -1, 2**31 - 1, (0, 1, 0)), (1, 2, 3, (0, 0, 0))]:
        put(plc, "D0:4", a)
        put(plc, "D2:4", b)
        plc.scan()
        assert get(plc, "D4:4") == stored
        assert (get(plc, "M1020"), get(plc, "M1021"), get(plc, "M1022")) == flags


@MODES
def test_dmul_64_bit_product_and_ddiv_quotient_remainder(monitored: bool) -> None:
    plc = engine("LD X0\nDMUL D0 D2 D10\nDDIV D0 D2 D20\nDDIV D0 K0 D30\nEND\n",
                 monitored=monitored)
    put(plc, "D30:4", 77)
    put(plc, "D0:4", -1_000_000)
    put(plc, "D2:4", 300_000)
    put(plc, "X0", 1)
    plc.scan()
    product = -300_000_000_000
    low = get(plc, "D10:4") & 0xFFFF_FFFF
    high = get(plc, "D12:4")
    assert (high << 32) | low == product
    assert (get(plc, "D20:4"), get(plc, "D22:4")) == (-3, -100_000)  # toward zero
    assert get(plc, "D30:4") == 77 and get(plc, "M1067") == 1


@MODES
def test_dinc_ddec_wrap_and_pulse_forms_run_once(monitored: bool) -> None:
    plc = engine("LD X0\nDINC D0\nDDEC D2\nDINCP D4\nDMOVP D0 D6\nEND\n", monitored=monitored)
    put(plc, "D0:4", 2**31 - 3)
    put(plc, "X0", 1)
    plc.run_scans(5)
    assert get(plc, "D0:4") == -(2**31) + 2  # wrapped
    assert (get(plc, "D2:4"), get(plc, "D4:4")) == (-5, 1)
    assert get(plc, "D6:4") == 2**31 - 2  # the first scan's value only
    put(plc, "X0", 0)
    plc.scan()
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D4:4") == 2


@MODES
def test_dcmp_dzcp_set_one_of_three_bits(monitored: bool) -> None:
    plc = engine("LD X0\nDCMP D0 K100000 M0\nDZCP K-70000 K70000 D0 M10\nEND\n",
                 monitored=monitored)
    put(plc, "X0", 1)
    for d0, cmp_bits, zcp_bits in [(200000, (1, 0, 0), (0, 0, 1)), (100000, (0, 1, 0), (0, 0, 1)),
                                   (0, (0, 0, 1), (0, 1, 0)), (-70001, (0, 0, 1), (1, 0, 0))]:
        put(plc, "D0:4", d0)
        plc.scan()
        assert tuple(get(plc, f"M{k}") for k in range(3)) == cmp_bits
        assert tuple(get(plc, f"M{k}") for k in range(10, 13)) == zcp_bits


@MODES
@pytest.mark.parametrize(("op", "test"), [
    ("=", lambda a, b: a == b), (">", lambda a, b: a > b), ("<", lambda a, b: a < b),
    ("<>", lambda a, b: a != b), ("<=", lambda a, b: a <= b), (">=", lambda a, b: a >= b)])
def test_32_bit_comparison_contacts(monitored: bool, op: str, test) -> None:
    plc = engine(f"DLD{op} D0 D2\nOUT Y0\nLD X0\nDAND{op} D0 K100000\nOUT Y1\nLD X0\n"
                 f"DOR{op} D2 K-70000\nOUT Y2\nLD X1\nDLD{op} D0 D2\nORB\nOUT Y3\nEND\n",
                 monitored=monitored)
    for d0, d2, x0, x1 in [(100000, 100000, 1, 0), (65536, 0, 1, 1), (-70000, 70000, 0, 0),
                           (2**31 - 1, -(2**31), 1, 0), (0, -70000, 0, 1)]:
        put(plc, "D0:4", d0)
        put(plc, "D2:4", d2)
        put(plc, "X0", x0)
        put(plc, "X1", x1)
        plc.scan()
        assert get(plc, "Y0") == int(test(d0, d2))
        assert get(plc, "Y1") == int(x0 and test(d0, 100000))
        assert get(plc, "Y2") == int(x0 or test(d2, -70000))
        assert get(plc, "Y3") == int(x1 or test(d0, d2))


def test_a_16_bit_compare_reads_one_word_a_32_bit_one_two() -> None:
    plc = engine("LD= D0 K0\nOUT Y0\nDLD= D0 K0\nOUT Y1\nEND\n")
    put(plc, "D1", 1)  # high word only
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)


def test_the_machine_program_s_lines_run() -> None:
    # METALURGICA's forms (shared real program): DADD/DMUL/DAND< with a pair, DCNT with a D
    plc = engine("LD M1000\nDADD D500 D511 D7\nDMUL D7 K1 D9\nLD M1000\nDAND< D7 K0\n"
                 "DMOV K0 D7\nLD M1000\nDCNT C235 D9\nEND\n")
    put(plc, "D500:4", 100000)
    put(plc, "D511:4", 5)
    plc.scan()
    assert get(plc, "D7:4") == 100005 and get(plc, "D9:4") == 100005


@MODES
def test_high_speed_counter_counts_its_x_input_while_enabled(monitored: bool) -> None:
    plc = engine("LD X10\nDCNT C235 K3\nLD X10\nDCNT C236 D0\nLD C235\nOUT Y0\nEND\n",
                 monitored=monitored)
    put(plc, "D0:4", 100000)
    for x10, x0, x1 in [(1, 1, 1), (1, 0, 0), (1, 1, 1), (0, 0, 0), (0, 1, 0), (1, 0, 1),
                        (1, 1, 0), (1, 0, 1)]:
        put(plc, "X10", x10)
        put(plc, "X0", x0)
        put(plc, "X1", x1)
        plc.scan()
    assert (get(plc, "C235"), get(plc, "Y0")) == (3, 1)
    assert get(plc, "C236") == 4  # X1's rising edges while X10 was on
    put(plc, "M1235", 1)  # down
    put(plc, "X0", 0)
    plc.scan()
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "C235"), get(plc, "Y0")) == (2, 0)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_pulse_forms_and_counters_skip_exactly(monitored: bool) -> None:
    same_when_skipping("LD X0\nDINCP D10\nDADDP D10 D0 D12\nLD X1\nDCNT C235 K5\n"
                       "LD X2\nDMOV D0 D20\nDLD> D20 K3\nOUT Y0\nEND\n", 800, monitored)
