"""Where the elements of a map row live in PLC memory: by PMC address, or by a dialect's devices.

A PMC row (seed, FANUC) starts at an address (`X0.0`, `D0`): element i is the i-th bit after
it, or the i-th register of `width` bytes. A row of a registered dialect (`core/dialects`, e.g.
Delta) starts at a device (`X0`, `M1536`, `D4096`): element i is device number first + i (its
bit, or its 16-bit word; a 32-bit device such as Delta's C200 takes two registers, low word
first), found through the dialect's `DeviceMap`, so a row may run on into the next range of
the same letter (Delta D4999 in area D, D5000 in area E).
A row of a byte-addressed dialect (S7: `%Q0.0`, `%MW0`, a DB's laid-out `D16`) runs on byte by
byte: element i is the i-th bit after its first, or the 16-bit word 2i bytes after it, in the
memory's byte order (big-endian for S7, as MB_SERVER serves %MW).
"""

from __future__ import annotations

import re
from functools import cache, lru_cache

from ladderworks.core import dialects
from ladderworks.core.address import (
    Address,
    AddressError,
    Area,
    byte_in_range,
    parse_address,
    ranges_text,
)
from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.devices import Device, DeviceMap
from ladderworks.core.dialects.s7.devices import S7DeviceMap, format_absolute
from ladderworks.core.modbus.maps import MapRow


class PmcCells:
    """Rows addressed by PMC addresses."""

    @staticmethod
    @lru_cache(maxsize=1024)
    def first(row: MapRow) -> Address:
        """The row's first element: a bit address for a bit table, else a byte address."""
        return parse_address(row.device, want_bit=row.table.bits, width=row.width)

    def check(self, row: MapRow) -> None:
        """Refuse a row whose device is not an address of its kind, or whose elements run
        past the range of the area it starts in (AddressError / Refused)."""
        first = self.first(row)
        if first.bit is not None:
            last_byte = first.byte + (first.bit + row.count - 1) // 8
        else:
            last_byte = first.byte + row.count * row.width - 1
        if not byte_in_range(first.area, first.byte, last_byte - first.byte + 1):
            raise Refused("modbus-map-area", device=row.device, count=row.count,
                          area=first.area.value, ranges=ranges_text(first.area))

    def bit(self, row: MapRow, index: int) -> Address:
        """The bit element `index` of a bit row reaches."""
        first = self.first(row)
        assert first.bit is not None
        position = first.byte * 8 + first.bit + index
        return Address(first.area, position >> 3, position & 7)

    def register(self, row: MapRow, index: int) -> Address:
        """The first of the `row.width` bytes register `index` of a row reaches."""
        return Address(self.first(row).area, self.first(row).byte + index * row.width)


class DeviceCells:
    """Rows addressed by a dialect's devices (`DeviceMap`)."""

    def __init__(self, devices: DeviceMap) -> None:
        self.devices = devices
        self._first: dict[MapRow, tuple[Device, int]] = {}

    def _start(self, row: MapRow) -> tuple[Device, int]:
        found = self._first.get(row)
        if found is None:
            found = self._first[row] = self.devices.split(row.device)
        return found

    def _device(self, row: MapRow, number: int) -> Device:
        """The device of the row's letter that holds `number`."""
        first, _ = self._start(row)
        for device in self.devices.by_letter[first.letter]:
            if device.first <= number <= device.last:
                return device
        raise Refused("modbus-map-area", device=row.device, count=row.count,
                      area=first.letter, ranges=f"{first.spell(first.first)}-"
                      f"{first.spell(self.devices.by_letter[first.letter][-1].last)}")

    def _element(self, row: MapRow, index: int) -> tuple[Device, int, int]:
        """(device, number, which 16-bit half) of element `index`."""
        first, number = self._start(row)
        if row.table.bits:
            return self._device(row, number + index), number + index, 0
        if first.width(number) == 4:  # a 32-bit device: two registers each
            n = number + index // 2
            return self._device(row, n), n, index % 2
        return self._device(row, number + index), number + index, 0

    def check(self, row: MapRow) -> None:
        """Refuse a row whose device is unknown, has no bit (word) for a bit (register) row,
        or whose last element is no device."""
        first, _ = self._start(row)
        if row.table.bits and first.bits is None:
            raise AddressError("device-bit-needed", text=row.device)
        if not row.table.bits and first.words is None:
            raise AddressError("device-word-needed", text=row.device)
        if not row.table.bits and row.width != 2:
            raise Refused("modbus-map-width", device=row.device)
        self._element(row, row.count - 1)

    def bit(self, row: MapRow, index: int) -> Address:
        """The bit of device number first + index."""
        device, number, _ = self._element(row, index)
        return device.bit_address(number)

    def register(self, row: MapRow, index: int) -> Address:
        """The first byte of register `index`: a 16-bit word (or half of a 32-bit one)."""
        device, number, half = self._element(row, index)
        return device.word_address(number).offset(2 * half)


class ByteCells:
    """Rows addressed by a byte-addressed dialect's spellings (S7: `%Q0.0`, `%MW0`, `D16`)."""

    def __init__(self, devices: DeviceMap) -> None:
        self.devices = devices

    @lru_cache(maxsize=1024)  # noqa: B019 - one instance a dialect, kept for the program
    def first(self, row: MapRow) -> Address:
        """The row's first bit (bit rows) or byte (register rows)."""
        text = row.device.strip()
        laid = _LAID_OUT.match(text)
        if laid is not None and not row.table.bits:  # a DB member laid out by LadderWorks
            return Address(Area.D, int(laid.group(1)))
        if row.table.bits:
            return self.devices.bit(text)
        return self.devices.word(text)[0]

    def check(self, row: MapRow) -> None:
        """Refuse a row whose device is no address of its kind, or runs past its area, or a
        register row whose width is not 2 (S7 registers are words)."""
        first = self.first(row)
        if not row.table.bits and row.width != 2:
            raise Refused("modbus-map-width", device=row.device)
        if first.bit is not None:
            last = self.bit(row, row.count - 1)
        else:
            last = first.offset(row.count * 2 - 2)
        if not self.devices.holds(last.offset(0), 2 if last.bit is None else 1):
            device = next((d for d in self.devices.devices
                           if d.bits is not None and d.bits[0] is first.area), None)
            letter = device.letter if device is not None else first.area.value
            size = (device.last + 1) // 8 if device is not None else 0
            ends = (Address(first.area, 0, 0), Address(first.area, size - 1, 7)) \
                if row.table.bits else (Address(first.area, 0), Address(first.area, size - 2))
            raise Refused("modbus-map-area", device=row.device, count=row.count, area=letter,
                          ranges="-".join(format_absolute(a, 1 if row.table.bits else 2)
                                          or str(a) for a in ends))

    def bit(self, row: MapRow, index: int) -> Address:
        """The bit element `index` of a bit row reaches."""
        first = self.first(row)
        position = first.byte * 8 + (first.bit or 0) + index
        return Address(first.area, position >> 3, position & 7)

    def register(self, row: MapRow, index: int) -> Address:
        """The first byte of the 16-bit word register `index` reaches."""
        return self.first(row).offset(2 * index)


_LAID_OUT = re.compile(r"^D(\d{1,5})$")
Cells = PmcCells | DeviceCells | ByteCells
PMC_CELLS = PmcCells()


@cache
def cells_for(dialect: str) -> Cells:
    """How rows reach memory in programs of `dialect` (PMC addresses unless it has devices)."""
    found = dialects.get(dialect)
    if found is None:
        return PMC_CELLS
    if isinstance(found.devices, S7DeviceMap):
        return ByteCells(found.devices)
    return DeviceCells(found.devices)
