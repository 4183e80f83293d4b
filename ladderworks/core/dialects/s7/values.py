"""An S7 place's value as TIA's watch table shows and takes it: `TRUE`, `-7`, `1.5`, `T#5s`,
`16#0F`, `'A'`, `'Merhaba'`, `WSTRING#'Işık'` — read from and written to the engine's memory
by the place's declared type (layout.Place). For the watch table, scenarios and the CLI.
docs/dialects.md, "S7-1200: data types".
"""

from __future__ import annotations

import math

from ladderworks.core.address import Address
from ladderworks.core.dialects.s7.layout import Place, constant_value, string_value, time_ms
from ladderworks.core.dialects.s7.starts import STRING_CODEC, STRING_TYPE
from ladderworks.core.plc import typed
from ladderworks.core.plc.memory import Memory

_HEX = {typed.ValueType.BYTE: 2, typed.ValueType.WORD: 4, typed.ValueType.DWORD: 8}


def time_text(ms: int) -> str:
    """A Time as TIA's watch table shows it: `T#5S`, `T#1M_30S`, `T#-2S_500MS`."""
    sign, ms = ("-", -ms) if ms < 0 else ("", ms)
    parts = []
    for unit, size in (("D", 86_400_000), ("H", 3_600_000), ("M", 60_000), ("S", 1000)):
        if ms >= size:
            parts.append(f"{ms // size}{unit}")
            ms %= size
    if ms or not parts:
        parts.append(f"{ms}MS")
    return f"T#{sign}{'_'.join(parts)}"


def _quoted(text: str) -> str:
    out = []
    for char in text:
        if char == "'":
            out.append("$'")
        elif char == "$":
            out.append("$$")
        elif ord(char) < 32:
            out.append(f"${ord(char):02X}")
        else:
            out.append(char)
    return "'" + "".join(out) + "'"


def _string(memory: Memory, place: Place, wide: bool) -> str:
    data, at = memory.areas[place.address.area], place.address.byte
    if wide:
        maximum = int.from_bytes(data[at:at + 2], "big")
        length = min(int.from_bytes(data[at + 2:at + 4], "big"), maximum)
        chars = bytes(data[at + 4:at + 4 + 2 * length]).decode("utf-16-be", "replace")
        return "WSTRING#" + _quoted(chars)
    maximum, length = data[at], min(data[at + 1], data[at])
    del maximum
    return _quoted(bytes(data[at + 2:at + 2 + length]).decode(STRING_CODEC, "replace"))


def show(memory: Memory, place: Place) -> str:
    """The value at a place in TIA's spelling ("" for a type without one: a struct …)."""
    found = STRING_TYPE.match(place.type_name.strip())
    if found is not None:
        return _string(memory, place, bool(found.group(1)))
    vtype = place.vtype
    if vtype is None:
        return ""
    value = typed.read(memory, place.address, vtype)
    if vtype is typed.ValueType.BOOL:
        return "TRUE" if value else "FALSE"
    if vtype is typed.ValueType.TIME:
        return time_text(int(value))
    if vtype is typed.ValueType.CHAR:
        return _quoted(chr(int(value)))
    if vtype in _HEX:
        return f"16#{int(value):0{_HEX[vtype]}X}"
    if vtype in typed.FLOATS:
        number = float(value)
        if math.isnan(number) or math.isinf(number):
            return str(number)
        return repr(number) if vtype is typed.ValueType.LREAL else f"{number:.7g}"
    return str(int(value))


def store(memory: Memory, place: Place, text: str) -> None:
    """Write a value typed as TIA takes it at a place; ValueError when it is not one of its
    type (a String longer than its max length is cut, as TIA does)."""
    found = STRING_TYPE.match(place.type_name.strip())
    if found is not None:
        chars = string_value(text)
        if chars is None:
            raise ValueError(text)
        _store_string(memory, place.address, bool(found.group(1)), chars,
                      int(found.group(2) or 254))
        return
    vtype = place.vtype
    if vtype is None:
        raise ValueError(text)
    if vtype in typed.FLOATS:
        try:
            number = float(text.partition("#")[2] if "#" in text else text)
        except ValueError:
            raise ValueError(text) from None
        if vtype is typed.ValueType.REAL and math.isfinite(number) and \
                not typed.fits(number, vtype):  # past the largest Real: TIA refuses it
            raise ValueError(text)
        typed.write(memory, place.address, vtype, number)
        return
    value = time_ms(text) if vtype is typed.ValueType.TIME else constant_value(text, vtype)
    if value is None or not typed.fits(value, vtype):
        raise ValueError(text)
    typed.write(memory, place.address, vtype, value)


def _store_string(memory: Memory, at: Address, wide: bool, chars: str, maximum: int) -> None:
    data, byte = memory.areas[at.area], at.byte
    chars = chars[:maximum]
    if wide:
        raw = chars.encode("utf-16-be", "replace")
        data[byte:byte + 4] = maximum.to_bytes(2, "big") + len(chars).to_bytes(2, "big")
        data[byte + 4:byte + 4 + len(raw)] = raw
        return
    raw = chars.encode(STRING_CODEC, "replace")
    data[byte:byte + 2] = bytes([maximum, len(raw)])
    data[byte + 2:byte + 2 + len(raw)] = raw

