"""Fatek device spellings, ranges, timer bases, counter widths and their place in memory."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.fatek.devices import (
    Device,
    DeviceError,
    bit_address,
    counter_is_32bit,
    counter_is_retentive,
    device_at,
    parse_constant,
    parse_device,
    timer_base_ms,
    word_address,
    word_device_at,
)


@pytest.mark.parametrize(("text", "bit", "device"), [
    ("X0", True, Device("X", 0)), ("x 7", True, Device("X", 7)), ("M1924", True,
                                                                   Device("M", 1924)),
    ("TR39", True, Device("TR", 39)), ("R4133", False, Device("R", 4133)),
    ("DR10", False, Device("DR", 10)), ("WX8", False, Device("WX", 8)),
    ("C255", False, Device("C", 255)),
])
def test_spellings(text: str, bit: bool, device: Device) -> None:
    assert parse_device(text, bit=bit) == device


@pytest.mark.parametrize(("text", "bit", "code"), [
    ("X256", True, "fatek-device-range"), ("T256", True, "fatek-device-range"),
    ("TR40", True, "fatek-device-range"), ("R0", True, "fatek-device-kind"),
    ("Y0", False, "fatek-device-kind"), ("WX3", False, "fatek-device-range"),
    ("Q1", True, "fatek-device"), ("DR0", True, "fatek-device-kind"),
    ("R4168", False, "fatek-device-range"), ("R4999", False, "fatek-device-range"),
    ("R8072", False, "fatek-device-range"), ("D4096", False, "fatek-device-range"),
])
def test_bad_spellings(text: str, bit: bool, code: str) -> None:
    with pytest.raises(DeviceError) as error:
        parse_device(text, bit=bit)
    assert error.value.code == code


def test_timer_bases_and_counters() -> None:
    """001:392-416 and 001:572-588."""
    assert [timer_base_ms(n) for n in (0, 49, 50, 199, 200, 255)] == [10, 10, 100, 100, 1000,
                                                                      1000]
    assert not counter_is_32bit(199) and counter_is_32bit(200)
    assert counter_is_retentive(139) and not counter_is_retentive(140)
    assert counter_is_retentive(239) and not counter_is_retentive(240)


def test_memory_map() -> None:
    assert bit_address(Device("X", 9)) == Address(Area.X, 1, 1)
    assert bit_address(Device("M", 1924)) == Address(Area.R, 240, 4)
    assert word_address(Device("R", 3)) == (Address(Area.D, 6), 2)
    assert word_address(Device("DR", 3)) == (Address(Area.D, 6), 4)
    assert word_address(Device("C", 199)) == (Address(Area.T, 796), 2)
    assert word_address(Device("C", 200)) == (Address(Area.T, 800), 4)
    # R5000-R8071 (ROR): T2048 on, after the counters' values (T0-T1023)
    assert word_address(Device("R", 5000)) == (Address(Area.T, 2048), 2)
    assert word_address(Device("R", 8071)) == (Address(Area.T, 8190), 2)
    assert word_device_at(Address(Area.T, 2050)) == Device("R", 5001)
    assert word_device_at(Address(Area.T, 800)) == Device("C", 200)
    assert word_device_at(Address(Area.D, 8334)) == Device("R", 4167)
    assert word_device_at(Address(Area.D, 8336)) is None  # no R4168
    assert word_address(Device("WX", 8)) == (Address(Area.X, 1), 2)
    for kind, number in (("X", 255), ("M", 2001), ("S", 999), ("TR", 0), ("T", 17),
                         ("C", 255)):
        device = Device(kind, number)
        assert device_at(bit_address(device)) == device
    assert device_at(Address(Area.R, 9091, 1)) is None


def test_constants() -> None:
    assert parse_constant("7") == 7
    assert parse_constant("-5") == -5
    assert parse_constant("K10") is None
