"""WinProladder's project file (`.pdw`, header `Fatek WinProladder, File Format 1`): its records,
the program image they hold (XOR-masked) and the element comments (docs/dialects.md, ".pdw
projects" says what was learned from which material)."""

from __future__ import annotations

import struct
from collections import Counter
from dataclasses import dataclass, field

MAGIC = b"Fatek WinProladder, File Format 1"
FIRST_RECORD = 0x100  # the records follow a 256-byte header (magic, FB-PLC, model …)
MODEL_AT = 0xA0  # the PLC model, NUL-terminated, in the header
END_TAG = 0xFFFF
PROJECT_TAG = 0x1006  # project name and model
UNIT_TAG = 0x1001  # a program unit: its first byte in the image, its name
COMMENT_TAG = 0x1003  # an element comment: device and text
PROGRAM_TAG = 0x182A  # the program image (the PLC's program memory), masked
MASKED_TAGS = (0x182A, 0x182B)  # the program image and the PLC's comment memory, masked
SUMMED_TAGS = (PROJECT_TAG, UNIT_TAG, COMMENT_TAG)  # records whose checksum is known
KEY_PERIOD = 1280  # the mask repeats every 1280 bytes from each masked record's first byte
ERASED = 0xFF  # erased program memory
MAX_KEYS = 8  # the repeated blocks tried as the mask
MARK_AT = 0x1FC  # the program image's 55 AA (then 00 FF) before the code
MARK = b"\x55\xaa"
COMMENT_ENCODING = "cp1250"  # WinProladder writes comments in the Windows code page (cp1250 here)
RECORD_HEAD = 4  # tag and length, 16-bit little-endian each; the checksum follows the payload
RECORD_TAIL = 2
_HEAD = struct.Struct("<HH").unpack_from


class PdwError(Exception):
    """A .pdw that cannot be read: the diagnostic code, its byte offset and arguments."""

    def __init__(self, code: str, offset: int, **args: object) -> None:
        self.code = code
        self.offset = offset
        self.args_map: dict[str, object] = {"offset": offset, **args}
        super().__init__(f"{code} at byte {offset}")


@dataclass(frozen=True, slots=True)
class Record:
    """One record: its tag, where it starts in the file, its payload."""

    tag: int
    offset: int
    payload: bytes

    @property
    def payload_offset(self) -> int:
        """The file offset of the payload's first byte."""
        return self.offset + RECORD_HEAD


@dataclass(slots=True)
class PdwProject:
    """What a .pdw holds that LadderWorks reads: model, units, program image, comments."""

    model: str
    name: str
    image: bytes  # the program record unmasked
    image_offset: int  # its first byte in the file
    units: list[tuple[str, int]] = field(default_factory=list)  # name, first byte in the image
    comments: dict[str, str] = field(default_factory=dict)  # device (`M300`) -> text


_HIGH = bytes(range(0x80, 0x100))


def _text_bytes(tag: int, payload: bytes) -> bytes:
    """The text parts of a summed record (what its checksum adds as signed chars)."""
    if tag == UNIT_TAG:
        return payload[6:]
    if tag == PROJECT_TAG:
        return payload[8:]
    texts, at = [], 0
    while at + 2 <= len(payload):  # COMMENT_TAG: length-prefixed strings
        size = struct.unpack_from("<H", payload, at)[0]
        texts.append(payload[at + 2:at + 2 + size])
        at += 2 + size
    return b"".join(texts)


def checksum(tag: int, payload: bytes) -> int:
    """A record's checksum: its bytes summed, the text bytes as signed chars, 16 bits."""
    text = _text_bytes(tag, payload)
    high = len(text) - len(text.translate(None, _HIGH))  # bytes 0x80-0xFF
    return (sum(payload) - 256 * high) & 0xFFFF


def _chain(data: bytes) -> list[tuple[int, int, int]]:
    """Each record's tag, offset and payload size up to the end record; PdwError when the file
    ends first (nothing read but the heads: a cut file is found before any payload is read)."""
    chain: list[tuple[int, int, int]] = []
    at = FIRST_RECORD
    while True:
        if at + RECORD_HEAD > len(data):
            raise PdwError("pdw-truncated", at)
        tag, size = _HEAD(data, at)
        if tag == END_TAG:
            return chain
        if at + RECORD_HEAD + size + RECORD_TAIL > len(data):
            raise PdwError("pdw-truncated", at)
        chain.append((tag, at, size))
        at += RECORD_HEAD + size + RECORD_TAIL


def records(data: bytes) -> list[Record]:
    """The records after the header up to the end record; PdwError when the file is cut, a
    record runs past its end or a known record's checksum does not match."""
    if not data.startswith(MAGIC):
        raise PdwError("pdw-header", 0)
    if len(data) < FIRST_RECORD:
        raise PdwError("pdw-truncated", len(data))
    found: list[Record] = []
    for tag, at, size in _chain(data):
        end = at + RECORD_HEAD + size
        payload = data[at + RECORD_HEAD:end]
        if tag in SUMMED_TAGS and struct.unpack_from("<H", data, end)[0] != checksum(tag,
                                                                                   payload):
            raise PdwError("pdw-checksum", at)
        found.append(Record(tag, at, payload))
    return found


def mask_keys(masked: list[Record]) -> list[bytes]:
    """The masks the masked records may have, likeliest first: each 1280-byte block found more
    than once (erased memory, 0xFF under the mask) XOR 0xFF, the most frequent first. PdwError
    when no block repeats (nothing erased to learn the mask from)."""
    blocks: Counter[bytes] = Counter()
    for record in masked:
        payload = record.payload
        for start in range(0, len(payload) - KEY_PERIOD + 1, KEY_PERIOD):
            blocks[payload[start:start + KEY_PERIOD]] += 1
    keys = [bytes(byte ^ ERASED for byte in block)
            for block, count in blocks.most_common() if count > 1]
    if not keys:
        raise PdwError("pdw-key", masked[0].offset if masked else FIRST_RECORD)
    return keys


def _unmasked_image(program: Record, keys: list[bytes]) -> bytes:
    """The program image under the first mask that shows its `55 AA` mark (else the likeliest's:
    the caller reports the missing mark)."""
    for key in keys[:MAX_KEYS]:
        image = unmask(program.payload, key)
        if image[MARK_AT:MARK_AT + len(MARK)] == MARK:
            return image
    return unmask(program.payload, keys[0])


def unmask(payload: bytes, key: bytes) -> bytes:
    """A masked record's payload XOR the mask repeated from its first byte."""
    repeats = -(-len(payload) // len(key))
    stream = (key * repeats)[:len(payload)]
    return (int.from_bytes(payload, "little") ^ int.from_bytes(stream, "little")).to_bytes(
        len(payload), "little")


def _text(raw: bytes) -> str:
    """A NUL-terminated header string."""
    return raw.split(b"\0", 1)[0].decode("latin-1")


def _strings(payload: bytes, at: int, count: int, offset: int) -> tuple[list[bytes], int]:
    """`count` length-prefixed (16-bit) strings from `payload[at:]`; PdwError past its end."""
    out: list[bytes] = []
    for _ in range(count):
        if at + 2 > len(payload):
            raise PdwError("pdw-record", offset)
        size = struct.unpack_from("<H", payload, at)[0]
        at += 2
        if at + size > len(payload):
            raise PdwError("pdw-record", offset)
        out.append(payload[at:at + size])
        at += size
    return out, at


def _unit(record: Record) -> tuple[str, int]:
    """A unit record: its name and first byte in the image (u16 start, u16 name length, two
    zero bytes, the name)."""
    payload = record.payload
    if len(payload) < 6:
        raise PdwError("pdw-record", record.offset)
    start, size = struct.unpack_from("<HH", payload, 0)
    if 6 + size > len(payload):
        raise PdwError("pdw-record", record.offset)
    return payload[6:6 + size].decode("latin-1"), start


def _comment(record: Record) -> tuple[str, str]:
    """A comment record: the device as written (`M300`) and the comment's text."""
    (device, text), _end = _strings(record.payload, 0, 2, record.offset)
    return device.decode("latin-1").strip().upper(), text.decode(COMMENT_ENCODING, "replace")


def read_project(data: bytes) -> PdwProject:
    """The project a .pdw holds; PdwError (code, byte offset) when it cannot be read."""
    found = records(data)
    programs = [record for record in found if record.tag == PROGRAM_TAG]
    if not programs:
        raise PdwError("pdw-no-program", len(data))
    program = programs[0]
    keys = mask_keys([record for record in found if record.tag in MASKED_TAGS])
    project = PdwProject(model=_text(data[MODEL_AT:MODEL_AT + 16]), name="",
                         image=_unmasked_image(program, keys),
                         image_offset=program.payload_offset)
    for record in found:
        if record.tag == PROJECT_TAG and len(record.payload) >= 8:
            size = struct.unpack_from("<H", record.payload, 2)[0]
            project.name = record.payload[8:8 + size].decode("latin-1")
        elif record.tag == UNIT_TAG:
            project.units.append(_unit(record))
        elif record.tag == COMMENT_TAG:
            device, text = _comment(record)
            project.comments[device] = text
    return project
