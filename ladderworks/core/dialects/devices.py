"""A dialect's address map: its device spellings (X0, M100, D10) and where each lives in memory.

A device is a letter and a number (octal for Delta X/Y). Its bits and its words live at fixed
places of the PMC memory image (`core/address.py`'s areas): bit n of a device at byte
`byte + (n - first) // 8`, bit `(n - first) % 8` of its area; word n at byte
`byte + stride * (n - first)`. One letter may have several ranges, each in its own place (Delta
D0-D4999 in area D, D5000-D9999 in area E), so no area grows beyond the PMC's. So every part
that reads an `Address` (the engine, the binary, the code generator, forcing, the trace) works
unchanged, and only spelling (parse, format) goes through the map.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ladderworks.core.address import Address, AddressError, Area

_DEVICE_RE = re.compile(r"^([A-Za-z]+)([0-9]+)$")


@dataclass(frozen=True, slots=True)
class Device:
    """One kind of device: its letters, numbers, and where its bits and words are."""

    letter: str  # as written: "X", "M", "T", "D"
    first: int  # lowest number
    last: int  # highest number
    meaning: str  # English, for the docs and the bit display
    base: int = 10  # the radix of its numbers (8: Delta X/Y)
    bits: tuple[Area, int] | None = None  # area and byte of bit 0 (None: no bit use)
    words: tuple[Area, int] | None = None  # area and byte of word 0 (None: no word use)
    stride: int = 2  # bytes from one word to the next
    wide_from: int | None = None  # numbers from here hold 4-byte values (Delta C200..C255)
    read_only: bool = False  # the program may not write it (inputs)

    def width(self, number: int) -> int:
        """Bytes of the value of word `number` (2, or 4 for a 32-bit device)."""
        return 4 if self.wide_from is not None and number >= self.wide_from else 2

    def spell(self, number: int) -> str:
        """The device's text for `number`: `X17` (octal), `M100`."""
        return f"{self.letter}{number:o}" if self.base == 8 else f"{self.letter}{number}"

    def bit_address(self, number: int) -> Address:
        """Where bit device `number` lives."""
        assert self.bits is not None
        area, byte = self.bits
        offset = number - self.first
        return Address(area, byte + offset // 8, offset % 8)

    def word_address(self, number: int) -> Address:
        """Where word `number` starts."""
        assert self.words is not None
        area, byte = self.words
        return Address(area, byte + self.stride * (number - self.first))

    def bit_number(self, address: Address) -> int | None:
        """The device number whose bit is at `address`, or None."""
        if self.bits is None or address.bit is None or address.area is not self.bits[0]:
            return None
        number = self.first + (address.byte - self.bits[1]) * 8 + address.bit
        return number if self.first <= number <= self.last and address.byte >= self.bits[1] \
            else None

    def word_number(self, address: Address) -> int | None:
        """The device number whose word starts at `address`, or None."""
        if self.words is None or address.bit is not None or address.area is not self.words[0]:
            return None
        offset = address.byte - self.words[1]
        if offset < 0 or offset % self.stride:
            return None
        number = self.first + offset // self.stride
        return number if self.first <= number <= self.last else None

    def bytes_needed(self) -> dict[Area, int]:
        """The bytes each area needs to hold this device (its highest byte + 1)."""
        need: dict[Area, int] = {}
        if self.bits is not None:
            need[self.bits[0]] = self.bits[1] + (self.last - self.first) // 8 + 1
        if self.words is not None:
            area = self.words[0]
            top = self.words[1] + self.stride * (self.last - self.first) + self.width(self.last)
            need[area] = max(need.get(area, 0), top)
        return need


@dataclass(frozen=True, slots=True)
class DeviceMap:
    """A dialect's devices: parse a spelling to an Address, format an Address back."""

    devices: tuple[Device, ...]
    by_letter: dict[str, tuple[Device, ...]] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        by_letter: dict[str, tuple[Device, ...]] = {}
        for device in self.devices:
            by_letter[device.letter] = (*by_letter.get(device.letter, ()), device)
        object.__setattr__(self, "by_letter", by_letter)

    def letters(self) -> str:
        """The device letters, for messages: `X, Y, M, S, T, C, D`."""
        return ", ".join(self.by_letter)

    def split(self, text: str) -> tuple[Device, int]:
        """The device and number of a spelling; AddressError (device-unknown, device-octal,
        device-range) when it names none."""
        match = _DEVICE_RE.match(text.strip())
        if match is None:
            raise AddressError("device-unknown", text=text, letters=self.letters())
        letter, digits = match.group(1).upper(), match.group(2)
        ranges = self.by_letter.get(letter)
        if ranges is None:
            raise AddressError("device-unknown", text=text, letters=self.letters())
        device = ranges[0]
        if device.base == 8:
            if any(ch in "89" for ch in digits):
                raise AddressError("device-octal", text=text, letter=letter)
            number = int(digits, 8)
        else:
            number = int(digits) if len(digits) <= 9 else -1
        for device in ranges:
            if device.first <= number <= device.last:
                return device, number
        raise AddressError("device-range", text=text, first=ranges[0].spell(ranges[0].first),
                           last=ranges[-1].spell(ranges[-1].last))

    def bit(self, text: str) -> Address:
        """The Address of bit device `text` (`X10`, `M1000`, `T0`'s contact)."""
        device, number = self.split(text)
        if device.bits is None:
            raise AddressError("device-bit-needed", text=text)
        return device.bit_address(number)

    def word(self, text: str) -> tuple[Address, int]:
        """The Address and byte width of word device `text` (`D10`, `T0`'s current value)."""
        device, number = self.split(text)
        if device.words is None:
            raise AddressError("device-word-needed", text=text)
        return device.word_address(number), device.width(number)

    def target(self, text: str, want: str | None = None) -> tuple[Address, int]:
        """A device typed where a value is read or written (CLI --set/--print, scenarios, the
        bit display): its Address and byte width. `want` "bit" or "word" picks one use of a
        device that has both (T0's contact or value); None takes the word when there is one."""
        device, number = self.split(text)
        if want == "bit" or (want is None and device.words is None):
            if device.bits is None:
                raise AddressError("device-bit-needed", text=text)
            return device.bit_address(number), 1
        if device.words is None:
            raise AddressError("device-word-needed", text=text)
        return device.word_address(number), device.width(number)

    def device_of(self, address: Address) -> tuple[Device, int] | None:
        """The device and number at `address` (bit or word), or None."""
        for device in self.devices:
            number = (device.bit_number(address) if address.bit is not None
                      else device.word_number(address))
            if number is not None:
                return device, number
        return None

    def format(self, address: Address) -> str | None:
        """The spelling of `address` (`X17`, `D100`), None if no device lives there."""
        found = self.device_of(address)
        return None if found is None else found[0].spell(found[1])

    def format_sized(self, address: Address, width: int) -> str | None:
        """The spelling of a value of `width` bytes at `address` (the device's own here)."""
        return self.format(address)

    def laid_out(self, address: Address) -> bool:
        """True for a place LadderWorks laid out itself (no absolute address in the PLC)."""
        return False

    def width_at(self, address: Address) -> int:
        """The byte width of the word at `address` (2 unless a 32-bit device lives there)."""
        found = self.device_of(address)
        return 2 if found is None else found[0].width(found[1])

    def holds(self, address: Address, width: int = 1) -> bool:
        """True when a device lives at `address` (a word: with room for `width` bytes)."""
        found = self.device_of(address)
        if found is None:
            return False
        device = found[0]
        if address.bit is not None or device.words is None:
            return True
        end = device.words[1] + device.stride * (device.last - device.first) \
            + device.width(device.last)
        return address.byte + width <= end

    def read_only(self, address: Address) -> bool:
        """True when the program may not write `address` (an input device)."""
        found = self.device_of(address)
        return found is not None and found[0].read_only

    def bytes_needed(self) -> dict[Area, int]:
        """The bytes each area needs to hold every device."""
        need: dict[Area, int] = {}
        for device in self.devices:
            for area, size in device.bytes_needed().items():
                need[area] = max(need.get(area, 0), size)
        return need
