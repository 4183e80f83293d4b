"""The PLC memory image: one bytearray per area; multi-byte values in the program's byte order
(little-endian for the PMC, Delta and Fatek; big-endian for S7: `Dialect.byteorder`)."""

from __future__ import annotations

from typing import Literal

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects import memory_sizes
from ladderworks.core.plc.bcd import bcd_to_int, int_to_bcd


class Memory:
    """Every area's bytes; values of 2 and 4 bytes are little-endian (low byte first).

    Each area holds the PMC's map and whatever a dialect's devices need beyond it (the 20000
    bytes of Delta's D0-D9999 words): core/dialects.memory_sizes."""

    def __init__(self, byteorder: str = "little") -> None:
        # the one place a value's byte order is decided: the engine sets it from the dialect
        self.byteorder: Literal["little", "big"] = "big" if byteorder == "big" else "little"
        self.areas: dict[Area, bytearray] = {
            area: bytearray(size) for area, size in memory_sizes().items()
        }

    def bit(self, address: Address) -> int:
        """The bit at a bit address (0 or 1)."""
        assert address.bit is not None
        return (self.areas[address.area][address.byte] >> address.bit) & 1

    def set_bit(self, address: Address, value: bool | int) -> None:
        """Set or clear the bit at a bit address."""
        assert address.bit is not None
        data = self.areas[address.area]
        mask = 1 << address.bit
        if value:
            data[address.byte] |= mask
        else:
            data[address.byte] &= ~mask & 0xFF

    def read(self, address: Address, width: int = 1, *, signed: bool = False) -> int:
        """The `width`-byte value starting at a byte address."""
        data = self.areas[address.area]
        return int.from_bytes(data[address.byte:address.byte + width], self.byteorder,
                              signed=signed)

    def write(self, address: Address, value: int, width: int = 1) -> None:
        """Store `value` (wrapped to `width` bytes, two's complement) at a byte address."""
        data = self.areas[address.area]
        bits = 8 * width
        value &= (1 << bits) - 1
        data[address.byte:address.byte + width] = value.to_bytes(width, self.byteorder)

    def read_bcd(self, address: Address, width: int) -> int | None:
        """The BCD value of `width` bytes (2 digits a byte); None on an invalid digit."""
        return bcd_to_int(self.read(address, width), 2 * width)

    def write_bcd(self, address: Address, value: int, width: int) -> bool:
        """Store `value` as BCD in `width` bytes; False (nothing written) if it does not fit."""
        raw = int_to_bcd(value, 2 * width)
        if raw is None:
            return False
        self.write(address, raw, width)
        return True

    def snapshot(self) -> dict[Area, bytes]:
        """An immutable copy of every area."""
        return {area: bytes(data) for area, data in self.areas.items()}

    def clear(self, *areas: Area) -> None:
        """Zero the given areas."""
        for area in areas:
            self.areas[area][:] = bytes(len(self.areas[area]))
