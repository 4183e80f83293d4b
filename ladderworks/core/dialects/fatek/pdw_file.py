"""A WinProladder project (`.pdw`) read: its program as WinProladder prints its mnemonic listing,
and its element comments (docs/dialects.md, ".pdw projects")."""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.dialects.fatek.pdw_code import Decoder, Step
from ladderworks.core.dialects.fatek.pdw_records import (
    MAGIC,
    MARK,
    MARK_AT,
    PdwError,
    PdwProject,
    read_project,
)

CODE_START = 0x200  # the program's first word in the image
COUNT_AT = 0x106  # the code's length in words (16-bit little-endian)
CHECKSUM_AT = 0xCA  # the code's 16-bit little-endian words summed, minus one
TIMER_COUNTS_AT = 0x1DA  # how many 0.01 s timers, then 0.1 s timers (the rest 1 s)
TIMER_BASES = (".01", ".1", "1")  # as the listing prints them (.01 seen; .1 and 1 assumed)
UNIT_LETTERS = ("M", "S")  # the step suffix of the main unit and the subroutine unit
HEADER = "Printed Item: Mnemonic - {unit}"
SUFFIX = ".pdw"
OPERAND_INDENT = " " * 7


@dataclass(slots=True)
class PdwProgram:
    """A .pdw read: its listing lines, comments, and the error that stopped it (or None)."""

    lines: list[str] = field(default_factory=list)
    comments: dict[str, str] = field(default_factory=dict)
    model: str = ""
    name: str = ""
    units: list[tuple[str, list[Step]]] = field(default_factory=list)
    error: PdwError | None = None

    @property
    def text(self) -> str:
        """The listing as one text (CRLF line ends, as WinProladder writes text)."""
        return "".join(line + "\r\n" for line in self.lines)


def is_pdw(data: bytes) -> bool:
    """True for a WinProladder project file (its header)."""
    return data.startswith(MAGIC)


def is_pdw_path(path: Path) -> bool:
    """True for a file named `.pdw` or one that starts with the .pdw header (never written)."""
    if path.suffix.lower() == SUFFIX:
        return True
    try:
        with open(path, "rb") as file:
            return is_pdw(file.read(len(MAGIC)))
    except OSError:
        return False


def _code(project: PdwProject) -> list[int]:
    """The code's words after checking the image's mark, length and checksum."""
    image, base = project.image, project.image_offset
    if len(image) < CODE_START or image[MARK_AT:MARK_AT + 2] != MARK:
        raise PdwError("pdw-image", base + MARK_AT)
    count = struct.unpack_from("<H", image, COUNT_AT)[0]
    if CODE_START + 2 * count > len(image):
        raise PdwError("pdw-image", base + COUNT_AT)
    code = image[CODE_START:CODE_START + 2 * count]
    little = struct.unpack(f"<{count}H", code)
    if (sum(little) - 1) & 0xFFFF != struct.unpack_from("<H", image, CHECKSUM_AT)[0]:
        raise PdwError("pdw-program-checksum", base + CHECKSUM_AT)
    return list(struct.unpack(f">{count}H", code))


def _timer_bases(image: bytes) -> Callable[[int], str]:
    """Timer n's base as printed, from the project's timer allocation."""
    fast, mid = struct.unpack_from("<HH", image, TIMER_COUNTS_AT)
    if fast + mid > 256:
        fast, mid = 50, 150  # the FBs default (T0-T49, T50-T199)

    def base(number: int) -> str:
        return TIMER_BASES[0 if number < fast else 1 if number < fast + mid else 2]
    return base


def _unit_spans(project: PdwProject, words: int) -> list[tuple[str, int, int]]:
    """Each unit's name and word span in the code (a unit ends where the next starts)."""
    units = sorted((start, name) for name, start in project.units) or [(CODE_START, "Main")]
    spans = []
    for index, (start, name) in enumerate(units):
        stop = units[index + 1][0] if index + 1 < len(units) else CODE_START + 2 * words
        first = max(0, (start - CODE_START) // 2)
        spans.append((name, first, min(words, max(first, (stop - CODE_START) // 2))))
    return spans


def _render(unit: str, letter: str, steps: list[Step]) -> list[str]:
    """A unit's steps as WinProladder's mnemonic page (`00012M AND X0`, operand lines)."""
    lines = [HEADER.format(unit=unit), ""]
    for number, step in enumerate(steps):
        lines.append(f"{number:05d}{letter} {step.text}")
        lines.extend(f"{OPERAND_INDENT}{label}: {value}" for label, value in step.operands)
    return lines


def read_pdw(data: bytes) -> PdwProgram:
    """A .pdw's program (as its mnemonic listing) and comments; `error` set (code, byte offset)
    when the file is cut or damaged or holds code not decoded yet (the steps before it kept)."""
    result = PdwProgram()
    try:
        project = read_project(data)
        result.comments, result.model, result.name = project.comments, project.model, project.name
        words = _code(project)
        bases = _timer_bases(project.image)
        for index, (unit, first, stop) in enumerate(_unit_spans(project, len(words))):
            decoder = Decoder(words[first:stop], project.image_offset + CODE_START + 2 * first,
                              bases)
            try:
                decoder.run()
            finally:
                result.units.append((unit, decoder.done))
                if decoder.done:
                    letter = UNIT_LETTERS[min(index, len(UNIT_LETTERS) - 1)]
                    result.lines.extend(_render(unit, letter, decoder.done))
    except PdwError as error:
        result.error = error
    return result
