"""The instruction codes of a WPLSoft `.dvp` project: 16-bit words -> mnemonics and operands.

Learned from public WPLSoft projects (docs/dialects.md, ".dvp projects"): each program step is
one little-endian word. A word of 0x1000 or more starts an instruction; the operand words after
it are below 0x1000, each one operand byte (low) and a tag (high). Only codes seen in real
projects, or in an API family whose numbering those projects confirm, are in the tables.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

OPERAND_LIMIT = 0x1000  # words below this are operand words
NOP = 0x7FFF  # the word WPLSoft fills the unused program memory with
END = 0x800F

# contacts and coils with the device in the word: high nibble = instruction, next = device
CONTACTS = {0xA: "LD", 0xB: "LDI", 0xC: "AND", 0xD: "ANI", 0xE: "OR", 0xF: "ORI",
            0x4: "OUT", 0x5: "SET"}
# A bit device is its Delta device address (DVP programming manual, "PLC device address"):
# S 0x000+n, X 0x400+n, Y 0x500+n, T 0x600+n, M0-M1535 0x800+n, C 0xE00+n, M1536-M4095
# 0xB000+(n-1536). High byte -> (letter, first number); the contact words hold 12 bits only.
BIT_DEVICES = {0x0: ("S", 0), 0x1: ("S", 256), 0x2: ("S", 512), 0x3: ("S", 768),
               0x4: ("X", 0), 0x5: ("Y", 0), 0x6: ("T", 0), 0x8: ("M", 0), 0x9: ("M", 256),
               0xA: ("M", 512), 0xB: ("M", 768), 0xC: ("M", 1024), 0xD: ("M", 1280),
               0xE: ("C", 0),
               **{0xB0 + k: ("M", 1536 + 256 * k) for k in range(10)}}
OCTAL = frozenset("XY")
LABEL_HIGH = 0x30  # 0x30nn: the pointer P nn

# instructions alone in their word
ALONE = {0x7FF6: "PN", 0x7FF7: "NP", 0x7FF8: "ANB", 0x7FF9: "ORB", 0x7FFA: "MPS",
         0x7FFB: "MRD", 0x7FFC: "MPP", 0x7FFD: "INV", NOP: "NOP", END: "END"}

# basic instructions with operand words, and how their operands are laid out
TIMER, COUNTER, DEVICE, NEST = "timer", "counter", "device", "nest"
BASIC: dict[int, tuple[str, tuple[str, ...]]] = {
    0x8003: ("TMR", (TIMER, "value")), 0x8005: ("CNT", (COUNTER, "value")),
    0x8006: ("DCNT", (COUNTER, "value32")), 0x8007: ("RST", (DEVICE,)),
    0x800A: ("MC", (NEST,)), 0x800B: ("MCR", (NEST,)),
    0x8101: ("LDP", (DEVICE,)), 0x8102: ("LDF", (DEVICE,)), 0x8103: ("ANDP", (DEVICE,)),
    0x8104: ("ANDF", (DEVICE,)), 0x8105: ("ORP", (DEVICE,)), 0x8106: ("ORF", (DEVICE,)),
    0x8107: ("PLS", (DEVICE,)), 0x8108: ("PLF", (DEVICE,)),
}
# applied instructions seen in real projects whose code the API numbering above does not give
SEEN = {0x81B4: ("SCLP", False)}

# Delta's API numbers (DVP programming manual) of the applied instructions the codes reach:
# code = 0x8000 + 2 * (API + offset) + 1 for the 32-bit (D) form
_API_LOW = {  # offset 8
    0: "CJ", 1: "CALL", 2: "SRET", 3: "IRET", 4: "EI", 5: "DI", 6: "FEND", 7: "WDT",
    8: "FOR", 9: "NEXT", 10: "CMP", 11: "ZCP", 12: "MOV", 13: "SMOV", 14: "CML", 15: "BMOV",
    16: "FMOV", 17: "XCH", 18: "BCD", 19: "BIN", 20: "ADD", 21: "SUB", 22: "MUL", 23: "DIV",
    24: "INC", 25: "DEC", 26: "WAND", 27: "WOR", 28: "WXOR", 29: "NEG", 30: "ROR", 31: "ROL",
    32: "RCR", 33: "RCL", 34: "SFTR", 35: "SFTL", 36: "WSFR", 37: "WSFL", 38: "SFWR",
    39: "SFRD", 40: "ZRST", 41: "DECO", 42: "ENCO", 43: "SUM", 44: "BON", 45: "MEAN",
    46: "ANS", 47: "ANR", 48: "SQR", 49: "FLT", 50: "REF", 51: "REFF", 52: "MTR", 53: "HSCS",
    54: "HSCR", 55: "HSZ", 56: "SPD", 57: "PLSY", 58: "PWM", 59: "PLSR", 60: "IST", 61: "SER",
    62: "ABSD", 63: "INCD", 64: "TTMR", 65: "STMR", 66: "ALT", 67: "RAMP", 68: "DTM",
    69: "SORT", 70: "TKY", 71: "HKY", 72: "DSW", 73: "SEGD", 74: "SEGL", 75: "ARWS", 76: "ASC",
    77: "PR", 78: "FROM", 79: "TO", 80: "RS", 81: "PRUN", 82: "ASCI", 83: "HEX", 84: "CCD",
    85: "VRRD", 86: "VRSC", 87: "ABS", 88: "PID", 110: "ECMP", 111: "EZCP", 112: "MOVR",
}
_API_FLOAT = {  # offset 16 (after the edge instructions' codes 0x8100..0x810F)
    120: "EADD", 121: "ESUB", 122: "EMUL", 123: "EDIV", 124: "EXP", 125: "LN", 126: "LOG",
    127: "ESQR", 128: "POW", 129: "INT", 130: "SIN", 131: "COS", 132: "TAN", 133: "ASIN",
    134: "ACOS", 135: "ATAN",
}
_LOGIC = {215: "&", 216: "|", 217: "^"}  # LD& ... OR^: API 215 + 3 * (LD, AND, OR)
_COMPARE = {0: "=", 1: ">", 2: "<", 4: "<>", 5: "<=", 6: ">="}  # LD= 224, AND= 232, OR= 240
_FLOAT_COMPARE = 275  # FLD= 275 .. FOR>= 292, offset 16, always 32-bit


def _api_table() -> dict[int, tuple[str, bool]]:
    """Code (without the D bit) -> (mnemonic, 32-bit only)."""
    table: dict[int, tuple[str, bool]] = {}
    for api, name in _API_LOW.items():
        table[0x8000 + 2 * (api + 8)] = (name, False)
    for api, name in _API_FLOAT.items():
        table[0x8000 + 2 * (api + 16)] = (name, False)
    for index, start in enumerate(("LD", "AND", "OR")):
        for offset, op in _LOGIC.items():
            table[0x8000 + 2 * (offset + 3 * index + 8)] = (start + op, False)
        for offset, op in _COMPARE.items():
            table[0x8000 + 2 * (224 + 8 * index + offset + 8)] = (start + op, False)
            table[0x8000 + 2 * (_FLOAT_COMPARE + 6 * index + _order(offset) + 16)] = (
                "F" + start + op, True)
    table.update(SEEN)
    return table


def _order(offset: int) -> int:
    """The place of a comparison among the six (=, >, <, <>, <=, >=)."""
    return offset if offset < 3 else offset - 1


API = _api_table()
_FLOATING = frozenset(("ECMP", "EZCP", "MOVR", *_API_FLOAT.values()))


def floating(name: str) -> bool:
    """True for an applied instruction (its table name, no D) whose constants are F floats."""
    return name in _FLOATING or name.startswith("F")


class DvpCodeError(ValueError):
    """A word that is not an instruction code or operand the tables know; `index` is its
    place among the program's words, `code` the diagnostic."""

    def __init__(self, code: str, index: int, word: int) -> None:
        super().__init__(f"{code} at word {index}: {word:#06x}")
        self.code = code
        self.index = index
        self.word = word
        self.read: list[DvpInstruction] = []  # the instructions before it (decode_words)


@dataclass(frozen=True, slots=True)
class DvpInstruction:
    """One decoded instruction: its step number, mnemonic and operand texts."""

    step: int
    mnemonic: str
    operands: tuple[str, ...] = ()
    known: bool = True  # False: a code the tables do not know (mnemonic `?CODE`)

    def text(self) -> str:
        """The instruction as WPLSoft's instruction list writes it: `LD X0`, `MOV K1 D0`."""
        return " ".join((self.mnemonic, *self.operands))


def device_text(letter: str, number: int) -> str:
    """`X17` (octal for X and Y), `M1000`."""
    return f"{letter}{number:o}" if letter in OCTAL else f"{letter}{number}"


def _bit_device(value: int, index: int, word: int) -> str:
    """A bit device from its address (device nibble, number byte)."""
    found = BIT_DEVICES.get(value >> 8)
    if found is None:
        raise DvpCodeError("dvp-unknown-device", index, word)
    letter, base = found
    return device_text(letter, base + (value & 0xFF))


_WORD_DEVICES = {0x02: "T", 0x04: "C", 0x06: "D"}


def _number(data: bytes) -> int:
    """A little-endian signed number of 2 or 4 bytes."""
    return int.from_bytes(data, "little", signed=True)


def float_text(data: bytes) -> str | None:
    """An F constant of 4 bytes, as short as it reads back; None when no decimal text does
    (not a finite number)."""
    value = struct.unpack("<f", data)[0]
    for digits in range(6, 10):  # the shortest text that reads back as the same 4 bytes
        text = f"{value:.{digits}g}"
        if "n" not in text and struct.pack("<f", float(text)) == data:
            return text if "e" in text or "." in text else text + ".0"
    return None


def operand(words: list[int], start: int, floating: bool) -> str:
    """The text of an applied instruction's operand (2 or 4 words from `start`); every bit of
    the words is accounted for (a word WPLSoft would not write is an error)."""
    tag = words[0] >> 8
    tags = [word >> 8 for word in words[1:]]
    data = bytes(word & 0xFF for word in words)
    if tag in (0x00, 0x02) and not any(tags):
        if tag == 0x00:
            return f"K{_number(data)}"
        text = float_text(data) if floating and len(data) == 4 else None
        return f"F{text}" if text is not None else f"H{int.from_bytes(data, 'little'):X}"
    if tag == 0x04 and not any(tags) and not any(data[2:]):
        return _bit_device(data[0] | data[1] << 8, start, words[0])
    if tag == 0x06 and not any(tags[1:]) and not any(data[2:]):
        letter = _WORD_DEVICES.get(tags[0])
        value = data[0] | data[1] << 8
        if letter is not None and not value % 2:
            return f"{letter}{value // 2}"
    if tag == 0x08 and not any(words[1:]):
        return f"P{data[0]}"
    raise DvpCodeError("dvp-bad-operand", start, words[0])


_RESET_KINDS = {0x0206: "T", 0x040E: "C"}  # the second word of RST T n, RST C n


def _device(words: list[int], start: int) -> str:
    """A basic instruction's device operand (two words: RST, LDP, PLS ...)."""
    tag = words[0] >> 8
    if tag == 0x04 and words[1] < 0x100:
        return _bit_device((words[0] & 0xFF) | words[1] << 8, start, words[0])
    if tag == 0x06:  # a word: D n as 2n; T n and C n as the number and a fixed word
        value = (words[0] & 0xFF) | (words[1] & 0xFF) << 8
        if words[1] >> 8 == 0x06 and not value % 2:
            return f"D{value // 2}"
        letter = _RESET_KINDS.get(words[1])
        if letter is not None:
            return f"{letter}{words[0] & 0xFF}"
    raise DvpCodeError("dvp-bad-operand", start, words[0])


def _basic(layout: tuple[str, ...], words: list[int], start: int) -> tuple[str, ...]:
    """The operands of a basic instruction with operand words."""
    texts: list[str] = []
    place = 0
    for kind in layout:
        if place + _SIZES[kind] > len(words):
            raise DvpCodeError("dvp-operand-count", start - 1, _at(words, 0))
        if kind in (TIMER, COUNTER):
            want = {TIMER: 0x01, COUNTER: 0x03}[kind]
            if words[place] >> 8 != want:
                raise DvpCodeError("dvp-bad-operand", start + place, _at(words, place))
            texts.append(("T" if kind == TIMER else "C") + str(words[place] & 0xFF))
            place += 1
        elif kind in ("value", "value32"):
            size = 2 if kind == "value" else 4
            texts.append(operand(words[place:place + size], start + place, False))
            place += size
        elif kind == DEVICE:
            texts.append(_device(words[place:place + 2], start + place))
            place += 2
        else:  # NEST: N n, then a word WPLSoft writes 0x0200
            if words[place] >> 8 != 0x08 or words[place + 1] != 0x0200:
                raise DvpCodeError("dvp-bad-operand", start + place, words[place])
            texts.append(f"N{words[place] & 0xFF}")
            place += 2
    if place != len(words):
        raise DvpCodeError("dvp-operand-count", start, _at(words, 0))
    return tuple(texts)


_SIZES = {TIMER: 1, COUNTER: 1, "value": 2, "value32": 4, DEVICE: 2, NEST: 2}


def _at(words: list[int], place: int) -> int:
    """words[place], or 0 past the end."""
    return words[place] if place < len(words) else 0


def _applied(code: int, words: list[int], start: int) -> tuple[str, tuple[str, ...]]:
    """An applied (API) instruction: mnemonic and operands."""
    found = API.get(code & ~1)
    if found is None:
        raise DvpCodeError("dvp-unknown-code", start - 1, code)
    name, wide_only = found
    return name if not code & 1 or wide_only else "D" + name, _operands(name, code, words, start)


def _operands(name: str, code: int, words: list[int], start: int) -> tuple[str, ...]:
    """An applied instruction's operands: 2 words each, 4 for the 32-bit (D) form."""
    wide = bool(code & 1)
    size = 4 if wide else 2
    if len(words) % size:
        raise DvpCodeError("dvp-operand-count", start - 1, code)
    return tuple(operand(words[place:place + size], start + place, floating(name))
                 for place in range(0, len(words), size))


def decode_one(code: int, words: list[int], start: int) -> tuple[str, tuple[str, ...]]:
    """The mnemonic and operand texts of the instruction `code` whose operand words, from word
    `start`, are `words`; raises DvpCodeError."""
    if code in ALONE or code >> 8 == LABEL_HIGH:
        if words:
            raise DvpCodeError("dvp-operand-count", start, words[0])
        if code >> 8 == LABEL_HIGH:
            return f"P{code & 0xFF}", ()
        return ALONE[code], ()
    name = CONTACTS.get(code >> 12)
    if name is not None:
        if words:
            raise DvpCodeError("dvp-operand-count", start, words[0])
        return name, (_bit_device(code & 0xFFF, start - 1, code),)
    basic = BASIC.get(code)
    if basic is not None:
        return basic[0], _basic(basic[1], words, start)
    if code >> 12 == 0x8:
        return _applied(code, words, start)
    raise DvpCodeError("dvp-unknown-code", start - 1, code)


def _decoded(code: int, words: list[int], start: int) -> tuple[str, tuple[str, ...], bool]:
    """decode_one, an unknown applied-instruction code kept as `?CODE` (known False)."""
    try:
        return (*decode_one(code, words, start), True)
    except DvpCodeError as error:
        if error.code != "dvp-unknown-code" or code >> 12 != 0x8:
            raise
        return f"?{code:04X}", _operands("", code, words, start), False


def decode_words(words: list[int]) -> list[DvpInstruction]:
    """The instructions of a program's words (up to END; the NOP filler after it is dropped);
    raises DvpCodeError at the first word it cannot read."""
    found: list[DvpInstruction] = []
    index = 0
    count = len(words)
    while index < count:
        code = words[index]
        if code < OPERAND_LIMIT:
            raise DvpCodeError("dvp-stray-operand", index, code)
        stop = index + 1
        while stop < count and words[stop] < OPERAND_LIMIT:
            stop += 1
        operand_words = words[index + 1:stop]
        try:
            mnemonic, operands, known = _decoded(code, operand_words, index + 1)
        except DvpCodeError as error:
            error.read = found
            raise
        found.append(DvpInstruction(index, mnemonic, operands, known))
        index = stop
        if code == END:
            break
    return found
