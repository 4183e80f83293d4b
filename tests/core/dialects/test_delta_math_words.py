"""Delta CML, RCR/RCL, BON, MEAN, SQR, ABS, SWAP, GRY/GBIN (D forms), WSFR/WSFL, SFWR/SFRD,
fast and monitored; the FIFO (state in memory, pulse forms) skips exactly."""

from __future__ import annotations

import pytest

from tests.core.dialects.conftest import engine, get, put
from tests.core.dialects.test_delta_words32 import same_when_skipping

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


@MODES
def test_complement_rotation_through_carry_and_bits(monitored: bool) -> None:
    plc = engine("LD X0\nCML D0 D1\nDCML D2 D4\nRCR D6 K1\nRCL D7 K2\nDRCL D8 K1\nBON D0 M0 K3\n"
                 "DBON D2 M1 K20\nEND\n", monitored=monitored)
    put(plc, "D0", 0x0F08)
    put(plc, "D2:4", 0x0010_0000)
    put(plc, "D6", 0x0003)
    put(plc, "D7", -16384)  # 0xC000
    put(plc, "D8:4", -(2**31))  # 0x80000000
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D1") & 0xFFFF == 0xF0F7
    assert get(plc, "D4:4") & 0xFFFF_FFFF == 0xFFEF_FFFF
    # RCR 0x0003 by 1, carry 0: 0x0001, carry 1; RCL 0xC000 by 2 with that carry: 0x0002 + 1
    assert get(plc, "D6") == 1
    assert get(plc, "D7") == 0b11  # bit 15 went to the carry, then the carry (1) came in
    # DRCL 0x80000000 by 1 with the carry RCL left (1): 0x00000001, carry 1
    assert get(plc, "D8:4") == 1 and get(plc, "M1022") == 1
    assert (get(plc, "M0"), get(plc, "M1")) == (1, 1)


@MODES
def test_mean_root_absolute_swap_gray(monitored: bool) -> None:
    plc = engine("LD X0\nMEAN D0 D10 K3\nDMEAN D20 D26 K2\nSQR D11 D12\nDSQR D30 D32\n"
                 "SQR D34 D35\nABS D13\nDABS D36\nSWAP D14\nDSWAP D38\nGRY K10 D15\n"
                 "GBIN D15 D16\nEND\n", monitored=monitored)
    for k, number in enumerate((3, 4, -8)):
        put(plc, f"D{k}", number)
    put(plc, "D20:4", 100000)
    put(plc, "D22:4", 300001)
    put(plc, "D30:4", 10**9)
    put(plc, "D34", -4)
    put(plc, "D35", 77)
    put(plc, "D13", -32768)
    put(plc, "D36:4", -5)
    put(plc, "D14", 0x1234)
    put(plc, "D38:4", 0x1234_5678)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D10") == -0  # (3 + 4 - 8) / 3 toward zero
    assert get(plc, "D26:4") == 200000
    assert get(plc, "D12") == 0 and get(plc, "D32:4") == 31622
    assert get(plc, "D35") == 77 and get(plc, "M1067") == 1  # SQR of a negative: kept
    assert (get(plc, "D13"), get(plc, "D36:4")) == (-32768, 5)
    assert get(plc, "D14") == 0x3412
    assert get(plc, "D38:4") == 0x3412_7856
    assert (get(plc, "D15"), get(plc, "D16")) == (0b1111, 10)  # 10 = 0b1010: Gray 0b1111


@MODES
def test_word_shifts(monitored: bool) -> None:
    plc = engine("LD X0\nWSFRP D0 D10 K4 K2\nWSFLP K9 D20 K3 K1\nEND\n", monitored=monitored)
    put(plc, "D0", 100)
    put(plc, "D1", 101)
    for k in range(4):
        put(plc, f"D{10 + k}", k + 1)
        put(plc, f"D{20 + k}", k + 1)
    put(plc, "X0", 1)
    plc.scan()
    plc.scan()  # pulse forms: once
    assert [get(plc, f"D{10 + k}") for k in range(4)] == [3, 4, 100, 101]
    assert [get(plc, f"D{20 + k}") for k in range(4)] == [9, 1, 2, 4]


@MODES
def test_fifo_write_then_read(monitored: bool) -> None:
    plc = engine("LD X0\nSFWRP D0 D10 K4\nLD X1\nSFRDP D10 D20 K4\nEND\n", monitored=monitored)

    def pulse(device: str) -> None:
        put(plc, device, 1)
        plc.scan()
        put(plc, device, 0)
        plc.scan()

    for number in (7, 8, 9, 10):
        put(plc, "D0", number)
        pulse("X0")
    assert [get(plc, f"D{10 + k}") for k in range(4)] == [3, 7, 8, 9]  # full at 3: 10 not in
    assert get(plc, "M1022") == 1
    pulse("X1")
    assert get(plc, "D20") == 7 and [get(plc, f"D{10 + k}") for k in range(3)] == [2, 8, 9]
    pulse("X1")
    pulse("X1")
    assert get(plc, "D20") == 9 and get(plc, "D10") == 0 and get(plc, "M1020") == 1


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_fifo_and_rotations_skip_exactly(monitored: bool) -> None:
    assert same_when_skipping("LD X0\nSFWRP D0 D10 K5\nLD X1\nSFRDP D10 D20 K5\nLD X2\n"
                              "RCLP D1 K1\nLD X3\nMEAN D10 D30 K5\nEND\n", 1500, monitored) > 0


@MODES
def test_smov_moves_bcd_digits(monitored: bool) -> None:
    plc = engine("LD X0\nSMOV D0 K4 K2 D1 K3\nSMOV D2 K1 K1 D3 K4\nSMOV K10000 K1 K1 D4 K1\n"
                 "END\n", monitored=monitored)
    put(plc, "D0", 1234)
    put(plc, "D1", 5678)
    put(plc, "D2", 9)
    put(plc, "D3", 0)
    put(plc, "D4", 7)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D1") == 5128  # digits 4, 3 of 1234 (1, 2) to digits 3, 2 of 5678
    assert get(plc, "D3") == 9000
    assert get(plc, "D4") == 7 and get(plc, "M1067") == 1  # 10000 is not 4 digits


@MODES
def test_bit_of_a_word_out_set_reset(monitored: bool) -> None:
    plc = engine("LD X0\nBOUT D0 K3\nLD X1\nBSET D1 K15\nDBSET D2 K20\nLD X2\nBRST D1 K0\n"
                 "END\n", monitored=monitored)
    put(plc, "D1", 1)
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "D0"), get(plc, "D1") & 0xFFFF, get(plc, "D2:4")) == (8, 0x8001, 1 << 20)
    put(plc, "X0", 0)
    put(plc, "X2", 1)
    plc.scan()
    assert (get(plc, "D0"), get(plc, "D1") & 0xFFFF) == (0, 0x8000)


@MODES
def test_scal_and_sclp_scale(monitored: bool) -> None:
    plc = engine("LD X0\nSCAL D0 K500 K-10 D1\nSCLP D2 D10 D3\nDSCLP D20 D30 D40\n"
                 "SCAL K32767 K2000 K0 D4\nEND\n", monitored=monitored)
    put(plc, "D0", 101)
    put(plc, "D2", 2000)  # a 0-4000 input scaled to 0-1000
    for k, number in enumerate((4000, 0, 1000, 0)):
        put(plc, f"D{10 + k}", number)
    put(plc, "D20:4", 50000)  # 0-100000 to -500..500
    for k, number in enumerate((100000, 0, 500, -500)):
        put(plc, f"D{30 + 2 * k}:4", number)
    put(plc, "D4", 3)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "D1"), get(plc, "D3"), get(plc, "D40:4")) == (40, 500, 0)  # 50.5 - 10
    assert get(plc, "D4") == 3 and get(plc, "M1067") == 1  # 65534 is out of range
