"""Tests for address parsing, canonical spelling and range checks."""

import pytest

from ladderworks.core.address import (
    AREA_SIZES,
    Address,
    AddressError,
    Area,
    format_address,
    parse_address,
)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("X2.1", Address(Area.X, 2, 1)),
        ("A021.0", Address(Area.A, 21, 0)),
        ("A21.0", Address(Area.A, 21, 0)),
        ("R0100", Address(Area.R, 100)),
        ("D10", Address(Area.D, 10)),
        ("r9000.0", Address(Area.R, 9000, 0)),
        ("F001.7", Address(Area.F, 1, 7)),
    ],
)
def test_parse(text: str, expected: Address) -> None:
    assert parse_address(text) == expected


def test_canonical_spelling_drops_leading_zeros() -> None:
    assert format_address(parse_address("A021.0")) == "A21.0"
    assert str(parse_address("R0100")) == "R100"
    assert str(parse_address("G8.4")) == "G8.4"


@pytest.mark.parametrize(
    ("text", "code"),
    [
        ("Q2.1", "unknown-area"),
        ("X2.8", "bit-range"),
        ("X2.10", "bit-range"),
        ("X128.0", "byte-range"),
        ("A100.0", "byte-range"),
        ("2.1", "bad-address"),
        ("X", "bad-address"),
        ("X2.", "bad-address"),
    ],
)
def test_errors_have_codes(text: str, code: str) -> None:
    with pytest.raises(AddressError) as info:
        parse_address(text)
    assert info.value.code == code


def test_bit_and_byte_demands() -> None:
    with pytest.raises(AddressError) as info:
        parse_address("R100", want_bit=True)
    assert info.value.code == "bit-expected"
    with pytest.raises(AddressError) as info:
        parse_address("R100.1", want_bit=False)
    assert info.value.code == "byte-expected"


def test_width_must_fit_in_area() -> None:
    last = AREA_SIZES[Area.D] - 4
    assert parse_address(f"D{last}", width=4).byte == last
    with pytest.raises(AddressError):
        parse_address(f"D{last + 1}", width=4)


def test_result_register() -> None:
    assert parse_address("R9000").is_result_register()
    assert parse_address("R9005.7").is_result_register()
    assert not parse_address("R9006").is_result_register()
    assert not parse_address("D9000").is_result_register()


def test_alarm_area_holds_800_alarms() -> None:
    assert AREA_SIZES[Area.A] * 8 == 800
