"""Delta floating point (FLT, INT, DEMOV, DEADD ... DEZCP), FROM/TO and PLSY, fast and
monitored; PLSY's time-driven count skips exactly."""

from __future__ import annotations

import struct

import pytest

from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.plc.functions.delta_modules import register_of
from tests.core.dialects.conftest import engine, get, put
from tests.core.dialects.test_delta_words32 import pair_of, same_when_skipping
from tests.core.plc.test_skipping import differences

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


def single(number: float) -> int:
    """The signed 32 bits of `number` as an IEEE single."""
    return int.from_bytes(struct.pack("<f", number), "little", signed=True)


def real(raw: int) -> float:
    """The single whose bits are `raw`."""
    return float(struct.unpack("<f", (raw & 0xFFFF_FFFF).to_bytes(4, "little"))[0])


@MODES
def test_flt_int_and_float_arithmetic(monitored: bool) -> None:
    plc = engine("LD X0\nFLT D0 D10\nDFLT D2 D12\nDEADD D10 K1 D14\nDESUB D10 D12 D16\n"
                 "DEMUL D12 K-3 D18\nDEDIV D10 K4 D20\nINT D20 D22\nDINT D18 D24\n"
                 "DEMOV K7 D26\nEND\n", monitored=monitored)
    put(plc, "D0", -7)
    put(plc, "D2:4", 100000)
    put(plc, "X0", 1)
    plc.scan()
    assert real(get(plc, "D10:4")) == -7.0 and real(get(plc, "D12:4")) == 100000.0
    assert real(get(plc, "D14:4")) == -6.0
    assert real(get(plc, "D16:4")) == -100007.0
    assert real(get(plc, "D18:4")) == -300000.0
    assert real(get(plc, "D20:4")) == -1.75
    assert get(plc, "D22") == -1  # toward zero
    assert get(plc, "D24:4") == -300000
    assert real(get(plc, "D26:4")) == 7.0
    assert get(plc, "D10") & 0xFFFF == single(-7.0) & 0xFFFF  # low word first


@MODES
def test_float_flags_and_errors(monitored: bool) -> None:
    plc = engine("LD X0\nDEDIV D0 K0 D10\nDEMUL D2 D2 D12\nDESUB D4 D4 D14\nINT D6 D16\n"
                 "END\n", monitored=monitored)
    put(plc, "D0:4", single(1.0))
    put(plc, "D10:4", 5)
    put(plc, "D2:4", single(1e30))
    put(plc, "D4:4", single(2.5))
    put(plc, "D6:4", single(1e6))
    put(plc, "D16", 9)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D10:4") == 5 and get(plc, "M1067") == 1  # division by 0: kept
    assert real(get(plc, "D12:4")) == struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]
    assert real(get(plc, "D14:4")) == 0.0 and get(plc, "M1020") == 1  # the last: zero
    assert get(plc, "D16") == 9  # 1e6 is not a 16-bit integer: kept


@MODES
def test_decmp_dezcp(monitored: bool) -> None:
    plc = engine("LD X0\nDECMP D0 D2 M0\nDEZCP K-1 K1 D0 M10\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    for a, b, cmp_bits, zone_bits in [(0.5, 0.25, (1, 0, 0), (0, 1, 0)),
                                      (-1.5, -1.5, (0, 1, 0), (1, 0, 0)),
                                      (2.0, 3.0, (0, 0, 1), (0, 0, 1))]:
        put(plc, "D0:4", single(a))
        put(plc, "D2:4", single(b))
        plc.scan()
        assert tuple(get(plc, f"M{k}") for k in range(3)) == cmp_bits
        assert tuple(get(plc, f"M{k}") for k in range(10, 13)) == zone_bits


@MODES
def test_from_to_move_a_module_s_registers(monitored: bool) -> None:
    plc = engine("LD X0\nTO K0 K1 H0 K1\nTOP K1 K2 D0 K3\nFROM K2 K30 D50 K2\n"
                 "DTO K3 K10 K100000 K1\nDFROM K3 K10 D60 K1\nEND\n", monitored=monitored)
    put(plc, "CR1", 7)  # module 0, CR#1: overwritten with H0
    for k in range(3):
        put(plc, f"D{k}", 10 + k)
    put(plc, "CR230", -5)  # module 2, CR#30: an analog value fed by hand
    put(plc, "CR231", 4000)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "CR1") == 0
    assert [get(plc, f"CR{102 + k}") for k in range(3)] == [10, 11, 12]
    assert (get(plc, "D50"), get(plc, "D51")) == (-5, 4000)
    assert get(plc, "D60:4") == 100000
    assert register_of(2, 30) == DEVICES.word("CR230")[0]


def test_a_register_past_cr99_is_an_operation_error() -> None:
    plc = engine("LD X0\nFROM K0 K98 D0 K4\nEND\n")
    put(plc, "CR98", 1)
    put(plc, "CR99", 2)
    put(plc, "D2", 33)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "D0"), get(plc, "D1"), get(plc, "D2"), get(plc, "M1067")) == (1, 2, 33, 1)


@MODES
def test_plsy_counts_pulses_on_the_clock(monitored: bool) -> None:
    plc = engine("LD X0\nPLSY K100 K50 Y0\nLD X1\nDPLSY K10 K0 Y1\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    plc.step(200)  # 100 Hz: a pulse every 10 ms
    count = get(plc, "D1030:4")
    assert 18 <= count <= 20 and get(plc, "Y0") == 1 and get(plc, "M1029") == 0
    plc.step(400)
    assert get(plc, "D1030:4") == 50 and get(plc, "Y0") == 0 and get(plc, "M1029") == 1
    put(plc, "X0", 0)
    plc.scan()
    assert get(plc, "D1030:4") == 50  # kept
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D1030:4") == 0 and get(plc, "M1029") == 0  # a new run
    put(plc, "X1", 1)
    plc.step(10_000)
    assert 99 <= get(plc, "D1032:4") <= 100 and get(plc, "Y1") == 1  # K0: no end


def test_plsy_skips_exactly_and_wakes_at_each_pulse() -> None:
    full, fast = pair_of("LD X0\nPLSY K3 K7 Y0\nEND\n")
    for engine_ in (full, fast):
        put(engine_, "X0", 1)
    for limit in (500, 1700, 2500, 4000):
        assert full.advance(limit) == fast.advance(limit)
        assert not differences(full, fast), limit
    assert get(fast, "D1030:4") == 7 and fast.skipped > 0


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_modules_and_floats_skip_exactly(monitored: bool) -> None:
    same_when_skipping("LD X0\nPLSY D0 K20 Y0\nLD X1\nFROMP K0 K0 D10 K2\nTO K0 K5 D1 K1\n"
                       "LD X2\nDEADDP D2 K1 D2\nEND\n", 1500, monitored)


@MODES
def test_float_functions_and_degrees(monitored: bool) -> None:
    plc = engine("LD X0\nDESQR K16 D0\nDLN K1 D2\nDEXP K0 D4\nDLOG K10 K1000 D6\nDPOW K2 K10 D8\n"
                 "DSIN D20 D10\nDRAD K180 D12\nDDEG D12 D14\nDLN K0 D16\nEND\n",
                 monitored=monitored)
    put(plc, "D20:4", single(30.0))
    put(plc, "D16:4", 5)
    put(plc, "M1018", 1)  # degrees
    put(plc, "X0", 1)
    plc.scan()
    assert [real(get(plc, f"D{k}:4")) for k in (0, 2, 4, 8)] == [4.0, 0.0, 1.0, 1024.0]
    assert abs(real(get(plc, "D6:4")) - 3.0) < 1e-6
    assert abs(real(get(plc, "D10:4")) - 0.5) < 1e-6
    assert abs(real(get(plc, "D12:4")) - 3.14159265) < 1e-6
    assert abs(real(get(plc, "D14:4")) - 180.0) < 1e-4
    assert get(plc, "D16:4") == 5 and get(plc, "M1067") == 1  # ln 0: kept


@MODES
@pytest.mark.parametrize(("op", "test"), [
    ("=", lambda a, b: a == b), (">", lambda a, b: a > b), ("<", lambda a, b: a < b),
    ("<>", lambda a, b: a != b), ("<=", lambda a, b: a <= b), (">=", lambda a, b: a >= b)])
def test_floating_point_contacts(monitored: bool, op: str, test) -> None:
    plc = engine(f"FLD{op} D0 D2\nOUT Y0\nLD X0\nFAND{op} D0 K-2\nOUT Y1\nLD X0\n"
                 f"FOR{op} D2 K3\nOUT Y2\nEND\n", monitored=monitored)
    for a, b, x0 in [(-2.5, -2.0, 1), (1.5, 1.5, 0), (3.0, -1e10, 1), (-2.0, 3.0, 1)]:
        put(plc, "D0:4", single(a))
        put(plc, "D2:4", single(b))
        put(plc, "X0", x0)
        plc.scan()
        assert get(plc, "Y0") == int(test(a, b))
        assert get(plc, "Y1") == int(x0 and test(a, -2.0))
        assert get(plc, "Y2") == int(x0 or test(b, 3.0))


def test_a_drawn_float_contact_codes_as_a_float_contact() -> None:
    from ladderworks.core.instructions import Combine
    from ladderworks.core.ladder.row_contacts import row_for

    for start, wide in (("DVP.FLD=", "DVP.FAND="), ("DVP.DLD=", "DVP.DAND="),
                        ("DVP.LD=", "DVP.AND=")):
        found = row_for(start, Combine.AND, False)
        assert found is not None and found.name == wide


def test_module_registers_are_listed_in_the_register_table() -> None:
    from ladderworks.core.dialects.delta.tables import TABLES
    from ladderworks.core.dialects.device_tables import Table, device_range

    assert "CR" in TABLES.registers
    assert device_range(Table.REGISTERS, TABLES, DEVICES, "CR110-CR112") == [
        ("CR", 110), ("CR", 111), ("CR", 112)]
