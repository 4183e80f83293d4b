"""The ladder drawing a `.dvp` project keeps beside its program: read where the project holds no
compiled instruction list (saved in WPLSoft without compiling), rungs in series only.

The drawing (docs/dialects.md, ".dvp projects"): after the Initial Value section, 258 bytes on,
a 32-bit byte count, then rows of 12 five-byte cells (type, device type, 16-bit number, flags):
`12`/`22`/`B2`/`C2` a contact (open, closed, rising, falling), `D2` INV/PN/NP, `32` a coil,
`42` a box (its code), `E2` a comparison contact (its place in the family), `80` an operand
(`90` its high 16 bits), `52` a line. A cell of any other type (branches ...) or a pointer is
not read: the drawing is then not used."""

from __future__ import annotations

from ladderworks.core.dialects.delta.dvp_codes import (
    API,
    BASIC,
    DvpInstruction,
    device_text,
    float_text,
)
from ladderworks.core.dialects.delta.dvp_encode import DvpEncodeError, encode

DRAWING_AT = 258  # from the end of the Initial Value section's <DataEnd> line
CELL = 5
ROW = 12
MOST_CELLS = 100_000
CONTACT, CLOSED, COIL, BOX, COMPARE, OPERAND, HIGH, LINE = (
    0x12, 0x22, 0x32, 0x42, 0xE2, 0x80, 0x90, 0x52)
RISING, FALLING, LOGIC = 0xB2, 0xC2, 0xD2  # edge contacts; INV, PN, NP (by the device byte)
_CONTACTS = {CONTACT: ("LD", "AND"), CLOSED: ("LDI", "ANI"), RISING: ("LDP", "ANDP"),
             FALLING: ("LDF", "ANDF")}
_LOGIC = {0: "INV", 1: "PN", 2: "NP"}
WIDE_FLAG = 0x10  # a 32-bit (D) form
SET_BOX = 0xD000
DEVICES = {0x09: "X", 0x0A: "Y", 0x05: "M", 0x07: "T", 0x01: "C", 0x02: "D"}
CONSTANT, FLOAT, NEST = 0x04, 0x03, 0x0D  # K; F (with its high half); MC's N
# the pointers P n are not in the grid (a table after it, not decoded): a drawing with a jump,
# a call or a subroutine (operand type 0x0C P; FEND, SRET, IRET) is not read
_PROGRAM_FLOW = frozenset(("FEND", "SRET", "IRET"))
# comparison contacts by their place: 2k (+1 in the 32-bit form) for =, >, <, <>, <=, >=, &,
# |, ^; 0x16 + k for the floating-point FLD=, FLD> ... FLD>=
_COMPARE = ("=", ">", "<", "<>", "<=", ">=", "&", "|", "^")
_FLOAT = ("=", ">", "<", "<>", "<=", ">=")


class DrawingError(ValueError):
    """A drawing cell the reader does not take: its byte `offset`."""

    def __init__(self, offset: int) -> None:
        super().__init__(f"drawing cell at byte {offset}")
        self.offset = offset


def _number(cell: bytes) -> int:
    """The cell's 16-bit number."""
    return cell[2] | cell[3] << 8


def _device(cell: bytes, offset: int) -> str:
    """The device a contact, coil or operand cell names."""
    letter = DEVICES.get(cell[1])
    if letter is None:
        raise DrawingError(offset)
    return device_text(letter, _number(cell))


def _operand(cell: bytes, high: bytes | None, offset: int) -> str:
    """An operand cell (and its high half) as text."""
    if cell[1] == NEST and high is None:
        return f"N{_number(cell)}"
    if cell[1] == FLOAT and high is not None:
        text = float_text(cell[2:4] + high[2:4])
        if text is None:
            raise DrawingError(offset)
        return f"F{text}"
    if cell[1] != CONSTANT:
        if high is not None and any(high[2:4]):
            raise DrawingError(offset)
        return _device(cell, offset)
    value = _number(cell) | (_number(high) << 16 if high is not None else 0)
    bits = 32 if high is not None else 16
    return f"K{value - (1 << bits) if value >> (bits - 1) else value}"


def _compare(cell: bytes, first: bool, offset: int) -> str:
    """A comparison contact's mnemonic: LD-like at the start of a rung, AND-like after."""
    place = _number(cell)
    start = "LD" if first else "AND"
    if place < 2 * len(_COMPARE):
        wide = place & 1
        if bool(wide) != bool(cell[4] & WIDE_FLAG):
            raise DrawingError(offset)
        return ("D" if wide else "") + start + _COMPARE[place // 2]
    if 0x16 <= place < 0x16 + len(_FLOAT):
        return "F" + start + _FLOAT[place - 0x16]
    raise DrawingError(offset)


def _box(cell: bytes, offset: int) -> str:
    """A box's mnemonic, from its code."""
    code = _number(cell)
    if code == SET_BOX:
        return "SET"
    basic = BASIC.get(0x8000 | code)
    if basic is not None:
        return basic[0]
    if code == 0x000F:
        return "END"
    found = API.get(0x8000 | code & ~1)
    if found is None or bool(code & 1) != bool(cell[4] & WIDE_FLAG):
        raise DrawingError(offset)
    name, wide_only = found
    return "D" + name if code & 1 and not wide_only else name


def _operands(row: list[bytes], place: int, at: int) -> tuple[tuple[str, ...], int]:
    """The operand cells from `place` in a row: their texts and the place after them."""
    texts: list[str] = []
    while place < len(row) and row[place][0] == OPERAND:
        high = row[place + 1] if place + 1 < len(row) and row[place + 1][0] == HIGH else None
        texts.append(_operand(row[place], high, at + CELL * place))
        place += 2 if high is not None else 1
    return tuple(texts), place


def _row(row: list[bytes], at: int) -> list[tuple[str, tuple[str, ...]]]:
    """One row of the drawing as instructions (mnemonic, operands)."""
    found: list[tuple[str, tuple[str, ...]]] = []
    first = True
    place = 0
    while place < len(row):
        cell, offset = row[place], at + CELL * place
        kind = cell[0]
        if kind == LINE:
            place += 1
        elif kind in _CONTACTS:
            found.append((_CONTACTS[kind][not first], (_device(cell, offset),)))
            first, place = False, place + 1
        elif kind == LOGIC and cell[1] in _LOGIC and not any(cell[2:]):
            found.append((_LOGIC[cell[1]], ()))
            place += 1
        elif kind == COIL:
            found.append(("OUT", (_device(cell, offset),)))
            place += 1
        elif kind in (BOX, COMPARE):
            name = _box(cell, offset) if kind == BOX else _compare(cell, first, offset)
            if name in _PROGRAM_FLOW:
                raise DrawingError(offset)
            operands, place = _operands(row, place + 1, at)
            found.append((name, operands))
            first = first and kind == BOX
        else:
            raise DrawingError(offset)
    return found


def drawing_program(data: bytes, section_end: int) -> list[DvpInstruction]:
    """The instructions the drawing after `section_end` holds ([] for an empty drawing);
    raises DrawingError at a cell it does not read (or a drawing that does not fit)."""
    at = section_end + DRAWING_AT
    size = int.from_bytes(data[at:at + 4], "little") if at + 4 <= len(data) else -1
    first = at + CELL
    if size < 0 or size % (CELL * ROW) or size > CELL * MOST_CELLS or first + size > len(data):
        raise DrawingError(at)
    found: list[DvpInstruction] = []
    step = 0
    for start in range(first, first + size, CELL * ROW):
        cells = [data[start + CELL * k:start + CELL * (k + 1)] for k in range(ROW)]
        for name, operands in _row(cells, start):
            instruction = DvpInstruction(step, name, operands)
            try:  # the steps it would take, as compiled
                step += len(encode(instruction))
            except (DvpEncodeError, ValueError):
                raise DrawingError(start) from None
            found.append(instruction)
    return found
