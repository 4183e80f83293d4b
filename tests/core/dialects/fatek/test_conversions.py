"""FUN 20 →BCD and FUN 21 →BIN as the FBs-PLC manual's FUN 20 page defines them: D the
conversion of S; out of range (or a nibble above 9) FO0 ERR and D kept; P and D forms."""

from __future__ import annotations

from ladderworks.core.plc.functions.fatek_convert import from_bcd, to_bcd
from tests.core.dialects.fatek.test_programs import engine, get, put


def test_the_manuals_example_and_back() -> None:
    plc = engine("ORG X0\nFUN 20 BCD\n S : 9999\n D : R0\nORG X0\nFUN 21 BIN\n S : R0\n"
                 " D : R1\n")
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "R0") & 0xFFFF == 0x9999 and get(plc, "R1") == 9999


def test_out_of_range_sets_err_and_keeps_d() -> None:
    plc = engine("ORG X0\nFUN 20 BCD\n S : R5\n D : R0\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 21 BIN\n S : R6\n D : R1\nFO 0\nOUT Y1\n")
    put(plc, "R0", 77)
    put(plc, "R1", 88)
    put(plc, "R5", -1)
    put(plc, "R6", 0x12A4)  # A is no BCD digit
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "R0"), get(plc, "Y1"), get(plc, "R1")) == (1, 77, 1, 88)
    put(plc, "R5", 42)
    put(plc, "R6", 0x0042)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "R0"), get(plc, "Y1"), get(plc, "R1")) == (0, 0x42, 0, 42)


def test_the_pulse_and_32_bit_forms() -> None:
    plc = engine("ORG X0\nFUN 20DP BCD\n S : R10\n D : R0\n")
    put(plc, "R10", 1234)
    put(plc, "R11", 1)  # R10-R11: 65536 + 1234 = 66770
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "R0") & 0xFFFF, get(plc, "R1")) == (0x6770, 0x6)
    put(plc, "R10", 5)
    plc.scan()  # P form: EN still 1, no new conversion
    assert get(plc, "R0") & 0xFFFF == 0x6770


def test_the_codes() -> None:
    assert to_bcd(0, 4) == 0 and to_bcd(9999, 4) == 0x9999 and to_bcd(10000, 4) is None
    assert to_bcd(-1, 4) is None and to_bcd(99999999, 8) == 0x99999999
    assert from_bcd(0x1234, 4) == 1234 and from_bcd(0x123F, 4) is None
