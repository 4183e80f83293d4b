"""Delta's address map: device spellings <-> places in the PMC memory image."""

from __future__ import annotations

import pytest

from ladderworks.core import dialects
from ladderworks.core.address import AREA_SIZES, Address, AddressError, Area
from ladderworks.core.dialects.delta import DEVICES


@pytest.mark.parametrize(("text", "address"), [
    ("X0", Address(Area.X, 0, 0)), ("X7", Address(Area.X, 0, 7)), ("X10", Address(Area.X, 1, 0)),
    ("X377", Address(Area.X, 31, 7)), ("Y17", Address(Area.Y, 1, 7)),
    ("M0", Address(Area.R, 0, 0)), ("M1000", Address(Area.R, 125, 0)),
    ("M4095", Address(Area.R, 511, 7)), ("S0", Address(Area.R, 1000, 0)),
    ("S1023", Address(Area.R, 1127, 7)), ("T0", Address(Area.T, 1000, 0)),
    ("T255", Address(Area.T, 1031, 7)), ("C0", Address(Area.C, 2000, 0)),
    ("C255", Address(Area.C, 2031, 7)),
])
def test_bit_devices_round_trip(text: str, address: Address) -> None:
    assert DEVICES.bit(text) == address
    assert DEVICES.format(address) == text
    assert dialects.format_address(address, "delta") == text


@pytest.mark.parametrize(("text", "address", "width"), [
    ("D0", Address(Area.D, 0), 2), ("D4999", Address(Area.D, 9998), 2),
    ("D5000", Address(Area.E, 0), 2), ("D9999", Address(Area.E, 9998), 2),
    ("T0", Address(Area.T, 0), 2), ("T255", Address(Area.T, 510), 2),
    ("C0", Address(Area.C, 0), 2), ("C199", Address(Area.C, 796), 2),
    ("C200", Address(Area.C, 800), 4), ("C255", Address(Area.C, 1020), 4),
])
def test_word_devices_round_trip(text: str, address: Address, width: int) -> None:
    assert DEVICES.word(text) == (address, width)
    assert DEVICES.format(address) == text


@pytest.mark.parametrize(("text", "code"), [
    ("X8", "device-octal"), ("Y19", "device-octal"), ("X400", "device-range"),
    ("M4096", "device-range"), ("S1024", "device-range"), ("T256", "device-range"),
    ("C256", "device-range"), ("D10000", "device-range"), ("Q1", "device-unknown"),
    ("X", "device-unknown"), ("M1.0", "device-unknown"),
])
def test_bad_devices_say_why(text: str, code: str) -> None:
    with pytest.raises(AddressError) as caught:
        DEVICES.target(text)
    assert caught.value.code == code
    assert text in caught.value.diagnostic.message()


def test_a_bit_only_device_has_no_word_and_back() -> None:
    with pytest.raises(AddressError, match="not a word device"):
        DEVICES.word("M0")
    with pytest.raises(AddressError, match="not a bit device"):
        DEVICES.bit("D0")


def test_targets_take_the_value_of_timers_unless_a_bit_is_wanted() -> None:
    assert dialects.parse_target("T3", "delta") == (Address(Area.T, 6), 2)
    assert dialects.parse_target("T3", "delta", "bit") == (Address(Area.T, 1000, 3), 1)
    assert dialects.parse_target("Y0", "delta") == (Address(Area.Y, 0, 0), 1)
    assert dialects.parse_target("D10:4", "delta") == (Address(Area.D, 20), 4)
    assert dialects.parse_target("R10", None, width=2) == (Address(Area.R, 10), 2)


def test_no_area_grows_beyond_the_pmc_map() -> None:
    assert dialects.memory_sizes() == AREA_SIZES
    for area, size in DEVICES.bytes_needed().items():
        assert size <= AREA_SIZES[area]


def test_every_device_place_is_distinct() -> None:
    seen: dict[Address, str] = {}
    for device in DEVICES.devices:
        for number in range(device.first, device.last + 1):
            for address in ([device.bit_address(number)] if device.bits else []) + (
                    [device.word_address(number)] if device.words else []):
                assert address not in seen, (device.spell(number), seen.get(address))
                seen[address] = device.spell(number)
