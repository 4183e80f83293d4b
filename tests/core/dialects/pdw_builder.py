"""Small WinProladder projects (`.pdw`) made for the tests, in the layout the real project has
(docs/dialects.md, ".pdw projects"): header, project record, the masked program image, units,
comments, the end record. Only what the reader reads is filled in."""

from __future__ import annotations

import random
import struct

from ladderworks.core.dialects.fatek.pdw_records import (
    COMMENT_TAG,
    END_TAG,
    MAGIC,
    PROGRAM_TAG,
    PROJECT_TAG,
    UNIT_TAG,
    checksum,
)

IMAGE_SIZE = 0xA000  # 32 blocks of 1280 bytes, as the real project's
CODE_START = 0x200


def record(tag: int, payload: bytes) -> bytes:
    """Tag, length, payload, checksum (the known rule; 0 for the masked records)."""
    summed = checksum(tag, payload) if tag in (PROJECT_TAG, UNIT_TAG, COMMENT_TAG) else 0
    return struct.pack("<HH", tag, len(payload)) + payload + struct.pack("<H", summed)


def image(words: list[int], fast: int = 50, mid: int = 100) -> bytes:
    """An erased program image holding `words` (big-endian) with its length and checksum."""
    data = bytearray(b"\xff" * IMAGE_SIZE)
    data[0:8] = b"FBS40110"
    code = b"".join(struct.pack(">H", word) for word in words)
    data[CODE_START:CODE_START + len(code)] = code
    little = struct.unpack(f"<{len(words)}H", code) if words else ()
    struct.pack_into("<H", data, 0xCA, (sum(little) - 1) & 0xFFFF)
    struct.pack_into("<H", data, 0x106, len(words))
    struct.pack_into("<HH", data, 0x1DA, fast, mid)
    data[0x1FC:0x1FE] = b"\x55\xaa"
    return bytes(data)


def masked(payload: bytes, key: bytes) -> bytes:
    """`payload` XOR `key` repeated from its first byte."""
    stream = (key * (len(payload) // len(key) + 1))[:len(payload)]
    return (int.from_bytes(payload, "little") ^ int.from_bytes(stream, "little")).to_bytes(
        len(payload), "little")


def build(words: list[int], comments: dict[str, bytes] | None = None, *, seed: int = 7,
          sub_words: int = 0) -> bytes:
    """A .pdw of the given code words (Main_unit1; Sub_unit1 after it, empty unless
    `sub_words` of the words are its) and comments (device -> cp1250 text)."""
    key = random.Random(seed).randbytes(1280)
    head = bytearray(0x100)
    head[:len(MAGIC)] = MAGIC
    head[0x80:0x86] = b"FB-PLC"
    head[0x90:0x9C] = b"WinProladder"
    head[0xA0:0xA7] = b"HB1-14M"
    out = bytearray(head)
    out += record(PROJECT_TAG, struct.pack("<HHHH", 1, 4, 7, 0) + b"TESTHB1-14M")
    out += record(PROGRAM_TAG, masked(image(words), key))
    main_end = CODE_START + 2 * (len(words) - sub_words)
    sub_start = main_end if sub_words else main_end + 2
    for start, name in ((CODE_START, b"Main_unit1"), (sub_start, b"Sub_unit1")):
        out += record(UNIT_TAG, struct.pack("<HHH", start, len(name), 0) + name)
    for device, text in (comments or {}).items():
        name = device.encode("latin-1")
        out += record(COMMENT_TAG, struct.pack("<H", len(name)) + name
                      + struct.pack("<H", len(text)) + text + b"\0\0")
    out += struct.pack("<HH", END_TAG, 0) + b"\0\0"
    return bytes(out)
