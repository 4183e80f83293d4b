"""COD, CODB, DCNV, DCNVB: table look-up and binary/BCD conversion, errors, RST, ACT off."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at

SEED_TABLE = (27, 35, 56, 137)  # the seed's COD picture: index 3 gives 137


def test_cod_seed_example_four_digits(ctx: FunctionContext, box) -> None:
    cod = box("COD", 4, "R10", "R12", *SEED_TABLE)
    ctx.memory.write_bcd(at("R10"), 3, 1)
    assert cod(1, 0, 1) is False
    assert ctx.memory.read(at("R12"), 2) == 0x0137


def test_cod_two_digits_and_entry_too_big(ctx: FunctionContext, box) -> None:
    cod = box("COD", 4, "R10", "R12", *SEED_TABLE)
    ctx.memory.write_bcd(at("R10"), 1, 1)
    assert cod(0, 0, 1) is False
    assert ctx.memory.read(at("R12"), 2) == 0x35
    ctx.memory.write_bcd(at("R10"), 3, 1)  # 137 does not fit 2 digits
    assert cod(0, 0, 1) is True
    assert ctx.memory.read(at("R12"), 2) == 0x35


def test_cod_index_past_table_latches_until_rst(ctx: FunctionContext, box) -> None:
    cod = box("COD", 4, "R10", "R12", *SEED_TABLE)
    ctx.memory.write_bcd(at("R10"), 4, 1)  # rows are 0..3
    assert cod(1, 0, 1) is True
    assert ctx.memory.read(at("R12"), 2) == 0
    assert cod(1, 0, 0) is True  # ACT = 0: W1 unchanged
    assert cod(1, 1, 0) is False  # RST clears it
    assert cod(1, 1, 1) is False  # RST has priority over ACT
    ctx.memory.write(at("R10"), 0x0B)  # invalid BCD index
    assert cod(1, 0, 1) is True
    ctx.memory.write_bcd(at("R10"), 0, 1)
    assert cod(1, 0, 1) is False  # a good execution clears the error
    assert ctx.memory.read_bcd(at("R12"), 2) == 27


def test_codb_binary_table(ctx: FunctionContext, box) -> None:
    codb = box("CODB", 2, 3, "R10", "D0", 1000, -5, 32767)
    for row, value in enumerate((1000, -5, 32767)):
        ctx.memory.write(at("R10"), row)
        assert codb(0, 1) is False
        assert ctx.memory.read(at("D0"), 2, signed=True) == value
    ctx.memory.write(at("R10"), 3)
    assert codb(0, 1) is True
    assert codb(0, 0) is True
    assert codb(1, 0) is False


def test_codb_entry_too_big_for_one_byte(ctx: FunctionContext, box) -> None:
    codb = box("CODB", 1, 2, "R10", "D0", 255, 256)
    assert codb(0, 1) is False
    assert ctx.memory.read(at("D0")) == 255
    ctx.memory.write(at("R10"), 1)
    assert codb(0, 1) is True
    assert ctx.memory.read(at("D0")) == 255


def test_dcnv_binary_to_bcd(ctx: FunctionContext, box) -> None:
    dcnv = box("DCNV", "R0", "R2")
    ctx.memory.write(at("R0"), 99)
    assert dcnv(0, 0, 0, 1) is False
    assert ctx.memory.read(at("R2")) == 0x99
    ctx.memory.write(at("R0"), 100)  # 3 digits do not fit 1 byte
    assert dcnv(0, 0, 0, 1) is True
    assert ctx.memory.read(at("R2")) == 0x99
    assert dcnv(0, 0, 0, 0) is True
    assert dcnv(0, 0, 1, 0) is False
    ctx.memory.write(at("R0"), 9999, 2)
    assert dcnv(1, 0, 0, 1) is False
    assert ctx.memory.read(at("R2"), 2) == 0x9999
    ctx.memory.write(at("R0"), 10000, 2)
    assert dcnv(1, 0, 0, 1) is True


def test_dcnv_bcd_to_binary_and_invalid_digit(ctx: FunctionContext, box) -> None:
    dcnv = box("DCNV", "R0", "R2")
    ctx.memory.write(at("R0"), 0x1234, 2)
    assert dcnv(1, 1, 0, 1) is False
    assert ctx.memory.read(at("R2"), 2) == 1234
    ctx.memory.write(at("R0"), 0x12F4, 2)
    assert dcnv(1, 1, 0, 1) is True
    assert ctx.memory.read(at("R2"), 2) == 1234


def test_dcnvb_binary_to_bcd_sign_in_r9000(ctx: FunctionContext, box) -> None:
    dcnvb = box("DCNVB", 4, "D0", "D4")
    ctx.memory.write(at("D0"), -12345678, 4)
    assert dcnvb(0, 0, 0, 1) is False
    assert ctx.memory.read(at("D4"), 4) == 0x12345678
    assert ctx.memory.bit(at("R9000.1")) == 1  # negative
    ctx.memory.write(at("D0"), 100_000_000, 4)  # 9 digits
    assert dcnvb(0, 0, 0, 1) is True
    assert ctx.memory.bit(at("R9000.5")) == 1
    ctx.memory.write(at("D0"), 0, 4)
    assert dcnvb(0, 0, 0, 1) is False
    assert ctx.memory.read(at("R9000")) == 0x01  # zero


def test_dcnvb_bcd_to_binary_with_sin(ctx: FunctionContext, box) -> None:
    dcnvb = box("DCNVB", 1, "D0", "D4")
    ctx.memory.write(at("D0"), 0x99)
    assert dcnvb(1, 1, 0, 1) is False
    assert ctx.memory.read(at("D4"), 1, signed=True) == -99
    assert ctx.memory.bit(at("R9000.1")) == 1
    assert dcnvb(0, 1, 0, 1) is False
    assert ctx.memory.read(at("D4"), 1, signed=True) == 99
    ctx.memory.write(at("D0"), 0x9C)  # invalid digit
    assert dcnvb(0, 1, 0, 1) is True
    assert ctx.memory.read(at("D4"), 1, signed=True) == 99
    assert dcnvb(0, 1, 1, 1) is False


def test_codb_table_of_256_rows_with_32_bit_values(ctx: FunctionContext, box) -> None:
    """Issue #17: the manual's rows 00-255, values from -2^31 up to 2^32 - 1."""
    table = [-2**31, 2**32 - 1, *range(2, 255), 2**31 - 1]
    assert len(table) == 256
    codb = box("CODB", 4, 256, "R10", "D0", *table)
    for row, expected in [(0, -2**31), (1, 2**32 - 1), (200, 200), (255, 2**31 - 1)]:
        ctx.memory.write(at("R10"), row)
        assert codb(0, 1) is False
        assert ctx.memory.read(at("D0"), 4) == expected & 0xFFFF_FFFF
    short = box("CODB", 4, 255, "R10", "D0", *table[:255])
    ctx.memory.write(at("R10"), 255)
    assert short(0, 1) is True  # row 255 of a 255-row table
