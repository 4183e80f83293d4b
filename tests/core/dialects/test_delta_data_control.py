"""Delta comparisons, data instructions and program control, in fast and monitored mode."""

from __future__ import annotations

import pytest

from tests.core.dialects.conftest import engine, get, put

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


@MODES
@pytest.mark.parametrize(("op", "test"), [
    ("=", lambda a, b: a == b), (">", lambda a, b: a > b), ("<", lambda a, b: a < b),
    ("<>", lambda a, b: a != b), ("<=", lambda a, b: a <= b), (">=", lambda a, b: a >= b)])
def test_comparison_contacts(monitored: bool, op: str, test) -> None:
    plc = engine(f"LD{op} D0 D1\nOUT Y0\nLD X0\nAND{op} D0 K5\nOUT Y1\nLD X0\nOR{op} D1 K-3\n"
                 f"OUT Y2\nLD X1\nLD{op} D0 H10\nORB\nOUT Y3\nEND\n", monitored=monitored)
    for d0, d1, x0, x1 in [(1, 2, 1, 0), (5, 5, 1, 1), (-4, -3, 0, 0), (16, 0, 1, 0),
                           (-32768, 32767, 0, 1)]:
        put(plc, "D0", d0)
        put(plc, "D1", d1)
        put(plc, "X0", x0)
        put(plc, "X1", x1)
        plc.scan()
        assert get(plc, "Y0") == int(test(d0, d1))
        assert get(plc, "Y1") == int(x0 and test(d0, 5))
        assert get(plc, "Y2") == int(x0 or test(d1, -3))
        assert get(plc, "Y3") == int(x1 or test(d0, 16))


@MODES
def test_seed_compare_listings(monitored: bool) -> None:
    # seed 001:1000-1053: Y0 = T0==5; Y1 = X1 and (C1 < C2 or C2 > 10); Y2, Y3
    plc = engine("LD= T0  K5\nOUT  Y0\nLD X1\nLD< C1 C2\nOR> C2 K10\nANB\nOUT Y1\n"
                 "LD= T0  K5\nAND<= C1 C2\nOUT Y2\nLD= T0  K5\nOR<> C1 C2\nOUT Y3\nEND\n",
                 monitored=monitored)
    for t0, c1, c2, x1 in [(5, 0, 0, 1), (4, 1, 2, 1), (5, 3, 2, 0), (0, 20, 11, 1),
                           (0, 2, 2, 1)]:
        put(plc, "T0", t0)
        put(plc, "C1", c1)
        put(plc, "C2", c2)
        put(plc, "X1", x1)
        plc.scan()
        assert [get(plc, f"Y{k}") for k in range(4)] == [
            int(t0 == 5), int(x1 and (c1 < c2 or c2 > 10)), int(t0 == 5 and c1 <= c2),
            int(t0 == 5 or c1 != c2)]


@MODES
def test_cmp_sets_exactly_one_of_three_bits(monitored: bool) -> None:
    plc = engine("LD X0\nCMP K20 D10 M0\nLD X0\nCMP D10 K0 Y6\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    for d10, bits in [(5, (1, 0, 0)), (20, (0, 1, 0)), (25, (0, 0, 1))]:
        put(plc, "D10", d10)
        plc.scan()
        assert (get(plc, "M0"), get(plc, "M1"), get(plc, "M2")) == bits
        assert (get(plc, "Y6"), get(plc, "Y7"), get(plc, "Y10")) == (1, 0, 0)
    put(plc, "X0", 0)
    put(plc, "D10", 5)
    plc.scan()
    assert (get(plc, "M0"), get(plc, "M1"), get(plc, "M2")) == (0, 0, 1)  # kept


@MODES
def test_zcp_zones(monitored: bool) -> None:
    plc = engine("LD X0\nZCP K10 K20 D0 M10\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    for d0, bits in [(9, (1, 0, 0)), (10, (0, 1, 0)), (20, (0, 1, 0)), (21, (0, 0, 1))]:
        put(plc, "D0", d0)
        plc.scan()
        assert (get(plc, "M10"), get(plc, "M11"), get(plc, "M12")) == bits


@MODES
def test_moves_and_arithmetic(monitored: bool) -> None:
    plc = engine("LD X0\nMOV K1234 D0\nMOV H7FFF D1\nADD D0 K6 D2\nSUB K0 D0 D3\n"
                 "MUL D0 K100 D4\nDIV K-7 K2 D6\nADD D1 K1 D8\nMOV T0 D9\nEND\n",
                 monitored=monitored)
    put(plc, "T0", 42)
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"D{k}") for k in range(4)] == [1234, 32767, 1240, -1234]
    assert get(plc, "D4:4") == 123400
    assert (get(plc, "D6"), get(plc, "D7")) == (-3, -1)
    assert get(plc, "D8") == -32768 and get(plc, "M1022") == 1  # carry
    assert get(plc, "D9") == 42


@MODES
def test_inc_dec_every_scan_and_pulse_forms_once(monitored: bool) -> None:
    plc = engine("LD X0\nINC D0\nDEC D1\nINCP D2\nMOVP D0 D3\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    plc.run_scans(5)
    assert [get(plc, f"D{k}") for k in range(4)] == [5, -5, 1, 1]


def test_division_by_zero_writes_nothing() -> None:
    plc = engine("LD X0\nDIV K5 D1 D2\nEND\n")
    put(plc, "D2", 77)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D2") == 77 and get(plc, "M1067") == 1


@MODES
def test_cj_skips_and_skipped_coils_keep_their_state(monitored: bool) -> None:
    plc = engine("LD X0\nCJ P1\nLD X1\nOUT Y0\nP1\nLD X1\nOUT Y1\nEND\n", monitored=monitored)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 1)
    put(plc, "X0", 1)
    put(plc, "X1", 0)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)  # skipped: kept


@MODES
def test_call_runs_the_subroutine_when_on_and_comes_back(monitored: bool) -> None:
    plc = engine("LD X0\nCALL P2\nLD M5\nOUT Y1\nFEND\nP2\nLD X1\nOUT M5\nINC D0\nSRET\nEND\n",
                 monitored=monitored)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "Y1"), get(plc, "D0")) == (0, 0)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "Y1"), get(plc, "D0")) == (1, 1)
    put(plc, "X0", 0)
    put(plc, "X1", 0)
    plc.scan()
    assert (get(plc, "Y1"), get(plc, "D0")) == (1, 1)  # not called: M5 kept


@MODES
def test_mc_mcr_turn_off_the_coils_between_them(monitored: bool) -> None:
    plc = engine("LD X0\nMC N0\nLD X1\nOUT Y0\nLD X1\nSET Y1\nMCR N0\nLD X1\nOUT Y2\nEND\n",
                 monitored=monitored)
    put(plc, "X1", 1)
    plc.scan()
    assert [get(plc, f"Y{k}") for k in range(3)] == [0, 0, 1]
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"Y{k}") for k in range(3)] == [1, 1, 1]
    put(plc, "X0", 0)
    plc.scan()
    assert [get(plc, f"Y{k}") for k in range(3)] == [0, 1, 1]  # SET keeps


@MODES
def test_mc_off_resets_its_timers_and_holds_its_counters(monitored: bool) -> None:
    plc = engine("LD X0\nMC N0\nLD X1\nTMR T0 K100\nLD X1\nCNT C0 K5\nMCR N0\nEND\n",
                 monitored=monitored)
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.run_scans(51)
    assert (get(plc, "T0"), get(plc, "C0")) == (5, 1)
    put(plc, "X0", 0)
    plc.scan()
    assert (get(plc, "T0"), get(plc, "C0")) == (0, 1)  # timer reset, counter kept
