"""Delta TMR, CNT, DCNT and RST, in fast and monitored mode (seed 001)."""

from __future__ import annotations

import pytest

from tests.core.dialects.conftest import engine, get, put

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


def _on_at(plc, output: str, limit_ms: int) -> int:
    """The virtual time at which `output` first reads 1 (after the scan), -1 if never."""
    start = plc.now_ms
    while plc.now_ms - start <= limit_ms:
        plc.scan()
        if get(plc, output):
            return plc.now_ms - plc.period_ms - start
    return -1


@MODES
def test_t0_k10_is_one_second_and_clears_when_its_input_drops(monitored: bool) -> None:
    plc = engine("LD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    assert _on_at(plc, "Y0", 3000) == 1000
    plc.run_scans(50)
    assert get(plc, "T0") == 10  # stops at the set value
    put(plc, "X0", 0)
    plc.scan()
    assert (get(plc, "T0"), get(plc, "Y0")) == (0, 0)


@MODES
def test_six_seconds_three_ways(monitored: bool) -> None:
    # seed 001:95-97: T10 K60, T100 K600 with M1028 on, T127 K6000
    plc = engine("LD X0\nTMR T10 K60\nLD X0\nTMR T100 K600\nLD X0\nTMR T127 K6000\n"
                 "LD T10\nOUT Y0\nLD T100\nOUT Y1\nLD T127\nOUT Y2\nLD X1\nOUT M1028\nEND\n",
                 monitored=monitored)
    put(plc, "X1", 1)
    plc.scan()
    put(plc, "X0", 1)
    plc.run_scans(600)  # the timers start in the first (0 ms), then 599 x 10 ms = 5.99 s
    assert [get(plc, f"Y{k}") for k in range(3)] == [0, 0, 0]
    plc.scan()  # 6.00 s
    assert [get(plc, f"Y{k}") for k in range(3)] == [1, 1, 1]
    assert (get(plc, "T10"), get(plc, "T100"), get(plc, "T127")) == (60, 600, 6000)


def test_t64_counts_100_ms_without_m1028() -> None:
    plc = engine("LD X0\nTMR T64 K10\nLD T64\nOUT Y0\nEND\n")
    put(plc, "X0", 1)
    assert _on_at(plc, "Y0", 3000) == 1000


def test_a_preset_in_a_register() -> None:
    plc = engine("LD X0\nTMR T5 D20\nLD T5\nOUT Y0\nEND\n")
    put(plc, "D20", 3)
    put(plc, "X0", 1)
    assert _on_at(plc, "Y0", 3000) == 300


@MODES
def test_a_timer_skipped_by_cj_holds_and_goes_on(monitored: bool) -> None:
    # seed 003:178-186: timers in a skipped part stop counting and go on when the jump is off
    plc = engine("LD X1\nCJ P1\nLD X0\nTMR T0 K20\nP1\nLD T0\nOUT Y0\nEND\n",
                 monitored=monitored)
    put(plc, "X0", 1)
    plc.run_scans(101)  # 1.0 s counted
    assert get(plc, "T0") == 10
    put(plc, "X1", 1)
    plc.run_scans(300)  # skipped: holds
    assert get(plc, "T0") == 10
    put(plc, "X1", 0)
    plc.run_scans(99)
    assert get(plc, "Y0") == 0
    plc.run_scans(2)
    assert get(plc, "Y0") == 1


@MODES
def test_cnt_counts_edges_stops_at_its_value_and_resets(monitored: bool) -> None:
    plc = engine("LD X0\nCNT C0 K10\nLD C0\nOUT Y0\nLD X1\nRST C0\nEND\n", monitored=monitored)
    for _ in range(9):
        put(plc, "X0", 1)
        plc.run_scans(3)  # held: counts once
        put(plc, "X0", 0)
        plc.scan()
    assert (get(plc, "C0"), get(plc, "Y0")) == (9, 0)
    for _ in range(3):
        put(plc, "X0", 1)
        plc.scan()
        put(plc, "X0", 0)
        plc.scan()
    assert (get(plc, "C0"), get(plc, "Y0")) == (10, 1)
    put(plc, "X1", 1)
    plc.scan()  # RST after the OUT: Y0 follows in the next scan
    assert (get(plc, "C0"), get(plc, "Y0")) == (0, 1)
    plc.scan()
    assert (get(plc, "C0"), get(plc, "Y0")) == (0, 0)


@MODES
def test_dcnt_counts_up_and_down_by_m1200(monitored: bool) -> None:
    plc = engine("LD X1\nOUT M1200\nLD X0\nDCNT C200 K2\nLD C200\nOUT Y0\nLD X2\nRST C200\n"
                 "END\n", monitored=monitored)
    for _ in range(3):
        put(plc, "X0", 1)
        plc.scan()
        put(plc, "X0", 0)
        plc.scan()
    assert (get(plc, "C200"), get(plc, "Y0")) == (3, 1)
    put(plc, "X1", 1)
    for _ in range(5):
        put(plc, "X0", 1)
        plc.scan()
        put(plc, "X0", 0)
        plc.scan()
    assert (get(plc, "C200"), get(plc, "Y0")) == (-2, 0)
    put(plc, "C200", 2**31 - 1)
    put(plc, "X1", 0)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "C200") == -(2**31)  # wraps
    put(plc, "X2", 1)
    plc.scan()
    assert get(plc, "C200") == 0


def test_rst_of_a_timer_and_a_register() -> None:
    plc = engine("LD X0\nTMR T3 K5\nLD X1\nRST T3\nRST D7\nLD T3\nOUT Y0\nEND\n")
    put(plc, "D7", 99)
    put(plc, "X0", 1)
    plc.run_scans(60)
    assert (get(plc, "T3"), get(plc, "Y0")) == (5, 1)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "T3"), get(plc, "Y0"), get(plc, "D7")) == (0, 0, 0)
    put(plc, "X1", 0)
    plc.run_scans(60)
    assert (get(plc, "T3"), get(plc, "Y0")) == (5, 1)  # runs again from 0
