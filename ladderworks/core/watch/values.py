"""A watched value in a display format, as TIA's watch table shows it, and a typed modify value
read back into the bytes it writes (in the memory's byte order).

Formats: Bool (TRUE/FALSE), DEC (unsigned), DEC+/- (signed), Hex (`16#00FF`), Bin
(`2#0000_0101`), Real (LReal in 8 bytes), Time (`T#1M_30S_500MS`; 8 bytes: an LTime
`LT#5S_3NS`), Date (`D#2024-01-31`), Time_Of_Day (`TOD#12:30:00.000`), Char (`'A'`), String
(`'text'`, an S7 String: max length, length, characters); values of 1, 2, 4 or 8 bytes.
docs/plc-utilities.md, "Watch table".
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.watch import dates
from ladderworks.core.watch.places import WatchError, WatchPlace

TIME_UNITS = (("D", 86_400_000), ("H", 3_600_000), ("M", 60_000), ("S", 1000), ("MS", 1))
_TIME_RE = re.compile(r"(\d+(?:\.\d+)?)(ms|d|h|m|s)", re.I)
_INT_RE = re.compile(r"[+-]?\d+")
MAX_TEXT = 300  # a modify value longer than this is none (a String holds at most 254)


class Format(StrEnum):
    """A display format of the watch table."""

    BOOL = "bool"
    DEC = "dec"
    SDEC = "sdec"
    HEX = "hex"
    BIN = "bin"
    REAL = "real"
    TIME = "time"
    DATE = "date"
    TOD = "tod"
    CHAR = "char"
    STRING = "string"


# a type's display format by default (TIA's), by the type name in lower case
_TYPE_FORMATS = {"bool": Format.BOOL, "sint": Format.SDEC, "int": Format.SDEC,
                 "dint": Format.SDEC, "usint": Format.DEC, "uint": Format.DEC,
                 "udint": Format.DEC, "byte": Format.HEX, "word": Format.HEX,
                 "dword": Format.HEX, "real": Format.REAL, "time": Format.TIME,
                 "char": Format.CHAR, "lreal": Format.REAL, "lint": Format.SDEC,
                 "ulint": Format.DEC, "lword": Format.HEX, "ltime": Format.TIME,
                 "date": Format.DATE, "tod": Format.TOD, "time_of_day": Format.TOD}


def formats(place: WatchPlace) -> list[Format]:
    """The display formats a place can be shown in."""
    if place.is_bit:
        return [Format.BOOL, Format.DEC, Format.HEX, Format.BIN]
    if place.string_length is not None:
        return [Format.STRING, Format.HEX]
    found = [Format.DEC, Format.SDEC, Format.HEX, Format.BIN]
    if place.width in (4, 8):
        found += [Format.REAL, Format.TIME]
    if place.width == 4:
        found.append(Format.TOD)
    if place.width == 2:
        found.append(Format.DATE)
    if place.width == 1:
        found.append(Format.CHAR)
    return found


def default_format(place: WatchPlace, dialect: str | None) -> Format:
    """The format a new row shows: the type's (TIA's), else the family's for a word."""
    if place.is_bit:
        return Format.BOOL
    if place.string_length is not None:
        return Format.STRING
    found = _TYPE_FORMATS.get(place.type_name.strip().lower())
    if found is not None:
        return found
    family = dialects.get(dialect)
    untyped = Format(family.untyped_format) if family is not None else Format.SDEC
    return untyped if untyped in formats(place) else Format.SDEC


@dataclass(frozen=True, slots=True)
class Memory:
    """What the table reads: a bit, and `width` bytes unsigned in the memory's byte order."""

    bit: Callable[[Address], int]
    read: Callable[[Address, int], int]


def _limits(width: int, signed: bool) -> tuple[int, int]:
    """The range of an integer of `width` bytes (SInt … LInt, USInt … ULInt)."""
    bits = 8 * width
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)


def _signed(raw: int, width: int) -> int:
    bits = 8 * width
    return raw - (1 << bits) if raw >> (bits - 1) & 1 else raw


def time_text(ms: int) -> str:
    """Milliseconds as TIA writes a Time (`T#1D_2H_3M_4S_5MS`, `T#-2S`, `T#0MS`)."""
    sign, rest = ("-", -ms) if ms < 0 else ("", ms)
    parts = []
    for unit, size in TIME_UNITS:
        count, rest = divmod(rest, size)
        if count:
            parts.append(f"{count}{unit}")
    return f"T#{sign}{'_'.join(parts) or '0MS'}"


def _real_text(value: float) -> str:
    return f"{value:.7g}" if typed.fits(value, typed.ValueType.REAL) else str(value)


def _grouped(digits: str) -> str:
    """Binary digits in groups of four (`0000_0101`)."""
    return "_".join(digits[i:i + 4] for i in range(0, len(digits), 4))


def _char_text(code: int) -> str:
    return f"'{chr(code)}'" if 32 <= code < 127 or code >= 160 else f"'${code:02X}'"


def show(place: WatchPlace, fmt: Format, memory: Memory) -> str:
    """The value at `place` in `fmt` (the raw bytes read in the memory's byte order)."""
    if place.is_bit:
        value = memory.bit(place.address)
        shown = {Format.BOOL: "TRUE" if value else "FALSE", Format.HEX: f"16#{value}",
                 Format.BIN: f"2#{value}"}
        return shown.get(fmt, str(value))
    length = place.string_length
    if length is not None and fmt is Format.STRING:
        used = min(memory.read(Address(place.address.area, place.address.byte + 1), 1), length)
        text = "".join(chr(memory.read(Address(place.address.area,
                                               place.address.byte + 2 + i), 1))
                       for i in range(used))
        return f"'{text}'"
    width = min(place.width, 8)
    raw = memory.read(place.address, width)
    if fmt is Format.HEX:
        return f"16#{raw:0{2 * width}X}"
    if fmt is Format.BIN:
        return "2#" + _grouped(f"{raw:0{8 * width}b}")
    if fmt is Format.SDEC:
        return str(_signed(raw, width))
    if fmt is Format.REAL and width == 4:
        return _real_text(typed.bits_real(raw))
    if fmt is Format.REAL and width == 8:
        return repr(typed.bits_lreal(raw))  # every digit an LReal holds
    if fmt is Format.TIME and width == 4:
        return time_text(_signed(raw, 4))
    if fmt is Format.TIME and width == 8:
        return dates.ltime_text(_signed(raw, 8))
    if fmt is Format.DATE and width == 2:
        return dates.date_text(raw)
    if fmt is Format.TOD and width == 4:
        return dates.tod_text(raw)
    if fmt is Format.CHAR and width == 1:
        return _char_text(raw)
    return str(raw)


@dataclass(frozen=True, slots=True)
class Write:
    """One store a modify makes: a bit (`width` 0) or `width` bytes of `value` (unsigned)."""

    address: Address
    value: int
    width: int = 0


def _number(text: str) -> int | None:
    """An integer as typed: `12`, `-3`, `16#FF`, `2#0101`, `0x1F`, `0b11`, `8#17`."""
    clean = text.strip().replace("_", "")
    if len(clean) > MAX_TEXT:
        return None
    head, sep, digits = clean.partition("#")
    try:
        if sep and head in ("2", "8", "16"):
            return int(digits, int(head))
        if clean[:2].lower() in ("0x", "0b"):
            return int(clean, 0)
        if _INT_RE.fullmatch(clean):
            return int(clean)
    except ValueError:
        return None
    return None


def time_ms(text: str) -> int | None:
    """A Time typed (`T#1m30s`, `T#5S_300MS`, `TIME#-2s`, or plain milliseconds `1500`)."""
    clean = text.strip().replace("_", "")
    if len(clean) > MAX_TEXT:
        return None
    if _INT_RE.fullmatch(clean):
        return int(clean)
    head, sep, body = clean.partition("#")
    if not sep or head.upper() not in ("T", "TIME"):
        return None
    sign = -1 if body.startswith("-") else 1
    body = body.lstrip("+-")
    total, at = 0.0, 0
    units = dict(TIME_UNITS)
    for match in _TIME_RE.finditer(body):
        if match.start() != at:
            return None
        total += float(match.group(1)) * units[match.group(2).upper()]
        at = match.end()
    if not body or at != len(body) or total > 1e15:  # far past any Time: not one
        return None
    return sign * round(total)


def _bool(text: str) -> int:
    low = text.strip().upper()
    if low in ("TRUE", "1", "ON"):
        return 1
    if low in ("FALSE", "0", "OFF"):
        return 0
    raise WatchError("watch-bool", text=text.strip())


def _in_range(value: int, low: int, high: int, text: str) -> int:
    if not low <= value <= high:
        raise WatchError("watch-range", text=text.strip(), low=low, high=high)
    return value


def _quoted(text: str) -> str:
    clean = text.strip()
    if len(clean) >= 2 and clean[0] == clean[-1] == "'":
        return clean[1:-1].replace("''", "'")
    return clean


def _string(place: WatchPlace, text: str, length: int) -> list[Write]:
    value = _quoted(text)
    if len(value) > length:
        raise WatchError("watch-string", text=text.strip(), length=length)
    try:
        data = value.encode("latin-1")
    except UnicodeEncodeError as error:
        raise WatchError("watch-latin1", text=text.strip()) from error
    base = place.address
    return [Write(Address(base.area, base.byte + 1), len(data), 1)] + [
        Write(Address(base.area, base.byte + 2 + i), byte, 1) for i, byte in enumerate(data)]


def parse(place: WatchPlace, fmt: Format, text: str) -> list[Write]:
    """The stores a modify value typed in `fmt` makes at `place` (a format the place has not:
    its first). WatchError (at the cell)."""
    if not text.strip():
        raise WatchError("watch-empty")
    if len(text) > MAX_TEXT:
        raise WatchError("watch-long", length=len(text), limit=MAX_TEXT)
    if fmt not in formats(place):
        fmt = formats(place)[0]
    if place.is_bit:
        value = _number(text) if fmt is not Format.BOOL else None
        return [Write(place.address, _bool(text) if value is None else
                      _in_range(value, 0, 1, text))]
    length = place.string_length
    if length is not None and fmt is Format.STRING:
        return _string(place, text, length)
    width = min(place.width, 8)
    bits = 8 * width
    if fmt in (Format.TIME, Format.DATE, Format.TOD) or (fmt is Format.REAL and width == 8):
        return [Write(place.address, _dated(fmt, width, text) & ((1 << bits) - 1), width)]
    if fmt is Format.REAL:
        try:
            real = float(text.strip().replace(",", "."))
        except ValueError as error:
            raise WatchError("watch-real", text=text.strip()) from error
        if not typed.fits(real, typed.ValueType.REAL):
            raise WatchError("watch-real", text=text.strip())
        return [Write(place.address, typed.real_bits(real) & 0xFFFFFFFF, width)]
    if fmt is Format.CHAR:
        chars = _quoted(text)
        if len(chars) != 1 or ord(chars) > 255:
            raise WatchError("watch-char", text=text.strip())
        return [Write(place.address, ord(chars), 1)]
    value = _number(text)
    if value is None:
        raise WatchError("watch-number", text=text.strip())
    low, high = _limits(width, True)
    if fmt is Format.DEC:
        low, high = _limits(width, False)
    elif fmt is not Format.SDEC:  # Hex, Bin: any pattern (a negative: its two's complement)
        high = _limits(width, False)[1]
    value = _in_range(value, low, high, text)
    return [Write(place.address, value & ((1 << bits) - 1), width)]


def _dated(fmt: Format, width: int, text: str) -> int:
    """A Time / LTime, Date, Time_Of_Day or LReal typed, as the value its bytes hold."""
    if fmt is Format.REAL:  # an LReal
        try:
            real = float(text.strip().replace(",", "."))
        except ValueError as error:
            raise WatchError("watch-real", text=text.strip()) from error
        if real != real or real in (float("inf"), float("-inf")):
            raise WatchError("watch-real", text=text.strip())
        return typed.lreal_bits(real)
    if fmt is Format.DATE:
        days = dates.date_days(text)
        if days is None:
            raise WatchError("watch-date", text=text.strip())
        return days
    if fmt is Format.TOD:
        ms = dates.tod_ms(text)
        if ms is None:
            raise WatchError("watch-tod", text=text.strip())
        return ms
    if width == 8:
        ns = dates.ltime_ns(text)
        if ns is None:
            raise WatchError("watch-time", text=text.strip())
        return ns
    ms = time_ms(text)
    if ms is None:
        raise WatchError("watch-time", text=text.strip())
    return _in_range(ms, *typed.limits(typed.ValueType.TIME), text)
