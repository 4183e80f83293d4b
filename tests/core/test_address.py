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
        ("A250.0", "byte-range"),  # 30i: A0-A249 and A9000-A9249
        ("A8999.0", "byte-range"),
        ("X128.0", "byte-range"),
        ("X999.0", "byte-range"),
        ("G768.0", "byte-range"),
        ("R9500", "byte-range"),
        ("K100.0", "byte-range"),
        ("X" + "9" * 5000, "byte-range"),  # no int() of thousands of digits
        ("X1." + "9" * 5000, "bit-range"),
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


def test_alarm_message_file_covers_a0_to_a99() -> None:
    # AlarmMsg.dat numbers 000-799 are A0.0-A99.7; the 30i A area itself is A0-A249, A9000-
    from ladderworks.core.alarms import ALARM_COUNT

    assert ALARM_COUNT == 800 and AREA_SIZES[Area.A] == 9250


@pytest.mark.parametrize("text", [
    "X0.0", "X127.7", "X200.0", "X327.7", "X1000.0", "X1127.7", "Y1032.1",
    "F0", "F767", "G1008.4", "G2008.4", "F9767.7", "R0", "R7999.7", "R8999", "R9000.0",
    "R9499.7", "E0", "E4204.1", "E9999.7", "A249.7", "A9000.0", "A9249.7", "T499",
    "T9036.2", "T9499", "K99.7", "K900.1", "K999.7", "C399", "C5000", "C5199", "D9999",
])
def test_30i_memory_b_map(text: str) -> None:
    assert str(parse_address(text)) == text


def test_width_must_stay_in_one_range() -> None:
    assert parse_address("X126", width=2).byte == 126
    with pytest.raises(AddressError) as info:
        parse_address("X127", width=2)  # X128 does not exist
    assert info.value.code == "byte-range"
    assert "1000-1127" in str(info.value.args_map["ranges"])
    with pytest.raises(AddressError):
        parse_address("G767", width=2)
