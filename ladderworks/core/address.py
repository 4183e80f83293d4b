"""PMC addresses: areas, their sizes, and the parsing and canonical spelling of addresses."""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import StrEnum


class AddressError(ValueError):
    """An address that cannot be parsed or is out of range; `code` and `args` name the reason."""

    def __init__(self, code: str, **args: object) -> None:
        self.code = code
        self.args_map = dict(args)
        super().__init__(f"{code}: {args}")


class Area(StrEnum):
    """A memory area of the PMC."""

    X = "X"
    Y = "Y"
    F = "F"
    G = "G"
    R = "R"
    A = "A"
    D = "D"
    T = "T"
    C = "C"
    K = "K"
    E = "E"


# Number of bytes in each area; byte numbers run 0 .. size-1.
AREA_SIZES: dict[Area, int] = {
    Area.X: 128,  # machine -> PLC inputs X0..X127
    Area.Y: 128,  # PLC -> machine outputs Y0..Y127
    Area.F: 768,  # CNC -> PLC status F0..F767
    Area.G: 768,  # PLC -> CNC commands G0..G767
    Area.R: 9200,  # internal relays R0..R8999, system R9000..R9199
    Area.A: 100,  # alarm message bits A0..A99 (800 alarms)
    Area.D: 10000,  # data table D0..D9999
    Area.T: 400,  # timer presets: 4 bytes (ms, binary) per timer 1..100
    Area.C: 80,  # counters: 4 bytes per counter 1..20 (preset, current value)
    Area.K: 100,  # keep relays K0..K99 (retained)
    Area.E: 10000,  # extra relays E0..E9999 (FANUC 30i)
}

AREA_MEANING: dict[Area, str] = {
    Area.X: "machine to PLC input",
    Area.Y: "PLC to machine output",
    Area.F: "CNC to PLC signal",
    Area.G: "PLC to CNC signal",
    Area.R: "internal relay",
    Area.A: "alarm message bit",
    Area.D: "data table",
    Area.T: "timer preset",
    Area.C: "counter",
    Area.K: "keep relay",
    Area.E: "extra relay",
}

# Areas the program may not write: inputs from the machine and the CNC.
INPUT_AREAS: frozenset[Area] = frozenset({Area.X, Area.F})

# R9000..R9005: the functional-instruction result register, read-only to the program.
RESULT_REGISTER_FIRST = 9000
RESULT_REGISTER_LAST = 9005

_ADDRESS_RE = re.compile(r"^([A-Za-z])(\d+)(?:\.(\d+))?$")


@dataclass(frozen=True, slots=True, order=True)
class Address:
    """A byte (`bit is None`) or bit address such as `R100` or `X2.1`."""

    area: Area
    byte: int
    bit: int | None = None

    @property
    def is_bit(self) -> bool:
        """True for a bit address like `X2.1`."""
        return self.bit is not None

    def byte_address(self) -> Address:
        """The byte that holds this address."""
        return Address(self.area, self.byte)

    def with_bit(self, bit: int) -> Address:
        """The bit `bit` of this address's byte."""
        return Address(self.area, self.byte, bit)

    def offset(self, nbytes: int) -> Address:
        """The byte address `nbytes` further on (bit dropped)."""
        return Address(self.area, self.byte + nbytes)

    def is_result_register(self) -> bool:
        """True for R9000..R9005, the function result register."""
        return (
            self.area is Area.R
            and RESULT_REGISTER_FIRST <= self.byte <= RESULT_REGISTER_LAST
        )

    def __str__(self) -> str:
        return format_address(self)


def format_address(address: Address) -> str:
    """Canonical spelling: area letter, byte without leading zeros, `.bit` for bits (`A21.0`)."""
    text = f"{address.area.value}{address.byte}"
    if address.bit is not None:
        text += f".{address.bit}"
    return text


def parse_address(text: str, *, want_bit: bool | None = None, width: int = 1) -> Address:
    """Parse `X2.1`, `A021.0`, `R0100`; `want_bit` True/False demands a bit/byte address.

    `width` is the number of bytes the address must have room for (for 2- and 4-byte data).
    Raises AddressError with a code: bad-address, unknown-area, byte-range, bit-range,
    bit-expected, byte-expected.
    """
    match = _ADDRESS_RE.match(text.strip())
    if not match:
        raise AddressError("bad-address", text=text)
    letter, byte_text, bit_text = match.groups()
    try:
        area = Area(letter.upper())
    except ValueError:
        raise AddressError("unknown-area", text=text, area=letter.upper()) from None
    byte = int(byte_text)
    size = AREA_SIZES[area]
    if byte + max(width, 1) > size:
        raise AddressError(
            "byte-range", text=text, area=area.value, last=size - max(width, 1)
        )
    bit: int | None = None
    if bit_text is not None:
        bit = int(bit_text)
        if bit > 7 or len(bit_text) > 1:
            raise AddressError("bit-range", text=text)
    if want_bit is True and bit is None:
        raise AddressError("bit-expected", text=text)
    if want_bit is False and bit is not None:
        raise AddressError("byte-expected", text=text)
    return Address(area, byte, bit)


def looks_like_address(text: str) -> bool:
    """True when `text` has the shape of an address (letter, digits, optional `.bit`)."""
    return bool(_ADDRESS_RE.match(text.strip()))
