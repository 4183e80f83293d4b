"""Read a WPLSoft `.dvp` project (binary, header `57 01 01 00`): its instruction list and comments.

The layout, learned from public projects (docs/dialects.md, ".dvp projects"): a 0x100-byte
header (title at 0x0E, PLC model at 0x4A, format version at 0x4C, the program's key), the
program memory from 0x100 (one word a step, XOR-scrambled with a 2- or 4-byte key, unused steps
NOP 0x7FFF), a 0x48-byte block of settings, then text sections `<TypeBegin>` `Function=NAME`
`<TypeEnd>` `<DataBegin>` ... `<DataEnd>` (Initial Value, Device Comment: `DEVICE$&text` lines,
Output Comment, Symbol Table, Device Comment Range) with binary blocks between them.
"""

from __future__ import annotations

import re
import sys
from array import array
from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.delta.dvp_codes import (
    END,
    NOP,
    DvpCodeError,
    DvpInstruction,
    decode_words,
)
from ladderworks.core.dialects.delta.dvp_drawing import DrawingError, drawing_program

MAGIC = b"\x57\x01\x01\x00"
PROGRAM_START = 0x100
SETTINGS_SIZE = 0x48  # the block between the program memory and the first text section
MODEL, VERSION, TITLE, TITLE_END = 0x4A, 0x4C, 0x0E, 0x22
KEY_OLD, KEY = 0x56, 0x5E  # where the key of each format version is
SECTION_START = b"<TypeBegin>\nFunction="
FIRST_NAME = "Initial Value"
FIRST_SECTION = SECTION_START + FIRST_NAME.encode() + b"\n"
DATA_BEGIN, DATA_END = b"<TypeEnd>\n<DataBegin>\n", b"<DataEnd>"
COMMENTS = "Device Comment"
COMMENT_SPLIT = "$&"
ENCODING = "cp1254"  # WPLSoft writes the PC's ANSI code page: Turkish Windows' by default
BIG5 = "cp950"  # WPLSoft's own default comments carry Big5 punctuation (A1xx-A3xx)
_BIG5_PUNCTUATION = re.compile(rb"(?:[\x00-\x7f]|[\xa1-\xa3][\x40-\x7e\xa1-\xfe])*")
MOST_SECTIONS = 64
PROJECT_END = b"<PrjectEnd>"  # sic: the last line of every project WPLSoft writes


class DvpError(ValueError):
    """A `.dvp` file that cannot be read: the diagnostic `code` at byte `offset`."""

    def __init__(self, code: str, offset: int, **args: object) -> None:
        super().__init__(f"{code} at byte {offset}")
        self.code = code
        self.offset = offset
        self.args_map = {"offset": offset, **args}
        self.read: list[DvpInstruction] = []  # the program's instructions before the damage

    def diagnostic(self, line: int = 1) -> Diagnostic:
        """The error as a diagnostic (the byte offset in the message; `line`: of the text
        that shows the instructions read before it)."""
        return Diagnostic(self.code, dict(self.args_map), line=line, column=1)


@dataclass(slots=True)
class DvpProject:
    """What a `.dvp` project holds that LadderWorks reads."""

    title: str
    model: int  # the PLC model code at 0x4A (5: ES/SS, 7: SA/SX2 ..., as WPLSoft numbers them)
    version: int  # the format version at 0x4C (214, 215, 216 seen)
    capacity: int  # program memory in steps
    instructions: list[DvpInstruction] = field(default_factory=list)
    comments: dict[str, str] = field(default_factory=dict)  # device text -> comment
    sections: list[str] = field(default_factory=list)  # the text sections' names, in order
    warnings: list[Diagnostic] = field(default_factory=list)
    drawn: bool = False  # the instructions come from the ladder drawing (not compiled)

    @property
    def steps(self) -> int:
        """The steps the program uses (up to and with END)."""
        if not self.instructions:
            return 0
        return self.instructions[-1].step + 1  # END is one step


def is_dvp(data: bytes) -> bool:
    """True when `data` starts as a WPLSoft project does."""
    return data[:4] == MAGIC


def _keystream(data: bytes, version: int) -> bytes | None:
    """The 4 bytes the program words are XORed with (by the byte's place mod 4), or None."""
    if version == 215:
        key = data[KEY:KEY + 4]
        return bytes((key[0], key[1] ^ 0x80, key[2], key[3] ^ 0x80))
    if version in (214, 216):
        byte = data[KEY_OLD if version == 214 else KEY]
        return bytes((byte, byte ^ 0x80, byte, byte ^ 0x80))
    return None


def text_of(raw: bytes) -> str:
    """A comment or title: ASCII, Big5 where only Big5 punctuation is not ASCII (WPLSoft's
    default comments), else the ANSI code page (a byte it lacks becomes U+FFFD)."""
    if raw.isascii():
        return raw.decode("ascii")
    if _BIG5_PUNCTUATION.fullmatch(raw):
        return raw.decode(BIG5, errors="replace")
    return raw.decode(ENCODING, errors="replace")


def _words(area: bytes, stream: bytes) -> array[int]:
    """The program memory's words, unscrambled (an XOR of whole integers: fast)."""
    size = len(area)
    key = (stream * (size // 4 + 1))[:size]
    plain = (int.from_bytes(area, "little") ^ int.from_bytes(key, "little")).to_bytes(
        size, "little")
    words = array("H", plain[:size - size % 2])
    if sys.byteorder != "little":
        words.byteswap()
    return words


_FILLER = NOP.to_bytes(2, "little")


def _program(words: array[int], offset: int) -> list[DvpInstruction]:
    """The instructions up to END; what follows END must be the NOP filler."""
    data = words.tobytes() if sys.byteorder == "little" else b""
    used = len(words)
    if data:  # the NOP filler cut off at C speed (rstrip may take one byte of a word too many)
        used = min(used, (len(data.rstrip(_FILLER)) + 1) // 2)
    while used and words[used - 1] == NOP:
        used -= 1
    if not used:
        return []
    try:
        found = decode_words(list(words[:used]))
    except DvpCodeError as error:
        bad_word = DvpError(error.code, offset + 2 * error.index, word=f"{error.word:04X}",
                            step=error.index)
        bad_word.read = error.read
        raise bad_word from None
    last = found[-1]
    end = last.step + 1
    damaged = (DvpError("dvp-no-end", offset + 2 * used) if words[last.step] != END
               else DvpError("dvp-after-end", offset + 2 * end, step=end) if end != used
               else None)
    if damaged is not None:
        damaged.read = found
        raise damaged
    return found


def _sections(data: bytes, start: int) -> tuple[list[str], dict[str, tuple[int, bytes]]]:
    """The text sections from `start`: their names in order and each one's data (offset,
    bytes)."""
    names: list[str] = []
    bodies: dict[str, tuple[int, bytes]] = {}
    at = data.find(SECTION_START, start)
    while at >= 0 and len(names) < MOST_SECTIONS:
        name_at = at + len(SECTION_START)
        name_end = data.find(b"\n", name_at, name_at + 256)
        if name_end < 0:
            raise DvpError("dvp-bad-section", at)
        name = text_of(data[name_at:name_end])
        if data[name_end + 1:name_end + 1 + len(DATA_BEGIN)] != DATA_BEGIN:
            raise DvpError("dvp-bad-section", name_end + 1)
        body_at = name_end + 1 + len(DATA_BEGIN)
        body_end = data.find(DATA_END, body_at)
        if body_end < 0:
            raise DvpError("dvp-bad-section", at)
        names.append(name)
        bodies.setdefault(name, (body_at, data[body_at:body_end]))
        at = data.find(SECTION_START, body_end)
    return names, bodies


def _comments(body: bytes, offset: int) -> dict[str, str]:
    """`DEVICE$&text` lines -> {device: text}."""
    found: dict[str, str] = {}
    at = offset
    for raw in body.split(b"\n"):
        if raw:
            text = text_of(raw)
            device, split, comment = text.partition(COMMENT_SPLIT)
            if not split or not device.isalnum():
                raise DvpError("dvp-bad-comment", at)
            found[device.upper()] = comment
        at += len(raw) + 1
    return found


def read_dvp(data: bytes) -> DvpProject:
    """The project `data` holds; raises DvpError (code, byte offset) for a file that is not a
    `.dvp` project, is cut short or does not read as one."""
    if not is_dvp(data):
        raise DvpError("dvp-not-dvp", 0)
    if not data.endswith((PROJECT_END + b"\n", PROJECT_END + b"\r\n")):
        raise DvpError("dvp-truncated", len(data))
    if len(data) < PROGRAM_START:
        raise DvpError("dvp-bad-layout", len(data))
    version = data[VERSION] | data[VERSION + 1] << 8
    stream = _keystream(data, version)
    if stream is None:
        raise DvpError("dvp-version", VERSION, version=version)
    first = data.find(FIRST_SECTION, PROGRAM_START)
    if first < 0:
        raise DvpError("dvp-bad-layout", PROGRAM_START)
    stop = first - SETTINGS_SIZE
    if stop <= PROGRAM_START or (stop - PROGRAM_START) % 2:
        raise DvpError("dvp-bad-layout", max(first - SETTINGS_SIZE, 0))
    words = _words(data[PROGRAM_START:stop], stream)
    title = text_of(data[TITLE:TITLE_END].split(b"\0")[0]).strip()
    project = DvpProject(title, data[MODEL] | data[MODEL + 1] << 8, version, len(words))
    project.instructions = _program(words, PROGRAM_START)
    names, bodies = _sections(data, first)
    project.sections = names
    if COMMENTS in bodies:
        project.comments = _comments(bodies[COMMENTS][1], bodies[COMMENTS][0])
    project.warnings += [
        Diagnostic("dvp-unknown-code", {"offset": PROGRAM_START + 2 * each.step,
                                        "word": each.mnemonic[1:], "step": each.step},
                   line=1, column=1, severity=Severity.WARNING)
        for each in project.instructions if not each.known]
    if not project.instructions:
        _from_drawing(project, data, bodies)
    return project


def _from_drawing(project: DvpProject, data: bytes,
                  bodies: dict[str, tuple[int, bytes]]) -> None:
    """The program of a project saved without compiling, from its ladder drawing, with a
    warning that says so (or that it could not be read)."""
    body_at, body = bodies.get(FIRST_NAME, (0, b""))
    code = "dvp-no-program"
    args: dict[str, object] = {}
    try:
        project.instructions = drawing_program(data, body_at + len(body) + len(DATA_END) + 1)
    except DrawingError as error:
        code, args = "dvp-drawing-unread", {"offset": error.offset}
    if project.instructions:
        code = "dvp-from-drawing"
        project.drawn = True
    project.warnings.append(Diagnostic(code, args, line=1, column=1, severity=Severity.WARNING))


def read_or_diagnostic(data: bytes) -> tuple[DvpProject | None, Diagnostic | None]:
    """read_dvp, with its error as a diagnostic instead of an exception."""
    try:
        return read_dvp(data), None
    except DvpError as error:
        return None, error.diagnostic()
