"""Where the elements of a map row live in PLC memory, for the PMC dialects (seed, FANUC)."""

from __future__ import annotations

from functools import lru_cache

from ladderworks.core.address import Address, byte_in_range, parse_address, ranges_text
from ladderworks.core.diagnostics import Refused
from ladderworks.core.modbus.maps import MapRow


@lru_cache(maxsize=1024)
def first_element(row: MapRow) -> Address:
    """The row's first element: a bit address for a bit table, else a byte address."""
    return parse_address(row.device, want_bit=row.table.bits, width=row.width)


def check_row(row: MapRow) -> None:
    """Refuse a row whose device is not an address of its kind or whose elements run past
    the range of the area it starts in (AddressError / Refused, with a diagnostic)."""
    first = first_element(row)
    if first.bit is not None:
        last_byte = first.byte + (first.bit + row.count - 1) // 8
    else:
        last_byte = first.byte + row.count * row.width - 1
    if not byte_in_range(first.area, first.byte, last_byte - first.byte + 1):
        raise Refused("modbus-map-area", device=row.device, count=row.count,
                      area=first.area.value, ranges=ranges_text(first.area))


def bit_address(row: MapRow, index: int) -> Address:
    """The bit that element `index` of a bit row reaches."""
    first = first_element(row)
    assert first.bit is not None
    position = first.byte * 8 + first.bit + index
    return Address(first.area, position >> 3, position & 7)


def register_address(row: MapRow, index: int) -> Address:
    """The first byte of the `row.width` bytes that register `index` of a row reaches."""
    first = first_element(row)
    return Address(first.area, first.byte + index * row.width)
