"""PMC addresses: areas, their sizes, and the parsing and canonical spelling of addresses."""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from functools import lru_cache
from itertools import repeat

from ladderworks.core.diagnostics import Refused


class AddressError(Refused, ValueError):
    """An address that cannot be parsed or is out of range; its `diagnostic` says why."""


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

    __hash__ = str.__hash__  # the same value as Enum's hash of the name (name == value), in C


# The byte numbers that exist in each area: the first PMC of a 30i/31i-A, PMC memory-B
# (docs/address-map.md). The seed's own map (X/Y 0-127, F/G 0-767, R 0-8999 and system
# relays from R9000, A 0-99, T 0-399, C 0-79, K 0-99, D 0-9999) lies inside it.
_IO = ((0, 127), (200, 327), (400, 527), (600, 727), (1000, 1127))
_PATHS = tuple((1000 * n, 1000 * n + 767) for n in range(10))  # F/G of paths 1 .. 10
AREA_RANGES: dict[Area, tuple[tuple[int, int], ...]] = {
    Area.X: _IO,  # machine -> PLC inputs
    Area.Y: _IO,  # PLC -> machine outputs
    Area.F: _PATHS,  # CNC -> PLC status, path n at 1000 x (n - 1)
    Area.G: _PATHS,  # PLC -> CNC commands, path n at 1000 x (n - 1)
    Area.R: ((0, 9499),),  # internal relays R0..R8999, system relays R9000..R9499
    Area.A: ((0, 249), (9000, 9249)),  # message requests, message status
    Area.D: ((0, 9999),),  # data table
    Area.T: ((0, 499), (9000, 9499)),  # timer presets, timer precision codes
    Area.C: ((0, 399), (5000, 5199)),  # counters (CTR), fixed counters (CTRB)
    Area.K: ((0, 99), (900, 999)),  # keep relays: user, system
    Area.E: ((0, 9999),),  # extra relays
}

# The seed manual's own map (a LadderWorks "seed" program): no E area; A00-A99 (000, part 3).
# A FANUC 30i program has AREA_RANGES (docs/address-map.md).
SEED_AREA_RANGES: dict[Area, tuple[tuple[int, int], ...]] = {
    Area.X: ((0, 127),),
    Area.Y: ((0, 127),),
    Area.F: ((0, 767),),
    Area.G: ((0, 767),),
    Area.R: ((0, 9499),),  # R0..R8999 and the system relays from R9000
    Area.A: ((0, 99),),
    Area.D: ((0, 9999),),
    Area.T: ((0, 399),),
    Area.C: ((0, 79),),
    Area.K: ((0, 99),),
}

# Number of bytes to allocate for each area: its highest byte number + 1.
AREA_SIZES: dict[Area, int] = {area: ranges[-1][1] + 1 for area, ranges in AREA_RANGES.items()}

# The longest byte number the parser converts; longer ones are out of range without int().
MAX_BYTE_DIGITS = 6

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

_R = Area.R

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
            self.area is _R  # not Area.R: an Enum member read from its class is slow (3.11)
            and RESULT_REGISTER_FIRST <= self.byte <= RESULT_REGISTER_LAST
        )

    def __str__(self) -> str:
        return format_address(self)


# each area's letter: a dict lookup is C-speed, Enum's `.value` a Python descriptor (3.11)
_LETTER: dict[Area, str] = {area: area.value for area in Area}


def format_address(address: Address) -> str:
    """Canonical spelling: area letter, byte without leading zeros, `.bit` for bits (`A21.0`)."""
    bit = address.bit
    if bit is None:
        return f"{_LETTER[address.area]}{address.byte}"
    return f"{_LETTER[address.area]}{address.byte}.{bit}"


def ranges_text(area: Area) -> str:
    """The area's byte ranges as text: `0-127, 200-327, ...`."""
    return ", ".join(f"{lo}-{hi}" for lo, hi in AREA_RANGES[area])


def byte_in_range(area: Area, byte: int, width: int = 1) -> bool:
    """True when bytes `byte` .. `byte + width - 1` all lie in one range of the area."""
    last = byte + max(width, 1) - 1
    return any(lo <= byte and last <= hi for lo, hi in AREA_RANGES[area])


def parse_address(text: str, *, want_bit: bool | None = None, width: int = 1) -> Address:
    """Parse `X2.1`, `A021.0`, `R0100`; `want_bit` True/False demands a bit/byte address.

    `width` is the number of bytes the address must have room for (for 2- and 4-byte data).
    Raises AddressError with a code: bad-address, unknown-area, byte-range, bit-range,
    bit-expected, byte-expected. Results are cached (the parser calls this for every operand).
    """
    return _parse_address(text, want_bit, width)


_SET_AREA, _SET_BYTE, _SET_BIT = (vars(Address)[name].__set__ for name in ("area", "byte", "bit"))
_new = object.__new__


def _new_address(area: Area, byte: int, bit: int | None) -> Address:
    """Address(area, byte, bit) made about twice as fast (the parser makes one per distinct
    operand): it sets the slots as the frozen dataclass's __init__ does, without its checks."""
    address = _new(Address)
    _SET_AREA(address, area)
    _SET_BYTE(address, byte)
    _SET_BIT(address, bit)
    return address


# the area of each letter, either case
_AREA_OF: dict[str, Area] = {**{a.value: a for a in Area}, **{a.value.lower(): a for a in Area}}


def _range_ids(area: Area) -> bytes:
    """At each byte number of the area, which of its ranges holds it (1, 2, ...; 0: none)."""
    ids = bytearray(AREA_SIZES[area])
    for number, (lo, hi) in enumerate(AREA_RANGES[area], start=1):
        ids[lo:hi + 1] = bytes([number]) * (hi - lo + 1)
    return bytes(ids)


# the common spelling (upper-case letter, up to 6 digits, an optional bit 0-7), read without
# the general checks: its first and last byte lie in one range of the area; anything else
# (and every error) takes the full path; its groups: letter, byte digits, bit digit
PLAIN_SPELLING = r"([XYFGRADTCKE])([0-9]{1,6})(?:\.([0-7]))?"
_PLAIN_RE = re.compile(PLAIN_SPELLING)
_PLAIN_AREAS: dict[str, tuple[Area, bytes]] = {a.value: (a, _range_ids(a)) for a in Area}


@lru_cache(maxsize=65536)
def parse_address_cached(text: str, want_bit: bool | None, width: int) -> Address:
    """parse_address with positional arguments: the parser's fast path calls it directly."""
    plain = _PLAIN_RE.fullmatch(text)
    if plain is not None:
        common, ids = _PLAIN_AREAS[plain.group(1)]
        number = int(plain.group(2))
        end = number + max(width, 1) - 1
        bit_digit = plain.group(3)
        if end < len(ids) and ids[number] and ids[number] == ids[end] and (
                want_bit is None or want_bit is (bit_digit is not None)):
            return _new_address(common, number,
                                None if bit_digit is None else ord(bit_digit) - 48)
    match = _ADDRESS_RE.match(text.strip())
    if not match:
        raise AddressError("bad-address", text=text)
    letter, byte_text, bit_text = match.groups()
    area = _AREA_OF.get(letter)
    if area is None:
        raise AddressError("unknown-area", text=text, area=letter.upper())
    if len(byte_text) <= MAX_BYTE_DIGITS:
        byte = int(byte_text)
    else:
        stripped = byte_text.lstrip("0") or "0"
        byte = int(stripped) if len(stripped) <= MAX_BYTE_DIGITS else -1
    last = byte + max(width, 1) - 1
    for lo, hi in AREA_RANGES[area]:
        if lo <= byte and last <= hi:
            break
    else:
        raise AddressError("byte-range", text=text, area=area.value,
                           last=AREA_SIZES[area] - max(width, 1), ranges=ranges_text(area))
    bit: int | None = None
    if bit_text is not None:
        if len(bit_text) > 1 or int(bit_text) > 7:
            raise AddressError("bit-range", text=text)
        bit = int(bit_text)
    if want_bit is True and bit is None:
        raise AddressError("bit-expected", text=text)
    if want_bit is False and bit is not None:
        raise AddressError("byte-expected", text=text)
    return _new_address(area, byte, bit)


# one text a line: the text and its plain spelling's parts, or nothing (every text makes one
# match)
_PLAIN_LINE_RE = re.compile(rf"({PLAIN_SPELLING})\n|[^\n]*\n")
_BIT_OF: dict[str, int] = {str(bit): bit for bit in range(8)}  # "" (no bit) is not a key


def parse_plain_addresses(texts: list[str]) -> dict[str, Address]:
    """`parse_address_cached(text, None, 1)` of each text of the common spelling (_PLAIN_RE)
    whose byte lies in its area, made in one go; the other texts are left out (the caller
    reads them the usual way). For the thousands of operands and symbols of a real program:
    one findall reads them all, and the objects are made by C loops (map)."""
    found = _PLAIN_LINE_RE.findall("\n".join(texts) + "\n")
    if len(found) != len(texts):  # a text with a line break: read them the usual way
        return {}
    return plain_addresses(found)


def plain_addresses(rows: Iterable[Sequence[str]]) -> dict[str, Address]:
    """parse_plain_addresses of texts a regex found with the parts of _PLAIN_RE: each row
    starts with the text, its letter, byte digits and bit digit ("" for none); a row whose
    letter is "" is of another spelling."""
    kept: list[str] = []
    letters: list[str] = []
    numbers: list[int] = []
    bits: list[str] = []
    plain = _PLAIN_AREAS
    for row in rows:
        letter = row[1]
        if letter:
            ids = plain[letter][1]
            number = int(row[2])
            if number < len(ids) and ids[number]:  # width 1: the byte is in one range
                kept.append(row[0])
                letters.append(letter)
                numbers.append(number)
                bits.append(row[3])
    made = list(map(_new, repeat(Address, len(kept))))
    deque(map(_SET_AREA, made, map(_AREA_OF.__getitem__, letters)), maxlen=0)
    deque(map(_SET_BYTE, made, numbers), maxlen=0)
    deque(map(_SET_BIT, made, map(_BIT_OF.get, bits)), maxlen=0)
    return dict(zip(kept, made, strict=True))


_parse_address = parse_address_cached
# the same parse without the cache, for texts read once (`check` reading a symbol table)
parse_address_once: Callable[[str, bool | None, int], Address] = parse_address_cached.__wrapped__


def looks_like_address(text: str) -> bool:
    """True when `text` has the shape of an address (letter, digits, optional `.bit`)."""
    return bool(_ADDRESS_RE.match(text.strip()))
