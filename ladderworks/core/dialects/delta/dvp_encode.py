"""Instructions back to `.dvp` program words: the inverse of dvp_codes, so a test can show the
decoding loses nothing (every real project's program memory re-encoded byte for byte).

LadderWorks still writes no `.dvp` file (dvp_program.save_refused): the header's checksum and
the ladder drawing beside the program are not decoded (docs/dialects.md, ".dvp projects")."""

from __future__ import annotations

import re
import struct

from ladderworks.core.dialects.delta.dvp_codes import (
    ALONE,
    API,
    BASIC,
    BIT_DEVICES,
    CONTACTS,
    COUNTER,
    DEVICE,
    LABEL_HIGH,
    NEST,
    OCTAL,
    TIMER,
    DvpInstruction,
    floating,
)

_ALONE = {name: code for code, name in ALONE.items()}
_CONTACTS = {name: nibble for nibble, name in CONTACTS.items()}
_BASIC = {name: (code, layout) for code, (name, layout) in BASIC.items()}
_API = {name: (code, wide_only) for code, (name, wide_only) in API.items()}
_DEVICE = re.compile(r"^([A-Z])(-?\d+)$")
_WORD_KIND = {"T": 0x02, "C": 0x04, "D": 0x06}


class DvpEncodeError(ValueError):
    """An instruction or operand the `.dvp` codes cannot hold."""


def _split(text: str) -> tuple[str, int]:
    """`X17` -> ("X", 15) (octal X/Y), `D10` -> ("D", 10)."""
    match = _DEVICE.match(text)
    if match is None:
        raise DvpEncodeError(text)
    letter = match.group(1)
    return letter, int(match.group(2), 8 if letter in OCTAL else 10)


def _bit_value(text: str) -> int:
    """The 12-bit address of a bit device (device nibble, number byte)."""
    letter, number = _split(text)
    for nibble, (known, base) in BIT_DEVICES.items():
        if known == letter and base <= number < base + 256:
            return nibble << 8 | (number - base)
    raise DvpEncodeError(text)


def _bytes_of(text: str, size: int, floating: bool) -> tuple[int, bytes]:
    """(tag, bytes) of a constant operand: K, H, or F in the floating-point instructions."""
    head, body = text[0], text[1:]
    if head == "K":
        return 0x00, int(body).to_bytes(size, "little", signed=True)
    if head == "H":
        return 0x02, int(body, 16).to_bytes(size, "little")
    if head == "F" and floating and size == 4:
        return 0x02, struct.pack("<f", float(body))
    raise DvpEncodeError(text)


def operand_words(text: str, size: int, floating: bool) -> list[int]:
    """An applied instruction's operand as `size` words."""
    letter = text[:1]
    if letter in ("K", "H") or (letter == "F" and floating):
        tag, data = _bytes_of(text, size, floating)
        return [tag << 8 | data[0], *data[1:]]
    if letter == "P":
        return [0x0800 | int(text[1:]), *([0] * (size - 1))]
    if letter in _WORD_KIND:
        value = 2 * _split(text)[1]
        kind = _WORD_KIND[letter]
        return [0x0600 | value & 0xFF, kind << 8 | value >> 8, *([0] * (size - 2))]
    value = _bit_value(text)
    return [0x0400 | value & 0xFF, value >> 8, *([0] * (size - 2))]


def _device_words(text: str) -> list[int]:
    """A basic instruction's device operand (RST, LDP, PLS ...)."""
    letter, number = _split(text)
    if letter == "D":
        return [0x0600 | (2 * number) & 0xFF, 0x0600 | (2 * number) >> 8]
    if letter in ("T", "C"):
        return [0x0600 | number, 0x0206 if letter == "T" else 0x040E]
    value = _bit_value(text)
    return [0x0400 | value & 0xFF, value >> 8]


def _basic_words(layout: tuple[str, ...], operands: tuple[str, ...]) -> list[int]:
    """The operand words of a basic instruction."""
    words: list[int] = []
    for kind, text in zip(layout, operands, strict=True):
        if kind in (TIMER, COUNTER):
            words.append((0x0100 if kind == TIMER else 0x0300) | _split(text)[1])
        elif kind in ("value", "value32"):
            words += operand_words(text, 2 if kind == "value" else 4, False)
        elif kind == DEVICE:
            words += _device_words(text)
        elif kind == NEST:
            words += [0x0800 | int(text[1:]), 0x0200]
    return words


def _applied(mnemonic: str) -> tuple[int, str]:
    """The code (with the D bit) and table name of an applied instruction's mnemonic."""
    if mnemonic in _API:
        code, wide_only = _API[mnemonic]
        return code | wide_only, mnemonic
    if mnemonic.startswith("D") and mnemonic[1:] in _API:
        return _API[mnemonic[1:]][0] | 1, mnemonic[1:]
    if mnemonic.startswith("?"):
        return int(mnemonic[1:], 16), ""
    raise DvpEncodeError(mnemonic)


def encode(instruction: DvpInstruction) -> list[int]:
    """The program words of one instruction."""
    name, operands = instruction.mnemonic, instruction.operands
    if name in _ALONE and not operands:
        return [_ALONE[name]]
    if name[:1] == "P" and name[1:].isdigit() and not operands:
        return [LABEL_HIGH << 8 | int(name[1:])]
    if name in _CONTACTS and len(operands) == 1:
        value = _bit_value(operands[0])
        if value >= 0x1000:  # M1536 and up: not in a contact's 12 bits
            raise DvpEncodeError(operands[0])
        return [_CONTACTS[name] << 12 | value]
    if name in _BASIC:
        code, layout = _BASIC[name]
        return [code, *_basic_words(layout, operands)]
    code, table_name = _applied(name)
    size = 4 if code & 1 else 2
    is_float = floating(table_name)
    return [code, *(word for text in operands for word in operand_words(text, size, is_float))]


def encode_all(instructions: list[DvpInstruction]) -> list[int]:
    """The program words of a list of instructions, in order."""
    return [word for each in instructions for word in encode(each)]
