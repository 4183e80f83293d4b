"""Fatek FBs devices: spellings, ranges, timer bases, counter widths, their place in memory."""

from __future__ import annotations

import re
from dataclasses import dataclass

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.devices import Device as MapDevice
from ladderworks.core.dialects.devices import DeviceMap

# Device kinds and their numbers (docs/dialects.md, Fatek: FBs-PLC manual's memory map; the
# seeds give only T0-T255 and C0-C255 (001:392-416, 572-588) and "see section 3.2" (002:99)).
BIT_RANGES: dict[str, tuple[int, int]] = {
    "X": (0, 255),  # inputs
    "Y": (0, 255),  # outputs
    "M": (0, 2001),  # internal relays; M1912-M2001 special
    "S": (0, 999),  # step relays
    "T": (0, 255),  # timer contacts
    "C": (0, 255),  # counter contacts
    "TR": (0, 39),  # temporary relays: 40 a network (002:361)
}
WORD_RANGES: dict[str, tuple[int, int]] = {
    "R": (0, 8071),  # registers: R0-R4167 and R5000-R8071 (ROR_RANGE); R4168-R4999 none
    "D": (0, 4095),  # data registers
    "T": (0, 255),  # timer present values (as a register operand)
    "C": (0, 255),  # counter present values (C200-C255 32-bit)
    "WX": (0, 240),  # X0-X255 as 16-bit words (WX0 = X0-X15, WX8 = X8-X23 …)
    "WY": (0, 240),
    "WM": (0, 1984),
    "WS": (0, 984),
}

# The R registers (FBs-PLC manual §5.2: R0-R8071 by indirect addressing, R3840-R4167 the IR, OR
# and SR registers; Fatek's Modbus table: R0-R4167, R5000-R5998). R0-R3839 general (R4128-R4134
# the real-time clock, 004:223-224), R3840-R3903 IR, R3904-R3967 OR, R3968-R4167 SR,
# R5000-R8071 ROR (or general registers). No R4168-R4999.
R_RANGES: tuple[tuple[int, int], ...] = ((0, 4167), (5000, 8071))
ROR_FIRST = 5000

# Special relays (the FBs-PLC manual's special relay table; docs/dialects.md)
FIRST_SCAN = 1924  # M1924: ON for the first scan after RUN
CLOCKS: dict[int, int] = {1920: 10, 1921: 100, 1922: 1000, 1923: 60_000}  # M: period in ms
SPECIAL_FIRST = 1912  # M1912-M2001 are special relays

# Timers: the base from the number (001:392-416)
TIMER_BASES: tuple[tuple[int, int, float], ...] = ((0, 49, 0.01), (50, 199, 0.1), (200, 255, 1.0))
# Counters: C0-C199 16-bit, C200-C255 32-bit; retentive C0-C139 and C200-C239 (001:572-588)
COUNTER_32_FIRST = 200
RETENTIVE_COUNTERS = ((0, 139), (200, 239))
INT16 = (-32768, 32767)
INT32 = (-(2**31), 2**31 - 1)


def timer_base_ms(number: int) -> int:
    """Milliseconds per count of timer Tn: 10, 100 or 1000 (001:392-416)."""
    for first, last, base in TIMER_BASES:
        if first <= number <= last:
            return round(base * 1000)
    raise ValueError(number)


def counter_is_32bit(number: int) -> bool:
    """True for C200-C255 (001:582-588)."""
    return number >= COUNTER_32_FIRST


def counter_is_retentive(number: int) -> bool:
    """True for C0-C139 and C200-C239 (001:576-588)."""
    return any(first <= number <= last for first, last in RETENTIVE_COUNTERS)


@dataclass(frozen=True, slots=True, order=True)
class Device:
    """A Fatek device as written: kind (`X`, `M`, `R`, `DR` …) and number."""

    kind: str
    number: int

    def __str__(self) -> str:
        return f"{self.kind}{self.number}"

    @property
    def is_double(self) -> bool:
        """A 32-bit register pair (DR, DD, DWX …) or a 32-bit counter's value."""
        return (len(self.kind) > 1 and self.kind[0] == "D") or (
            self.kind == "C" and counter_is_32bit(self.number))


class DeviceError(ValueError):
    """A spelling that is not a Fatek device, or a number out of its range."""

    def __init__(self, code: str, text: str, detail: str = "") -> None:
        super().__init__(text)
        self.code = code
        self.text = text
        self.detail = detail


_DEVICE_RE = re.compile(r"^(DWX|DWY|DWM|DWS|WX|WY|WM|WS|DR|DD|TR|X|Y|M|S|T|C|R|D)\s*(\d+)$",
                        re.I)
_CONSTANT_RE = re.compile(r"^[+-]?\d+$")


def parse_device(text: str, *, bit: bool) -> Device:
    """A device spelling (`X0`, `M1924`, `R100`, `X 0` as seed 002 writes it); `bit` chooses the
    bit ranges (contacts, coils) or the word ranges (function operands)."""
    match = _DEVICE_RE.match(text.strip())
    if match is None:
        raise DeviceError("fatek-device", text)
    kind = match.group(1).upper()
    number = int(match.group(2))
    base = kind[1:] if kind.startswith("D") and len(kind) > 1 and kind not in ("D",) else kind
    ranges = BIT_RANGES if bit else WORD_RANGES
    if base not in ranges or (bit and kind != base):
        raise DeviceError("fatek-device-kind", text, "bit" if bit else "word")
    low, high = ranges[base]
    if not low <= number <= high or (base == "R" and not _is_register(number)):
        spans = R_RANGES if base == "R" else ((low, high),)
        raise DeviceError("fatek-device-range", text,
                          ", ".join(f"{base}{first}-{base}{last}" for first, last in spans))
    if base in ("WX", "WY", "WM", "WS") and number % 8:
        raise DeviceError("fatek-device-range", text, f"{base}0, {base}8, {base}16 …")
    return Device(kind, number)


def _is_register(number: int) -> bool:
    """True for the numbers an R register has (R0-R4167, R5000-R8071)."""
    return any(first <= number <= last for first, last in R_RANGES)


def parse_constant(text: str) -> int | None:
    """A decimal constant operand (`7`, `-5`, `K10` is not Fatek), or None."""
    text = text.strip()
    return int(text) if _CONSTANT_RE.match(text) else None


# Where each device lives in the engine's memory (docs/dialects.md, Fatek, memory map): bits
# in X/Y as 8 a byte, the relays in R bytes, registers as little-endian words in D and E.
_BIT_BASE: dict[str, tuple[Area, int]] = {
    "X": (Area.X, 0),
    "Y": (Area.Y, 0),
    "M": (Area.R, 0),  # M0-M2001: R0.0-R250.1
    "S": (Area.R, 300),  # S0-S999: R300.0-R424.7
    "TR": (Area.R, 440),  # TR0-TR39: R440.0-R444.7
    "T": (Area.R, 450),  # T0-T255 contacts: R450.0-R481.7
    "C": (Area.R, 490),  # C0-C255 contacts: R490.0-R521.7
}
_WORD_BASE: dict[str, tuple[Area, int, int]] = {  # area, first byte, bytes per number
    "R": (Area.D, 0, 2),  # R0-R4167: D0-D8335 (R5000-R8071: _ROR_BASE)
    "D": (Area.E, 0, 2),  # D0-D4095: E0-E8191
    "T": (Area.R, 1000, 2),  # T0-T255 present values: R1000-R1511 (cleared at a load)
    "C": (Area.T, 0, 4),  # C0-C255 present values, 4 bytes each: T0-T1023 (kept: C0-C139)
}
_ROR_BASE = (Area.T, 2048)  # R5000-R8071: T2048-T8191 (kept on a cold start as R0-R4167)
FO_AREA = (Area.R, 2700)  # function outputs: one byte (FO0-FO7) a box, R2700 on
FO_BOXES = 6000  # boxes with outputs a program may have (R2700-R8699)
_WORD_OF_BITS = {"WX": "X", "WY": "Y", "WM": "M", "WS": "S"}


def bit_address(device: Device) -> Address:
    """The engine bit of a contact or coil device."""
    area, first = _BIT_BASE[device.kind]
    return Address(area, first + device.number // 8, device.number % 8)


def word_address(device: Device) -> tuple[Address, int]:
    """The engine byte address of a register device and its width in bytes (2 or 4)."""
    kind = device.kind
    double = len(kind) > 1 and kind[0] == "D"
    base = kind[1:] if double else kind
    if base in _WORD_OF_BITS:
        area, first = _BIT_BASE[_WORD_OF_BITS[base]]
        return Address(area, first + device.number // 8), 4 if double else 2
    area, first, size = _WORD_BASE[base]
    number = device.number
    if base == "R" and number >= ROR_FIRST:
        (area, first), number = _ROR_BASE, number - ROR_FIRST
    wide = double or (base == "C" and counter_is_32bit(device.number))
    return Address(area, first + size * number), 4 if wide else 2


def fo_address(index: int) -> Address:
    """The byte of the `index`-th function box's outputs (bit n = FOn)."""
    area, first = FO_AREA
    return Address(area, first + index)


def device_at(address: Address) -> Device | None:
    """The Fatek bit device an engine bit address shows (for names and the cross reference)."""
    if address.bit is None:
        return None
    for kind, (area, first) in _BIT_BASE.items():
        low, high = BIT_RANGES[kind]
        number = (address.byte - first) * 8 + address.bit
        if area is address.area and low <= number <= high:
            return Device(kind, number)
    return None


def word_device_at(address: Address) -> Device | None:
    """The Fatek register an engine byte address starts (R, D, T and C values)."""
    if address.bit is not None:
        return None
    area, first = _ROR_BASE
    if address.area is area and address.byte >= first and not (address.byte - first) % 2:
        number = ROR_FIRST + (address.byte - first) // 2
        if ROR_FIRST <= number <= R_RANGES[-1][1]:
            return Device("R", number)
    for kind, (area, first, size) in _WORD_BASE.items():
        offset = address.byte - first
        if address.area is area and offset >= 0 and not offset % size:
            low, high = R_RANGES[0] if kind == "R" else WORD_RANGES[kind]
            number = offset // size
            if low <= number <= high:
                return Device(kind, number)
    return None


def _map_device(kind: str, meaning: str, **where: object) -> MapDevice:
    low, high = BIT_RANGES.get(kind) or WORD_RANGES[kind]
    return MapDevice(kind, low, high, meaning, **where)  # type: ignore[arg-type]


# The address map of the dialect framework (spelling in the CLI, scenarios and the IDE)
DEVICES = DeviceMap((
    _map_device("X", "input", bits=_BIT_BASE["X"], read_only=True),
    _map_device("Y", "output", bits=_BIT_BASE["Y"]),
    _map_device("M", "internal relay", bits=_BIT_BASE["M"]),
    _map_device("S", "step relay", bits=_BIT_BASE["S"]),
    _map_device("TR", "temporary relay", bits=_BIT_BASE["TR"]),
    _map_device("T", "timer", bits=_BIT_BASE["T"], words=_WORD_BASE["T"][:2], stride=2),
    _map_device("C", "counter", bits=_BIT_BASE["C"], words=_WORD_BASE["C"][:2], stride=4,
                wide_from=COUNTER_32_FIRST),
    MapDevice("R", *R_RANGES[0], "register", words=_WORD_BASE["R"][:2], stride=2),
    MapDevice("R", *R_RANGES[1], "register (ROR)", words=_ROR_BASE, stride=2),
    _map_device("D", "data register", words=_WORD_BASE["D"][:2], stride=2),
    # not Fatek devices: the boxes' outputs (FO n of box k is FO(8k + n), its byte FOB k)
    MapDevice("FO", 0, 8 * FO_BOXES - 1, "function output", bits=FO_AREA),
    MapDevice("FOB", 0, FO_BOXES - 1, "function outputs of a box", words=FO_AREA, stride=1),
))
