"""Small `.dvp` projects made for the tests, laid out as WPLSoft lays out its files
(docs/dialects.md, ".dvp projects"): header, scrambled program memory, settings, text sections."""

from __future__ import annotations

from ladderworks.core.dialects.delta.dvp_file import MAGIC, SETTINGS_SIZE

# LD X0 / TMR T0 K5 / LD T0 / OUT Y0 / LD X1 / RST T0 / END, as WPLSoft codes them
TIMER_WORDS = (0xA400, 0x8003, 0x0100, 0x0005, 0x0000, 0xA600, 0x4500, 0xA401, 0x8007,
               0x0600, 0x0206, 0x800F)
CAPACITY = 64  # steps of program memory (a real DVP has thousands)


def _section(name: str, body: bytes = b"") -> bytes:
    """One text section as WPLSoft writes it."""
    return (b"<TypeBegin>\nFunction=" + name.encode() + b"\n<TypeEnd>\n<DataBegin>\n" + body
            + b"<DataEnd>\n")


def cell(kind: int, device: int = 0, number: int = 0, flags: int = 0) -> bytes:
    """One 5-byte cell of the ladder drawing."""
    return bytes((kind, device)) + number.to_bytes(2, "little") + bytes((flags,))


LINE = cell(0x52)


def row(*cells: bytes) -> bytes:
    """A drawing row of 12 cells: the given ones, lines before the coil or box (else before the
    last cell) to fill it."""
    place = next((k for k, c in enumerate(cells) if c[0] in (0x32, 0x42)), len(cells) - 1)
    return b"".join(cells[:place]) + LINE * (12 - len(cells)) + b"".join(cells[place:])


def make_dvp(words: tuple[int, ...] = TIMER_WORDS, comments: bytes = b"X0$&start\n",
             version: int = 215, key: bytes = b"\x3c\x91\x5a\x07", title: bytes = b"sample",
             capacity: int = CAPACITY, drawing: bytes = b"") -> bytes:
    """A project holding `words` (the NOP filler after them), the ladder `drawing` (rows of
    cells) and the comment lines."""
    header = bytearray(0x100)
    header[0:4] = MAGIC
    header[0x0E:0x0E + len(title)] = title
    header[0x4A:0x4C] = (5).to_bytes(2, "little")
    header[0x4C:0x4E] = version.to_bytes(2, "little")
    if version == 215:
        header[0x5E:0x62] = key
        stream = bytes((key[0], key[1] ^ 0x80, key[2], key[3] ^ 0x80))
    else:
        header[0x56 if version == 214 else 0x5E] = key[0]
        stream = bytes((key[0], key[0] ^ 0x80, key[0], key[0] ^ 0x80))
    plain = b"".join(w.to_bytes(2, "little") for w in words)
    plain += b"\xff\x7f" * (capacity - len(words))
    program = bytes(b ^ stream[i % 4] for i, b in enumerate(plain))
    sections = (_section("Initial Value") + b"\x01" + bytes(257)
                + len(drawing).to_bytes(4, "little") + b"\x00" + drawing + bytes(64)
                + _section("Device Comment", comments) + _section("Output Comment")
                + _section("Symbol Table") + _section("Device Comment Range", b"Group=0\n"))
    return (bytes(header) + program + bytes(SETTINGS_SIZE) + sections
            + b"<SegCmt>\n</SegCmt>\n<PrjectEnd>\n")
