"""BCD and binary arithmetic, NUME, NUMEB: overflow, negative, divide by zero, flags, RST."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.arithmetic import truncated_division
from ladderworks.core.plc.memory import Memory
from tests.core.functions.conftest import Box, at


@pytest.mark.parametrize(("name", "a", "b", "want"), [
    ("ADD", 45, 54, 99), ("ADD", 50, 50, None), ("SUB", 50, 49, 1), ("SUB", 49, 50, None),
    ("MUL", 9, 11, 99), ("MUL", 10, 10, None), ("DIV", 99, 10, 9), ("DIV", 5, 0, None),
])
def test_bcd_two_digits_constant(ctx: FunctionContext, box, name: str, a: int, b: int,
                                 want: int | None) -> None:
    ctx.memory.write_bcd(at("R100"), a, 1)
    ctx.memory.write_bcd(at("R102"), 11, 1)
    w1 = box(name, 0, "R100", b, "R102")(0, 0, 1)
    assert w1 is (want is None)
    assert ctx.memory.read_bcd(at("R102"), 1) == (11 if want is None else want)


@pytest.mark.parametrize(("name", "a", "b", "want"), [
    ("ADD", 4500, 5499, 9999), ("ADD", 5000, 5000, None), ("SUB", 1000, 1, 999),
    ("MUL", 99, 101, 9999), ("MUL", 100, 100, None), ("DIV", 9999, 100, 99),
    ("DIV", 1, 0, None),
])
def test_bcd_four_digits_address(ctx: FunctionContext, box, name: str, a: int, b: int,
                                 want: int | None) -> None:
    ctx.memory.write_bcd(at("D0"), a, 2)
    ctx.memory.write_bcd(at("D2"), b, 2)
    w1 = box(name, 1, "D0", "D2", "D4")(1, 0, 1)
    assert w1 is (want is None)
    assert ctx.memory.read_bcd(at("D4"), 2) == (0 if want is None else want)


def test_bcd_invalid_digit_and_bad_constant(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("R100"), 0x1F)
    assert box("ADD", 0, "R100", 1, "R102")(0, 0, 1) is True
    ctx.memory.write_bcd(at("R100"), 1, 1)
    assert box("ADD", 0, "R100", 100, "R102")(0, 0, 1) is True  # 3 digits with BYT = 0
    assert box("ADD", 0, "R100", -1, "R102")(0, 0, 1) is True  # BCD has no sign


def test_bcd_error_held_until_rst(ctx: FunctionContext, box) -> None:
    div = box("DIV", 0, "R100", 0, "R102")
    assert div(0, 0, 1) is True
    assert div(0, 0, 0) is True
    assert div(0, 1, 1) is False
    assert div(0, 0, 0) is False


def test_truncated_division() -> None:
    assert truncated_division(7, 2) == (3, 1)
    assert truncated_division(-7, 2) == (-3, -1)
    assert truncated_division(7, -2) == (-3, 1)
    assert truncated_division(-7, -2) == (3, -1)


@pytest.mark.parametrize(("name", "width", "a", "b", "want", "flags"), [
    ("ADDB", 1, 100, 27, 127, 0x00), ("ADDB", 1, 100, 28, None, 0x20),
    ("ADDB", 2, -300, 300, 0, 0x01), ("SUBB", 2, -32768, 1, None, 0x20),
    ("SUBB", 4, 5, 7, -2, 0x02), ("MULB", 2, 181, 181, 32761, 0x00),
    ("MULB", 2, 182, 181, None, 0x20), ("MULB", 4, -46341, 46341, None, 0x20),
    ("DIVB", 1, -128, -1, None, 0x20), ("DIVB", 2, 1000, 0, None, 0x20),
    ("DIVB", 4, -99_999_999, 10, -9_999_999, 0x02),
])
def test_binary(ctx: FunctionContext, box, name: str, width: int, a: int, b: int,
                want: int | None, flags: int) -> None:
    ctx.memory.write(at("D0"), a, width)
    ctx.memory.write(at("D4"), b, width)
    ctx.memory.write(at("D8"), 55, width)
    w1 = box(name, 1000 + width, "D0", "D4", "D8")(0, 1)
    assert w1 is (want is None)
    assert ctx.memory.read(at("D8"), width, signed=True) == (55 if want is None else want)
    assert ctx.memory.read(at("R9000")) == flags
    # the same with b a constant
    ctx.memory.write(at("R9000"), 0)
    assert box(name, width, "D0", b, "D8")(0, 1) is (want is None)
    assert ctx.memory.read(at("R9000")) == flags


def test_divb_remainder_in_r9002(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("D0"), -1003, 2)
    assert box("DIVB", 2, "D0", 10, "D8")(0, 1) is False
    assert ctx.memory.read(at("D8"), 2, signed=True) == -100
    assert ctx.memory.read(at("R9002"), 2, signed=True) == -3
    ctx.memory.write(at("D0"), 123456789, 4)
    assert box("DIVB", 4, "D0", 1000, "D8")(0, 1) is False
    assert ctx.memory.read(at("R9002"), 4) == 789


def test_binary_rst_and_act_off(ctx: FunctionContext, box) -> None:
    addb = box("ADDB", 1, "D0", 200, "D8")
    ctx.memory.write(at("R9000"), 0x77)
    assert addb(0, 0) is False
    assert ctx.memory.read(at("R9000")) == 0x77  # ACT = 0: flags untouched
    assert addb(0, 1) is True  # 0 + 200 overflows a signed byte
    assert addb(0, 0) is True
    assert addb(1, 1) is False


def test_nume_and_numeb(ctx: FunctionContext, box) -> None:
    box("NUME", 12, "R0")(0, 0)
    assert ctx.memory.read(at("R0")) == 0
    box("NUME", 12, "R0")(0, 1)
    assert ctx.memory.read(at("R0")) == 0x12
    box("NUME", 1234, "R0")(1, 1)
    assert ctx.memory.read(at("R0"), 2) == 0x1234
    box("NUME", 1234, "R2")(0, 1)  # 4 digits do not fit 1 byte: nothing written
    assert ctx.memory.read(at("R2")) == 0
    box("NUMEB", 2, -2, "D0")(1)
    assert ctx.memory.read(at("D0"), 2, signed=True) == -2
    box("NUMEB", 1, 300, "D4")(1)  # does not fit: nothing written
    assert ctx.memory.read(at("D4")) == 0
    box("NUMEB", 4, 99_999_999, "D4")(0)
    assert ctx.memory.read(at("D4"), 4) == 0
    box("NUMEB", 4, 99_999_999, "D4")(1)
    assert ctx.memory.read(at("D4"), 4) == 99_999_999


@given(name=st.sampled_from(["ADD", "SUB", "MUL", "DIV"]), byt=st.booleans(),
       a=st.integers(0, 9999), b=st.integers(0, 9999))
def test_property_bcd_matches_integers(name: str, byt: bool, a: int, b: int) -> None:
    ctx = FunctionContext(Memory())
    width = 2 if byt else 1
    limit = 10 ** (2 * width) - 1
    a, b = a % (limit + 1), b % (limit + 1)
    ctx.memory.write_bcd(at("D0"), a, width)
    ctx.memory.write_bcd(at("D2"), b, width)
    exact = {"ADD": a + b, "SUB": a - b, "MUL": a * b, "DIV": a // b if b else None}[name]
    error = exact is None or not 0 <= exact <= limit
    assert Box(ctx, name, 1, "D0", "D2", "D4")(byt, 0, 1) is error
    assert ctx.memory.read_bcd(at("D4"), width) == (0 if error else exact)


@given(name=st.sampled_from(["ADDB", "SUBB", "MULB", "DIVB"]), width=st.sampled_from([1, 2, 4]),
       data=st.data())
def test_property_binary_matches_integers(name: str, width: int, data: st.DataObject) -> None:
    lo, hi = -(1 << (8 * width - 1)), (1 << (8 * width - 1)) - 1
    a, b = data.draw(st.integers(lo, hi)), data.draw(st.integers(lo, hi))
    ctx = FunctionContext(Memory())
    ctx.memory.write(at("D0"), a, width)
    ctx.memory.write(at("D4"), b, width)
    if name == "DIVB":
        exact = truncated_division(a, b)[0] if b else None
    else:
        exact = {"ADDB": a + b, "SUBB": a - b, "MULB": a * b}[name]
    error = exact is None or not lo <= exact <= hi
    assert Box(ctx, name, 1000 + width, "D0", "D4", "D8")(0, 1) is error
    assert ctx.memory.bit(at("R9000.5")) == error
    if not error:
        assert ctx.memory.read(at("D8"), width, signed=True) == exact
        assert ctx.memory.bit(at("R9000.1")) == (exact < 0)
        assert ctx.memory.bit(at("R9000.0")) == (exact == 0)
        if name == "DIVB":
            assert exact * b + ctx.memory.read(at("R9002"), width, signed=True) == a
