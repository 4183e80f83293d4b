"""S7-1200 addresses in the engine's memory: %I → X, %Q → Y, %M → R, DBs → D and E (big-endian).

`%I3.2` is bit 2 of byte 3 of the X area, `%IW0` bytes X0-X1 with X0 the high byte (S7 is
big-endian: `Memory.byteorder` of an S7 program is "big"). Absolute DB access `%DBn.DBX/B/W/D`
reaches DB1-DB39, 256 bytes each from E0 (`DB_BYTES`); symbolic (optimized) DB members and FB
instances are laid out by the lowering in the D area (`layout.py`). docs/dialects.md, S7-1200.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.dialects.devices import Device, DeviceMap

IO_BYTES = 1024  # %I0-%I1023, %Q0-%Q1023 (inside the PMC's X/Y areas: X0-X1127)
M_BYTES = 8192  # %M0-%M8191 in R0-R8191 (R9000.. stay the engine's system relays)
DB_BYTES = 256  # absolute DB access: DBn at E (n - 1) * 256
DB_LAST = 39
WIDTHS = {"": 1, "X": 1, "B": 1, "W": 2, "D": 4}
_AREAS = {"I": Area.X, "Q": Area.Y, "M": Area.R}
_LETTERS = {Area.X: "I", Area.Y: "Q", Area.R: "M"}
_SIZE = {"I": IO_BYTES, "Q": IO_BYTES, "M": M_BYTES}
_ABSOLUTE_RE = re.compile(r"^%?([IQM])([BWD]?)(\d{1,5})(?:\.(\d))?$", re.I)
_DB_RE = re.compile(r"^%?DB(\d{1,5})\.DB([XBWD])(\d{1,5})(?:\.(\d))?$", re.I)


def _device(letter: str, area: Area, size: int, meaning: str, read_only: bool = False) -> Device:
    return Device(letter, 0, size * 8 - 1, meaning, bits=(area, 0), words=(area, 0), stride=1,
                  read_only=read_only)


def parse_absolute(text: str) -> tuple[Address, int]:
    """An absolute S7 address (`%I0.0`, `%MW2`, `%DB1.DBW4`): its Address and byte width
    (1 for a bit). AddressError when it is none or out of range."""
    spelled = text.strip()
    match = _ABSOLUTE_RE.match(spelled)
    if match is not None:
        letter, size, byte_text, bit_text = match.groups()
        letter, size = letter.upper(), size.upper()
        byte, width = int(byte_text), WIDTHS[size]
        if (bit_text is None) == (size == "") or byte + width > _SIZE[letter] \
                or (bit_text is not None and int(bit_text) > 7):
            raise AddressError("s7-address", text=text)
        bit = int(bit_text) if bit_text is not None else None
        return Address(_AREAS[letter], byte, bit), width
    match = _DB_RE.match(spelled)
    if match is not None:
        number, size, byte_text, bit_text = match.groups()
        size = size.upper()
        byte, width, db = int(byte_text), WIDTHS[size], int(number)
        if not 1 <= db <= DB_LAST or (bit_text is None) == (size == "X") \
                or byte + width > DB_BYTES or (bit_text is not None and int(bit_text) > 7):
            raise AddressError("s7-address", text=text)
        bit = int(bit_text) if bit_text is not None else None
        return Address(Area.E, (db - 1) * DB_BYTES + byte, bit), width
    raise AddressError("s7-address", text=text)


def format_absolute(address: Address, width: int = 1) -> str | None:
    """The S7 spelling of an address (`%I0.0`, `%MW2`, `%DB1.DBW4`), None if S7 has none."""
    sizes = {1: "B", 2: "W", 4: "D"}
    letter = _LETTERS.get(address.area)
    if letter is not None:
        if address.byte >= _SIZE[letter]:
            return None
        if address.bit is not None:
            return f"%{letter}{address.byte}.{address.bit}"
        return f"%{letter}{sizes.get(width, 'B')}{address.byte}"
    if address.area is Area.E and address.byte < DB_LAST * DB_BYTES:
        db, byte = divmod(address.byte, DB_BYTES)
        if address.bit is not None:
            return f"%DB{db + 1}.DBX{byte}.{address.bit}"
        return f"%DB{db + 1}.DB{sizes.get(width, 'B')}{byte}"
    if address.area is Area.D:  # a DB member laid out by LadderWorks (shown by its name)
        return f"D{address.byte}" if address.bit is None else f"D{address.byte}.{address.bit}"
    return None


@dataclass(frozen=True, slots=True)
class S7DeviceMap(DeviceMap):
    """The S7 address map: absolute spellings instead of letter + number devices."""

    def split(self, text: str) -> tuple[Device, int]:
        """S7 has no letter + number devices: AddressError."""
        raise AddressError("s7-address", text=text)

    def bit(self, text: str) -> Address:
        """A bit address (`%I0.0`, `%DB1.DBX0.1`)."""
        address, _width = parse_absolute(text)
        if address.bit is None:
            raise AddressError("device-bit-needed", text=text)
        return address

    def word(self, text: str) -> tuple[Address, int]:
        """A byte/word/double word address (`%MW2`) and its width."""
        address, width = parse_absolute(text)
        if address.bit is not None:
            raise AddressError("device-word-needed", text=text)
        return address, width

    def target(self, text: str, want: str | None = None) -> tuple[Address, int]:
        """Any absolute address and its width."""
        return parse_absolute(text)

    def format(self, address: Address) -> str | None:
        """The S7 spelling of an address (a byte address as its byte: `%MB2`)."""
        return format_absolute(address)

    def format_sized(self, address: Address, width: int) -> str | None:
        """The S7 spelling of a value of `width` bytes (`%MW2`, `%DB1.DBD4`)."""
        return format_absolute(address, width)

    def laid_out(self, address: Address) -> bool:
        """True for an optimized DB's member: LadderWorks placed it, TIA gives it no address."""
        return address.area is Area.D

    def width_at(self, address: Address) -> int:
        """A byte address's width: 1 (S7 says the width in the spelling)."""
        return 1

    def holds(self, address: Address, width: int = 1) -> bool:
        """True when the S7 memory has `width` bytes at `address`."""
        limits = {Area.X: IO_BYTES, Area.Y: IO_BYTES, Area.R: M_BYTES,
                  Area.E: DB_LAST * DB_BYTES, Area.D: 10_000}
        limit = limits.get(address.area)
        return limit is not None and address.byte + (1 if address.bit is not None else width) \
            <= limit


    def bytes_needed(self) -> dict[Area, int]:
        """The bytes S7 uses of each area: all inside the PMC's sizes."""
        return {Area.X: IO_BYTES, Area.Y: IO_BYTES, Area.R: M_BYTES,
                Area.E: DB_LAST * DB_BYTES, Area.D: 10_000}


DEVICES = S7DeviceMap((
    _device("I", Area.X, IO_BYTES, "input (process image)", read_only=True),
    _device("Q", Area.Y, IO_BYTES, "output (process image)"),
    _device("M", Area.R, M_BYTES, "bit memory"),
    _device("DB", Area.E, DB_LAST * DB_BYTES, "data block (absolute access)"),
    _device("L", Area.D, 10_000, "DB members and instances laid out by LadderWorks"),
))
