"""Delta contacts, coils, blocks, stack operations and edges, in fast and monitored mode."""

from __future__ import annotations

import itertools

import pytest

from tests.core.dialects.conftest import engine, get, put

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


@MODES
def test_seed_latch_with_ani(monitored: bool) -> None:
    plc = engine("LD X0\nOR Y0\nANI X1\nOUT Y0\nEND\n", monitored=monitored)
    plc.scan()
    assert get(plc, "Y0") == 0
    put(plc, "X0", 1)
    plc.scan()
    put(plc, "X0", 0)
    plc.run_scans(3)
    assert get(plc, "Y0") == 1
    put(plc, "X1", 1)
    plc.scan()
    assert get(plc, "Y0") == 0


@MODES
def test_anb_orb_blocks_on_every_input(monitored: bool) -> None:
    # Y0 = (X0 + X1) * (X2 * X3 + !X4); Y1 = X0 * X1 + X2 * !X3
    plc = engine("LD X0\nOR X1\nLD X2\nAND X3\nORI X4\nANB\nOUT Y0\n"
                 "LD X0\nAND X1\nLD X2\nANI X3\nORB\nOUT Y1\nEND\n", monitored=monitored)
    for bits in itertools.product((0, 1), repeat=5):
        for k, value in enumerate(bits):
            put(plc, f"X{k}", value)
        plc.scan()
        x0, x1, x2, x3, x4 = bits
        assert get(plc, "Y0") == int((x0 or x1) and ((x2 and x3) or not x4)), bits
        assert get(plc, "Y1") == int((x0 and x1) or (x2 and not x3)), bits


@MODES
def test_mps_mrd_mpp_branch_outputs(monitored: bool) -> None:
    plc = engine("LD X0\nMPS\nAND X1\nOUT Y0\nMRD\nAND X2\nOUT Y1\nMPP\nANI X3\nOUT Y2\n"
                 "LD X4\nOUT Y3\nEND\n", monitored=monitored)
    for bits in itertools.product((0, 1), repeat=5):
        for k, value in enumerate(bits):
            put(plc, f"X{k}", value)
        plc.scan()
        x0, x1, x2, x3, x4 = bits
        assert [get(plc, f"Y{k}") for k in range(4)] == [
            x0 & x1, x0 & x2, x0 & (1 - x3), x4], bits


@MODES
def test_set_rst_inv_and_octal_outputs(monitored: bool) -> None:
    plc = engine("LD X0\nSET M100\nLD X1\nRST M100\nLD M100\nOUT Y17\nINV\nOUT Y20\n"
                 "LD X2\nSET S3\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    plc.scan()
    put(plc, "X0", 0)
    plc.scan()
    assert (get(plc, "M100"), get(plc, "Y17"), get(plc, "Y20")) == (1, 1, 0)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "M100"), get(plc, "Y17"), get(plc, "Y20")) == (0, 0, 1)
    put(plc, "X2", 1)
    plc.scan()
    assert get(plc, "S3") == 1


@MODES
def test_edge_contacts_are_on_for_one_scan(monitored: bool) -> None:
    plc = engine("LDP X0\nOUT Y0\nLDF X0\nOUT Y1\nLD X1\nANDP X2\nOUT Y2\nLD X1\nORF X3\n"
                 "OUT Y3\nLD X4\nPLS M0\nLD X4\nPLF M1\nEND\n", monitored=monitored)
    seen = []
    for x0 in (0, 1, 1, 1, 0, 0):
        put(plc, "X0", x0)
        put(plc, "X4", x0)
        plc.scan()
        seen.append((get(plc, "Y0"), get(plc, "Y1"), get(plc, "M0"), get(plc, "M1")))
    assert seen == [(0, 0, 0, 0), (1, 0, 1, 0), (0, 0, 0, 0), (0, 0, 0, 0), (0, 1, 0, 1),
                    (0, 0, 0, 0)]
    put(plc, "X2", 1)
    plc.scan()
    assert get(plc, "Y2") == 0  # X1 off
    put(plc, "X2", 0)
    plc.scan()
    put(plc, "X1", 1)
    put(plc, "X2", 1)
    plc.scan()
    assert get(plc, "Y2") == 1
    plc.scan()
    assert get(plc, "Y2") == 0
    put(plc, "X1", 0)
    put(plc, "X3", 1)
    plc.scan()
    put(plc, "X3", 0)
    plc.scan()
    assert get(plc, "Y3") == 1
    plc.scan()
    assert get(plc, "Y3") == 0


@MODES
def test_edge_contact_in_the_middle_of_a_rung_pushes(monitored: bool) -> None:
    plc = engine("LD X0\nLDP X1\nOR X2\nANB\nOUT Y0\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.scan()
    assert get(plc, "Y0") == 1
    plc.scan()
    assert get(plc, "Y0") == 0


def test_special_relays() -> None:
    plc = engine("LD M1000\nOUT Y0\nLD M1002\nOUT Y1\nLD M1013\nOUT Y2\nLD M1014\nOUT Y3\nEND\n",
                 period_ms=100)
    plc.scan()
    assert [get(plc, f"Y{k}") for k in range(4)] == [1, 1, 1, 1]
    plc.run_scans(5)  # 500 ms
    assert [get(plc, f"Y{k}") for k in range(4)] == [1, 0, 0, 1]
    plc.run_scans(299)  # the last scan at 30.4 s
    assert [get(plc, f"Y{k}") for k in range(4)] == [1, 0, 1, 0]
    plc.cold_start()
    plc.scan()
    assert get(plc, "Y1") == 1
