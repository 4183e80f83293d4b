"""Start values: what an S7-1200 puts in its DBs and instances at a cold start, written by
LadderWorks in the first scan after RUN (%M1.0, FirstScan).

For every member laid out: its declared start value (`Count : Int := 3;`, an array's
`[1, 2, 3]` or `[3(0)]`), then a global DB's actual start values (a `.db` source's BEGIN
section, `Block.starts`), which win. A String or WString gets its maximum length even with no
start value, as the CPU keeps it (header: max length, actual length; then the characters).
LReal constants a 32-bit parameter cannot hold are written to their places here.
docs/dialects.md, "S7-1200: data types".
"""

from __future__ import annotations

import re

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.s7.graph import Block
from ladderworks.core.dialects.s7.layout import (
    Layout,
    Place,
    constant_value,
    element,
    string_value,
)
from ladderworks.core.il.program import Instruction, Network
from ladderworks.core.plc import typed

FIRST_SCAN = Address(Area.R, 1, 0)  # %M1.0
STRING_TYPE = re.compile(r"^(w?)string(?:\s*\[\s*(\d+)\s*\])?$", re.I)
_REPEAT_RE = re.compile(r"^(\d+)\s*\((.*)\)$")
STRING_CODEC = "cp1254"  # a String's characters: one byte each (docs/dialects.md)


def _move(vtype: typed.ValueType, value: int, address: Address) -> Instruction:
    return Instruction("S7.MOVE", None, (int(vtype), value, address))


def lreal_constant(layout: Layout, text: str) -> Address | None:
    """The place of an LReal constant a Real cannot hold exactly, None if `text` is no number."""
    try:
        value = float(text.partition("#")[2] if "#" in text else text)
    except ValueError:
        return None
    return layout.lreal_constant(value)


def string_moves(place: Place, text: str | None) -> list[Instruction]:
    """The moves that make a String/WString place hold `text` (None: only its max length)."""
    found = STRING_TYPE.match(place.type_name.strip())
    if found is None:
        return []
    wide = bool(found.group(1))
    length = int(found.group(2) or 254)
    base = place.address
    chars = (text or "")[:length]
    if wide:
        code = [_move(typed.ValueType.WORD, length, base),
                _move(typed.ValueType.WORD, len(chars), Address(base.area, base.byte + 2))]
        return code + [_move(typed.ValueType.WORD, ord(c) & 0xFFFF,
                             Address(base.area, base.byte + 4 + 2 * n))
                       for n, c in enumerate(chars)]
    data = chars.encode(STRING_CODEC, "replace")
    code = [_move(typed.ValueType.BYTE, length, base),
            _move(typed.ValueType.BYTE, len(data), Address(base.area, base.byte + 1))]
    return code + [_move(typed.ValueType.BYTE, byte, Address(base.area, base.byte + 2 + n))
                   for n, byte in enumerate(data)]


def _elements(text: str) -> list[str]:
    """An array initializer's values: `[1, 2, 3]`, `[3(0), 1]` as ["0", "0", "0", "1"]."""
    body = text.strip()
    if not (body.startswith("[") and body.endswith("]")):
        return []
    values: list[str] = []
    for item in re.split(r",(?=(?:[^']*'[^']*')*[^']*$)", body[1:-1]):
        item = item.strip()
        repeat = _REPEAT_RE.match(item)
        if repeat is not None:
            values += [repeat.group(2).strip()] * min(int(repeat.group(1)), 100_000)
        else:
            values.append(item)  # "" for an element without a start value
    return values


def value_moves(layout: Layout, place: Place, text: str) -> list[Instruction]:
    """The moves that put one start value's text at a place (an array: element by element)."""
    if STRING_TYPE.match(place.type_name.strip()):
        chars = string_value(text)
        return string_moves(place, chars) if chars is not None else []
    elements = _elements(text)
    if elements:
        found = re.match(r"(?i)^array\s*\[\s*(-?\d+)", place.type_name.strip())
        low = int(found.group(1)) if found else 0
        code: list[Instruction] = []
        for n, item in enumerate(elements):
            inner = element(place, str(low + n))
            if inner is None:
                break
            if item:
                code += value_moves(layout, inner, item)
        return code
    vtype = place.vtype
    if vtype is None:
        return []
    value = constant_value(text, vtype)
    if value is None and vtype is typed.ValueType.LREAL:
        address = lreal_constant(layout, text)
        if address is not None:  # copied from the constant's place, written first
            return [Instruction("S7.MOVE", None, (int(vtype), address, place.address))]
    if value is None:
        return []
    return [_move(vtype, value, place.address)]


def _constants(layout: Layout) -> list[Instruction]:
    code = []
    for bits, address in layout.constants.items():
        high, low = bits >> 32, bits & 0xFFFFFFFF
        code.append(_move(typed.ValueType.DWORD, high - (1 << 32) if high >> 31 else high,
                          address))
        code.append(_move(typed.ValueType.DWORD, low - (1 << 32) if low >> 31 else low,
                          Address(address.area, address.byte + 4)))
    return code


def _db_starts(layout: Layout, block: Block) -> list[Instruction]:
    key = (block.name.lower(),)
    if key not in layout.places:
        return []
    code: list[Instruction] = []
    for path, text in block.starts.items():
        place = layout.sub(key, path)
        if place is not None:
            code += value_moves(layout, place, text)
    return code


def start_values(layout: Layout) -> Network | None:
    """The first-scan network writing every start value (see the module's docstring)."""
    code: list[Instruction] = []
    for key, member in list(layout.members.items()):
        place = layout.places.get(key)
        if place is None:
            continue
        if member.start:
            code += value_moves(layout, place, member.start)
        elif STRING_TYPE.match(place.type_name.strip()):
            code += string_moves(place, None)
    for block in layout.program.blocks:
        if block.starts and block.kind in ("GlobalDB", "InstanceDB"):
            code += _db_starts(layout, block)
    code = _constants(layout) + code
    if not code:
        return None
    return Network([Instruction("RD", FIRST_SCAN), *code], ["Start values"])
