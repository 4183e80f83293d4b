"""FUN 23 DIV48 and FUN 31 CRC16 as the FBs manual's pages 7-2 and 7-10 give them, fast and
monitored: 48-bit operands of three registers, U/S, D=0 and ERR; the Modbus RTU CRC of the
registers' low bytes, its high byte in D and its low byte after it."""

from __future__ import annotations

from tests.core.dialects.fatek.test_families import MODES, get, plc, put, scan


def _put48(engine: object, first: int, value: int) -> None:
    for k in range(3):
        put(engine, f"R{first + k}", (value >> (16 * k)) & 0xFFFF)  # type: ignore[arg-type]


def _get48(engine: object, first: int) -> int:
    value = sum((get(engine, f"R{first + k}") & 0xFFFF) << (16 * k)  # type: ignore[arg-type]
                for k in range(3))
    return value - (1 << 48) if value >> 47 else value


@MODES
def test_div48_as_the_manuals_example_signed_unsigned_and_by_zero(monitored: bool) -> None:
    engine = plc("ORG X0\nLD X1\nFUN 23P DIV48\n Sa : R0\n Sb : R3\n D : R6\n"
                 "FO 0\nOUT Y0\nFO 1\nOUT Y1\n", monitored)
    _put48(engine, 0, 2147483647)
    _put48(engine, 3, 1234567)
    scan(engine, X0=1)
    assert (_get48(engine, 6), get(engine, "Y0"), get(engine, "Y1")) == (1739, 0, 0)
    _put48(engine, 0, -10)
    _put48(engine, 3, 3)
    scan(engine, X0=0)
    scan(engine, X0=1)  # U/S = 0: signed, truncated toward 0
    assert _get48(engine, 6) == -3
    scan(engine, X0=0)
    scan(engine, X0=1, X1=1)  # U/S = 1: unsigned
    assert _get48(engine, 6) == ((1 << 48) - 10) // 3
    _put48(engine, 0, 2)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (_get48(engine, 6), get(engine, "Y0")) == (0, 1)  # D=0
    _put48(engine, 3, 0)
    _put48(engine, 6, 77)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (_get48(engine, 6), get(engine, "Y0"), get(engine, "Y1")) == (77, 0, 1)  # ERR


@MODES
def test_crc16_of_a_modbus_frame_and_the_frame_with_its_crc(monitored: bool) -> None:
    """Modbus RTU `01 03 00 00 00 01` has the CRC 0x0A84 (sent `84 0A`); the frame with it
    gives 0 (D=0), as the manual's page says a received frame does."""
    engine = plc("ORG X0\nFUN 31P CRC16\n MD : 0\n S : R0\n N : R20\n D : R10\n"
                 "FO 0\nOUT Y0\nFO 1\nOUT Y1\n", monitored)
    for k, byte in enumerate((0x01, 0x03, 0x00, 0x00, 0x00, 0x01, 0x84, 0x0A)):
        put(engine, f"R{k}", 0x5500 | byte)  # the high bytes do not count
    put(engine, "R20", 6)
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "R11"), get(engine, "Y0")) == (0x0A, 0x84, 0)
    put(engine, "R20", 8)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "R11"), get(engine, "Y0")) == (0, 0, 1)
    put(engine, "R20", 0)
    put(engine, "R10", 9)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "Y0"), get(engine, "Y1")) == (9, 0, 1)
